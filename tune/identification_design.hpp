// From an identification flight's three axis records to designed gains and their figures: the
// part of autotune that qrsim --autotune and the console share (docs/signal-chain.md, "Autotune:
// the identification flight"). Each record is fitted (fit_axis), one roll/pitch set and one yaw
// set are designed on the models, and the gains flown before and the new ones are evaluated on
// the same models so the pilot sees both side by side.
#pragma once

#include <stdint.h>

#include <array>
#include <optional>
#include <string>

#include <common/parameter_table.hpp>
#include <tune/axis_fit.hpp>
#include <tune/gains.hpp>
#include <tune/loop_design.hpp>

namespace tune {

inline constexpr const char* kAxisNames[3] = {"roll", "pitch", "yaw"};

struct IdentificationDesign {
  std::array<AxisModel, 3> models;
  RollPitchGains roll_pitch, roll_pitch_before;
  YawGains yaw, yaw_before;
  // The figures on the fitted models: the roll axis (pitch shares its gains), and yaw.
  AxisDesign before, after, after_pitch;
  YawDesign yaw_then, yaw_now;
  bool keeps = false;  // the new gains keep the targets on all three models
};

// `records`: roll, pitch, yaw, their moment and rate filled (sample_hz, filter and yaw are set
// here from `flown`, the parameters in force during the flight). Empty with `why` naming the axis
// whose fit was refused and the fit's reason.
std::optional<IdentificationDesign> design_from_identification(std::array<AxisRecord, 3> records,
                                                               const wire::ParameterValues& flown, double control_hz,
                                                               std::string* why);

}  // namespace tune
