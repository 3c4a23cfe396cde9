#include "closed_loop_flight.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>

#include <qr/core/chain/butterworth_design.hpp>
#include <qr/core/chain/controllers.hpp>
#include <qr/host/real_numbers.hpp>

namespace tune::test {
namespace {

using N = qr::chain::DoubleNumbers;
constexpr int kSubsteps = 20;

// A 9-bit maximal-length shift register (x^9 + x^5 + 1): 511 bits before it repeats.
class Prbs {
 public:
  double next_bit() {
    const unsigned bit = ((state_ >> 8) ^ (state_ >> 4)) & 1u;
    state_ = ((state_ << 1) | bit) & 0x1FFu;
    return bit != 0 ? 1.0 : -1.0;
  }

 private:
  unsigned state_ = 0x1FFu;
};

// The firmware's low-pass design run in double, settled on its first sample.
class GyroFilter {
 public:
  GyroFilter(double cutoff_hz, double sample_hz) : d_(qr::chain::design_butterworth(2, cutoff_hz, sample_hz)) {}
  double step(double x) {
    if (!d_.valid()) return x;
    if (!started_) {
      x1_ = x2_ = y1_ = y2_ = x;
      started_ = true;
    }
    const double y = d_.b[0] * x + d_.b[1] * x1_ + d_.b[2] * x2_ - d_.a[1] * y1_ - d_.a[2] * y2_;
    x2_ = x1_;
    x1_ = x;
    y2_ = y1_;
    y1_ = y;
    return y;
  }

 private:
  qr::chain::ButterworthDesign d_;
  double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
  bool started_ = false;
};

// The axis in continuous time: the motors' lag solved exactly over each step, the rate and the
// angle by the trapezoid.
struct Axis {
  AxisModel m;
  double motor = 0, rate = 0, angle = 0;

  void advance(double command, double disturbance_moment, double h) {
    const double before = motor;
    motor += (command - motor) * (1 - std::exp(-h / m.motor_tau_s));
    const double accel = m.gain * ((before + motor) / 2 + disturbance_moment) +
                         m.gain * m.lead_s * (motor - before) / h;
    const double rate_before = rate;
    rate += h * (accel - m.damping_per_s * rate);
    angle += h * (rate_before + rate) / 2;
  }
};

}  // namespace

Flight fly(const FlightSetup& s) {
  const double period = 1.0 / s.control_hz, h = period / kSubsteps;
  const auto ticks = static_cast<std::size_t>(s.seconds * s.control_hz);
  AxisModel plant = s.truth;
  plant.gain *= s.plant_gain_scale;
  const double delay = s.truth.delay_s + s.extra_delay_s;

  qr::chain::AttitudeController<N> roll;
  roll.set_gains(s.gains.p1, s.gains.p2, s.gains.i, s.gains.d);
  qr::chain::YawRateController<N> yaw;
  yaw.set_gains(s.gains.yaw_p, s.gains.yaw_i);
  GyroFilter filter(s.filter_cutoff_hz, s.control_hz);
  Prbs prbs;
  std::mt19937 random(s.seed);
  std::normal_distribution<double> noise(0.0, s.gyro_noise);

  Axis axis{plant, 0, s.initial_rate, 0};
  Flight f;
  f.record.sample_hz = s.control_hz;
  f.record.filter_cutoff_hz = s.filter_cutoff_hz;
  f.record.yaw = s.yaw;
  std::vector<double> commands;   // per tick, for the delay
  std::vector<double> estimates;  // the estimator's angle per tick, for the angle path's delay
  double estimate = 0, bit = 0;
  const auto bit_ticks = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(s.prbs_bit_s * s.control_hz)));
  for (std::size_t k = 0; k < ticks; ++k) {
    const double y = filter.step(axis.rate + (s.gyro_noise > 0 ? noise(random) : 0.0));
    estimate += period * y;
    estimates.push_back(estimate);
    const std::size_t seen = k >= static_cast<std::size_t>(s.angle_delay_ticks)
                                 ? k - static_cast<std::size_t>(s.angle_delay_ticks)
                                 : 0;
    double moment = 0;
    if (s.yaw) {
      moment = yaw.moment(s.setpoint, y, true);
    } else {
      moment = roll.moment(s.setpoint, s.angle_gain_scale * estimates[seen], y, true);
    }
    if (k % bit_ticks == 0) bit = prbs.next_bit();
    moment = std::clamp(moment + s.prbs_amplitude * bit, -1000.0, 1000.0);
    commands.push_back(moment);
    f.record.moment.push_back(moment);
    f.record.rate.push_back(y);
    f.angle.push_back(axis.angle);
    f.rate.push_back(axis.rate);
    // The engines hold this tick's command until the next; the airframe feels it `delay` later.
    for (int j = 0; j < kSubsteps; ++j) {
      const double t = static_cast<double>(k) * period + (j + 0.5) * h - delay;
      const double index = std::floor(t / period);
      const double command = index < 0 ? 0.0 : commands[static_cast<std::size_t>(index)];
      axis.advance(command, s.disturbance, h);
    }
  }
  return f;
}

double peak(const std::vector<double>& x, double control_hz, double from, double to) {
  double p = 0;
  for (std::size_t k = static_cast<std::size_t>(from * control_hz);
       k < x.size() && static_cast<double>(k) < to * control_hz; ++k) {
    p = std::max(p, std::fabs(x[k]));
  }
  return p;
}

}  // namespace tune::test
