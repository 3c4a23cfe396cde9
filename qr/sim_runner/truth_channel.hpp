// Serve mode's side channel (qrsim --serve --truth-fd N): the simulator's true state out, one line
// per 20 ms of simulated time, and pushes and resets in. The firmware never sees it; docs/simulator.md gives
// the line format.
#pragma once

#include <stdint.h>

#include <string>
#include <string_view>

#include <common/mode.hpp>
#include <sim/hand_tilt.hpp>
#include <sim/hand_turn.hpp>
#include <sim/quadrotor.hpp>
#include <sim/vec3.hpp>

namespace qrsim {

// "push TX TY TZ SECONDS": a torque in N·m, body axes, for that long.
// "reset": the vehicle picked up and set down upright, at rest, where it is (the heading kept),
// as a hand rights it after a crash; the firmware is not told.
// "turn AXIS N SECONDS": a hand turns the vehicle N whole turns about body axis AXIS (x, y or z)
// in that long and sets it down as it was (sim/hand_turn.hpp), for a gyro scale calibration;
// refused while an engine runs, as a reset is.
// "tilt AXIS DEG SECONDS": the same hand tilts it to DEG about body axis AXIS, holds it and sets
// it down as it was (sim/hand_tilt.hpp), for the console's orientation check; refused as a turn is.
// "radio arm MODE" (MODE manual, yaw or full): the radio's mode switch to MODE and its arm switch
// off, then on (qrsim --rc crsf, serve_radio.hpp). "radio off": the arm switch off.
struct TruthCommand {
  enum class Kind : uint8_t { push, reset, turn, tilt, radio_arm, radio_off };
  Kind kind = Kind::push;
  sim::Vec3 torque;  // push only
  double seconds = 0;
  wire::Mode mode = wire::Mode::manual;  // radio_arm only
  sim::HandTurnSpec turn;                // turn only
  sim::HandTiltSpec tilt;                // tilt only
};

// One command line (without its newline). True with `command` filled in; false with `error`
// saying why ("unknown command 'foo'", "push needs TX TY TZ SECONDS", ...).
bool parse_truth_command(std::string_view line, TruthCommand& command, std::string& error);

// The plant's state after a reset from `now`: level at the ground, still, heading and place kept.
sim::PlantState reset_state(const sim::PlantState& now);

// "truth t=12.340 roll=1.23 pitch=-0.50 yaw=10.00 height=1.500 north=0.100 east=-0.020 climb=0.000
// rotors=0.0,-104.7,0.0,0.0" (degrees, metres, m/s upward; each rotor's speed in rad/s, front,
// right, back, left, positive clockwise seen from above: which rotor turns, and which way, for a
// motor test), with a newline.
std::string truth_line(double t_s, const sim::Quadrotor& plant);

// "devboard t=12.340 core_mhz=16 tick_instr_mean=2738 tick_instr_max=8012 ticks=12340", with a
// newline, once a second when the devboard flies (qrsim --serve --devboard): its core's clock
// (--core-mhz; 0: none, its time stands still while a tick runs) and the whole tick's cost in RV32
// instructions since start, mean and largest, over that many ticks. The console's CPU row and its
// task figures (the b key) read it: the QR's own load and loop time are 0 without a clock.
std::string devboard_line(double t_s, uint32_t core_mhz, double tick_instr_mean, uint32_t tick_instr_max,
                          uint32_t ticks);

}  // namespace qrsim
