// The firmware's loops (qr/core/chain/controllers.hpp) closed around a model in double: the loop
// gains the margins are read from, and the step responses. loop_design.hpp states the loops.
#pragma once

#include <complex>

#include <tune/axis_model.hpp>
#include <tune/gains.hpp>
#include <tune/loop_design.hpp>
#include <tune/sensor_lowpass.hpp>

namespace tune {

// Moment asked for -> rate the loops see: the model, sampled, through the sensor low-pass.
class MeasuredPlant {
 public:
  MeasuredPlant(const AxisModel& model, const DesignLimits& limits);
  std::complex<double> response(double omega_rad_s) const;
  double period() const { return period_; }

 private:
  SampledAxis axis_;
  Lowpass filter_;
  double period_;
};

// The loop gains at one frequency (loop_design.hpp: inner, outer, yaw).
std::complex<double> inner_loop(const MeasuredPlant& plant, const RollPitchGains& g, double omega_rad_s);
std::complex<double> outer_loop(const MeasuredPlant& plant, const RollPitchGains& g, double omega_rad_s);
std::complex<double> yaw_loop(const MeasuredPlant& plant, const YawGains& g, double omega_rad_s);

// From rest: the true angle after an angle step, the true rate after a yaw-rate step.
StepFigures angle_step(const AxisModel& model, const RollPitchGains& g, const DesignLimits& limits);
StepFigures yaw_step(const AxisModel& model, const YawGains& g, const DesignLimits& limits);

}  // namespace tune
