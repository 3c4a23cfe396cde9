// What the gain keys do to the QR's parameters: one row per key action. Controller gains step by
// a fixed amount; the filter's divisors C1 and C2 span orders of magnitude, so they double and
// halve.
#pragma once

#include <stdint.h>

#include <common/parameter_table.hpp>
#include <pc/core/action.hpp>

namespace qrterm {

struct GainStep {
  Action action;
  wire::ParamId id;
  int32_t add;       // raw units
  int32_t multiply;  // 2: double; -2: halve; 1: none
};

inline constexpr GainStep kGainSteps[] = {
    {Action::yaw_p_up, wire::ParamId::yaw_p, 80, 1},  // 5.0 in the Q4 gain
    {Action::yaw_p_down, wire::ParamId::yaw_p, -80, 1},
    {Action::p1_up, wire::ParamId::roll_pitch_p1, 64, 1},  // 0.25 in the Q8 gain
    {Action::p1_down, wire::ParamId::roll_pitch_p1, -64, 1},
    {Action::p2_up, wire::ParamId::roll_pitch_p2, 40, 1},  // 2.5 in the Q4 gain
    {Action::p2_down, wire::ParamId::roll_pitch_p2, -40, 1},
    {Action::c1_up, wire::ParamId::attitude_c1, 0, 2},
    {Action::c1_down, wire::ParamId::attitude_c1, 0, -2},
    {Action::c2_up, wire::ParamId::attitude_c2, 0, 2},
    {Action::c2_down, wire::ParamId::attitude_c2, 0, -2},
};

// The row for an action, or null when the action is no gain step.
const GainStep* find_gain_step(Action action);

// The value one step takes `raw` to, clamped to the parameter's range.
int32_t stepped(const GainStep& step, int32_t raw);

}  // namespace qrterm
