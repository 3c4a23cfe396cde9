#include <tune/cascade.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace tune {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

constexpr double kStepSeconds = 4;
constexpr double kSettleBand = 0.1;  // of the step

// The controller's parts at z = e^(j omega T): the integral (I T z / (z - 1): it adds this tick's
// error before the moment is formed), the derivative on the measured rate (D (1 - 1/z) / T), and
// the estimator's integration of the rate (T z / (z - 1)).
struct Parts {
  std::complex<double> z, sum, difference;  // sum = T z / (z - 1), difference = (1 - 1/z) / T
};

Parts parts(double omega, double period) {
  const std::complex<double> z = std::polar(1.0, omega * period);
  return {z, period * z / (z - 1.0), (1.0 - 1.0 / z) / period};
}

// Rise, overshoot and settling of x (sample i at time (i + 1) T) after a step to `step` at 0.
StepFigures figures_of(const std::vector<double>& x, double period, double step, double peak_moment) {
  StepFigures f{kInfinity, 0, kInfinity, peak_moment};
  const auto crossing = [&](double level) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (x[i] >= level) {
        const double before = i == 0 ? 0 : x[i - 1];
        const double t = (level - before) / (x[i] - before);
        return (static_cast<double>(i) + t) * period;
      }
    }
    return kInfinity;
  };
  f.rise_s = crossing(0.9 * step) - crossing(0.1 * step);
  if (std::isnan(f.rise_s)) f.rise_s = kInfinity;
  f.overshoot_pct = std::max(0.0, (*std::max_element(x.begin(), x.end()) - step) / step * 100);
  f.settle_s = 0;
  for (std::size_t i = x.size(); i-- > 0;) {
    if (std::fabs(x[i] - step) > kSettleBand * step) {
      f.settle_s = i + 1 == x.size() ? kInfinity : static_cast<double>(i + 2) * period;
      break;
    }
  }
  return f;
}

}  // namespace

MeasuredPlant::MeasuredPlant(const AxisModel& model, const DesignLimits& limits)
    : axis_(model, limits.control_hz), filter_(butterworth_lowpass(limits.filter_cutoff_hz, limits.control_hz)),
      period_(1.0 / limits.control_hz) {}

std::complex<double> MeasuredPlant::response(double omega) const {
  return filter_.response(std::polar(1.0, omega * period_)) * axis_.response(omega);
}

std::complex<double> inner_loop(const MeasuredPlant& plant, const RollPitchGains& g, double omega) {
  const Parts c = parts(omega, plant.period());
  return (g.p2 + g.i * c.sum + g.d * c.difference) * plant.response(omega);
}

// Broken at the angle estimate: an angle a gives the rate set-point -P1 a; the rate loop, closed,
// turns it into a measured rate, and the estimator into an angle.
std::complex<double> outer_loop(const MeasuredPlant& plant, const RollPitchGains& g, double omega) {
  const Parts c = parts(omega, plant.period());
  const std::complex<double> g_plant = plant.response(omega);
  const std::complex<double> on_error = g.p2 + g.i * c.sum;
  const std::complex<double> rate_loop = on_error * g_plant / (1.0 + (on_error + g.d * c.difference) * g_plant);
  return g.p1 * rate_loop * c.sum;
}

std::complex<double> yaw_loop(const MeasuredPlant& plant, const YawGains& g, double omega) {
  const Parts c = parts(omega, plant.period());
  return (g.p + g.i * c.sum) * plant.response(omega);
}

StepFigures angle_step(const AxisModel& model, const RollPitchGains& g, const DesignLimits& limits) {
  const double period = 1.0 / limits.control_hz, step = limits.angle_step_rad;
  SampledAxis axis(model, limits.control_hz);
  LowpassRun filter(butterworth_lowpass(limits.filter_cutoff_hz, limits.control_hz));
  std::vector<double> angle;
  const auto ticks = static_cast<std::size_t>(kStepSeconds * limits.control_hz);
  angle.reserve(ticks);
  double truth = 0, estimate = 0, integral = 0, previous = 0, peak = 0;
  for (std::size_t k = 0; k < ticks; ++k) {
    const double rate = axis.rate();
    const double y = filter.step(rate);
    estimate += period * y;
    const double error = g.p1 * (step - estimate) - y;
    integral += g.i * period * error;
    const double moment = g.p2 * error - g.d * (y - previous) / period + integral;
    previous = y;
    peak = std::max(peak, std::fabs(moment));
    axis.step(moment);
    truth += period * (rate + axis.rate()) / 2;
    angle.push_back(truth);
  }
  return figures_of(angle, period, step, peak);
}

StepFigures yaw_step(const AxisModel& model, const YawGains& g, const DesignLimits& limits) {
  const double period = 1.0 / limits.control_hz, step = limits.yaw_step_rad_s;
  SampledAxis axis(model, limits.control_hz);
  LowpassRun filter(butterworth_lowpass(limits.filter_cutoff_hz, limits.control_hz));
  std::vector<double> rate;
  const auto ticks = static_cast<std::size_t>(kStepSeconds * limits.control_hz);
  rate.reserve(ticks);
  double integral = 0, peak = 0;
  for (std::size_t k = 0; k < ticks; ++k) {
    const double error = step - filter.step(axis.rate());
    integral += g.i * period * error;
    const double moment = g.p * error + integral;
    peak = std::max(peak, std::fabs(moment));
    rate.push_back(axis.step(moment));
  }
  return figures_of(rate, period, step, peak);
}

}  // namespace tune
