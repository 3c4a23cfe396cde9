#include <tune/axis_model.hpp>

#include <algorithm>
#include <cmath>

namespace tune {

// Over a part of the period of length h with the motors driven by a constant v:
//   a(h) = v + (a0 - v) e^(-h/tau),   integral of a = v h + (a0 - v) tau (1 - e^(-h/tau)).
// The period has two parts when the delay is not a whole number of periods: the older moment for
// the first h1 = (delay mod T), the newer for the rest; their products give the coefficients.
SampledAxis::SampledAxis(const AxisModel& model, double sample_hz)
    : gain_(model.gain), lead_(model.lead_s), damping_(model.damping_per_s), period_(1.0 / sample_hz) {
  const double tau = std::max(model.motor_tau_s, 1e-6);
  const double delay = std::max(model.delay_s, 0.0) / period_;
  whole_ = static_cast<int>(std::floor(delay));
  const double h1 = (delay - whole_) * period_, h2 = period_ - h1;
  const double e1 = std::exp(-h1 / tau), e2 = std::exp(-h2 / tau);
  e_ = e1 * e2;
  carry_old_ = e2 * (1 - e1);
  carry_new_ = 1 - e2;
  int_a_ = tau * (1 - e_) / period_;
  int_old_ = (h1 - tau * (1 - e1) * e2) / period_;
  int_new_ = (h2 - tau * (1 - e2)) / period_;
  past_.assign(static_cast<std::size_t>(whole_) + 2, 0.0);
}

void SampledAxis::settle(double moment) {
  std::fill(past_.begin(), past_.end(), moment);
  motor_ = moment;
}

SampledAxis::Increment SampledAxis::increment(double moment) {
  // A ring, newest at `newest_`, going back in time upwards.
  const std::size_t n = past_.size();
  newest_ = (newest_ + n - 1) % n;
  past_[newest_] = moment;
  const std::size_t whole = static_cast<std::size_t>(whole_);
  const double newer = past_[(newest_ + whole) % n], older = past_[(newest_ + whole + 1) % n];
  const double mean = int_a_ * motor_ + int_old_ * older + int_new_ * newer;
  const double next = e_ * motor_ + carry_old_ * older + carry_new_ * newer;
  const double change = (next - motor_) / period_;
  motor_ = next;
  return {mean, change};
}

double SampledAxis::step(double moment, double disturbance) {
  const Increment inc = increment(moment);
  rate_ += period_ * (gain_ * (inc.mean + lead_ * inc.change) - damping_ * rate_ + disturbance);
  return rate_;
}

std::complex<double> SampledAxis::response(double omega_rad_s) const {
  const std::complex<double> z = std::polar(1.0, omega_rad_s * period_);
  const std::complex<double> newer = std::pow(z, -whole_), older = newer / z;
  const std::complex<double> drive = carry_old_ * older + carry_new_ * newer;
  const std::complex<double> motor = drive / (z - e_);  // A / U
  const std::complex<double> mean = int_a_ * motor + int_old_ * older + int_new_ * newer;
  const std::complex<double> change = ((e_ - 1) * motor + drive) / period_;
  return gain_ * period_ * (mean + lead_ * change) / (z - 1.0 + damping_ * period_);
}

}  // namespace tune
