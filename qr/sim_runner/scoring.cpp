#include <qr/sim_runner/scoring.hpp>

#include <algorithm>

namespace qrsim {
namespace {

// First time after t_step at which `level` is crossed upward by the normalised response.
double first_crossing(const Trace& trace, double t_step, double from, double to, double level) {
  const double span = to - from;
  const Sample* previous = nullptr;
  for (const Sample& s : trace) {
    if (s.t < t_step) continue;
    const double n = (s.value - from) / span;
    if (n >= level) {
      if (previous == nullptr) return s.t;
      const double np = (previous->value - from) / span;
      return previous->t + (s.t - previous->t) * (level - np) / (n - np);
    }
    previous = &s;
  }
  return kNotMeasured;
}

}  // namespace

StepFigures step_response(const Trace& trace, double t_step, double from, double to, double band) {
  StepFigures f;
  const double t10 = first_crossing(trace, t_step, from, to, 0.1);
  const double t90 = first_crossing(trace, t_step, from, to, 0.9);
  if (!std::isnan(t10) && !std::isnan(t90)) f.rise_s = t90 - t10;

  double peak = 0;
  bool any = false;
  // Inside the band from the step on, unless a sample says otherwise; each sample outside
  // restarts the search for the moment it came back for good.
  double settled_at = t_step;
  for (const Sample& s : trace) {
    if (s.t < t_step) continue;
    any = true;
    peak = std::max(peak, (s.value - from) / (to - from));
    if (std::abs(s.value - to) > band) {
      settled_at = kNotMeasured;
    } else if (std::isnan(settled_at)) {
      settled_at = s.t;
    }
  }
  if (!any) return f;
  f.overshoot_pct = std::max(0.0, peak - 1) * 100;
  f.settle_s = settled_at - t_step;
  return f;
}

double rms(const Trace& trace, double t0, double t1) {
  double sum = 0;
  long n = 0;
  for (const Sample& s : trace) {
    if (s.t < t0 || s.t > t1) continue;
    sum += s.value * s.value;
    ++n;
  }
  return n == 0 ? kNotMeasured : std::sqrt(sum / static_cast<double>(n));
}

double peak_abs(const Trace& trace, double t0, double t1) {
  double peak = kNotMeasured;
  for (const Sample& s : trace) {
    if (s.t < t0 || s.t > t1) continue;
    peak = std::isnan(peak) ? std::abs(s.value) : std::max(peak, std::abs(s.value));
  }
  return peak;
}

double mean(const Trace& trace, double t0, double t1) {
  double sum = 0;
  long n = 0;
  for (const Sample& s : trace) {
    if (s.t < t0 || s.t > t1) continue;
    sum += s.value;
    ++n;
  }
  return n == 0 ? kNotMeasured : sum / static_cast<double>(n);
}

double recovery_time(const Trace& trace, double t0, double band) {
  double back_at = t0;
  for (const Sample& s : trace) {
    if (s.t < t0) continue;
    if (std::abs(s.value) > band) {
      back_at = kNotMeasured;
    } else if (std::isnan(back_at)) {
      back_at = s.t;
    }
  }
  return back_at - t0;
}

}  // namespace qrsim
