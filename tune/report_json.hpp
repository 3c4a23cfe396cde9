// The autotune's figures as JSON, written by hand (the project has no JSON library): the model
// fitted, the margins and step response of a design, and the parameters as --param takes them.
// One writer for the test that prints the default vehicle's design and for qrsim --autotune.
#pragma once

#include <string>

#include <tune/axis_model.hpp>
#include <tune/gains.hpp>
#include <tune/loop_design.hpp>

namespace tune {

std::string json_number(double x);  // null when not finite
std::string model_json(const AxisModel& m);
std::string margins_json(const Margins& m);
std::string step_json(const StepFigures& s);
std::string design_json(const AxisDesign& roll_pitch, const YawDesign& yaw);
// {"roll_pitch_p1": 7.46, ...}: the raw parameters' values, exactly as --param NAME=VALUE reads them.
std::string params_json(const RollPitchGains& roll_pitch, const YawGains& yaw);

}  // namespace tune
