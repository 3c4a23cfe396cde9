// Flight modes as numbered on the wire (the mode change request and the telemetry mode field),
// and every fact about a mode in one row: its names and what it means for the vehicle. The QR's
// safety machine, its debug text and LEDs, the console, the simulator and the tests all read
// this table.
#pragma once

#include <stdint.h>

namespace wire {

// IN4073 numbers its height mode 7, after a raw mode (6) this project does not have. The numbers
// here stay dense, because every table of modes (this one, the QR's task sets, the console's) is
// indexed by them: height hold is 6, acro (issue 31's worked example of adding a mode,
// docs/architecture.md) 7, the motor test 8, the autotune's identification flight 9.
enum class Mode : uint8_t {
  safe = 0,
  panic = 1,
  manual = 2,
  calibration = 3,
  yaw_control = 4,
  full_control = 5,
  height_hold = 6,
  acro = 7,
  motor_test = 8,
  autotune = 9,
};

inline constexpr uint8_t kModeCount = 10;

// The radio's mode switch (docs/safety.md rule 17): the position at which its arm switch arms a
// mode. The switch has three positions (common/drivers/rc_sticks.hpp: RcSticks::mode_position 0,
// 1, 2), each one mode's; a mode at none is never armed by the radio.
enum class ModeSwitch : uint8_t { low = 0, centre = 1, high = 2, none = 3 };
inline constexpr uint8_t kModeSwitchPositions = 3;

struct ModeSpec {
  Mode mode;
  const char* name;        // as the pilot reads it: screen, debug text
  const char* key;         // one word: JSON figures, command lines
  bool flies;              // engines follow the pilot; leaving goes through panic; watchdogs on
  bool needs_calibration;  // uses calibrated sensors: refused until a calibration has finished
  bool needs_attitude;     // flies on the attitude estimate: the tilt watchdog applies; a panic can land
  Mode entered_from;       // the one mode a request may enter it from
  bool holds_height;       // flies on the height estimate: needs one, and needs to be flying
  ModeSwitch armed_at;     // the radio's mode switch position its arm switch arms it at
};

inline constexpr ModeSpec kModeTable[] = {
    {Mode::safe, "safe", "safe", false, false, false, Mode::safe, false, ModeSwitch::none},
    {Mode::panic, "panic", "panic", false, false, false, Mode::safe, false, ModeSwitch::none},
    {Mode::manual, "manual", "manual", true, false, false, Mode::safe, false, ModeSwitch::low},
    {Mode::calibration, "calibration", "calibration", false, false, false, Mode::safe, false, ModeSwitch::none},
    {Mode::yaw_control, "yaw control", "yaw", true, true, true, Mode::safe, false, ModeSwitch::centre},
    // Full control is also where height hold returns to (the pilot's toggle, or a lift change).
    {Mode::full_control, "full control", "full", true, true, true, Mode::safe, false, ModeSwitch::high},
    // Holds the height at entry with the lift (IN4073's height mode): entered while flying in
    // full control, so the height it holds is one the pilot chose (and no arming mode of the radio).
    {Mode::height_hold, "height hold", "height", true, true, true, Mode::full_control, true, ModeSwitch::none},
    // The rate loops alone: the sticks ask for roll, pitch and yaw rates (full stick:
    // max_yaw_rate_rad_s on every axis) and the vehicle stays where they leave it. A rate mode for
    // learning, not for flips: the tilt watchdog still applies, and a panic lands. The radio's
    // mode switch has no position left for it: the console's key enters it.
    {Mode::acro, "acro", "acro", true, true, true, Mode::safe, false, ModeSwitch::none},
    // One engine at a low level for 2 s, on the bench with the propellers off, to find an engine on
    // the wrong output or turning the wrong way (docs/safety.md rule 22). Its own request enters it
    // (motor_test: which engine, how fast), never a mode change; it does not fly (no watchdog's
    // panic, no idle floor: it ends by itself, or at once, in safe).
    {Mode::motor_test, "motor test", "motor", false, false, false, Mode::safe, false, ModeSwitch::none},
    // The autotune's identification flight (issue 34, docs/signal-chain.md): full control's loops
    // hover the vehicle while a known moment is added to one axis at a time. Entered in flight from
    // full control, where it returns when it is over, when a stick or the lift moves, when the tilt
    // leaves its few degrees or the battery warns (docs/safety.md rule 23).
    {Mode::autotune, "autotune", "autotune", true, true, true, Mode::full_control, false, ModeSwitch::none},
};
static_assert(sizeof(kModeTable) / sizeof(kModeTable[0]) == kModeCount, "one row per mode");

constexpr bool rows_in_mode_order() {
  for (uint8_t i = 0; i < kModeCount; ++i) {
    if (static_cast<uint8_t>(kModeTable[i].mode) != i) return false;
  }
  return true;
}
static_assert(rows_in_mode_order(), "row i is mode i");

constexpr bool valid_mode(Mode mode) { return static_cast<uint8_t>(mode) < kModeCount; }

// The row of a mode; modes outside the table get the safe row's facts (they never fly).
constexpr const ModeSpec& mode_spec(Mode mode) { return kModeTable[valid_mode(mode) ? static_cast<uint8_t>(mode) : 0]; }

// "?" for a number outside the table.
constexpr const char* mode_name(Mode mode) { return valid_mode(mode) ? mode_spec(mode).name : "?"; }
constexpr const char* mode_key(Mode mode) { return valid_mode(mode) ? mode_spec(mode).key : "unknown"; }
constexpr bool flies(Mode mode) { return mode_spec(mode).flies; }
// Entered from full control, so in flight: height hold and the autotune. The pilot's request for
// full control returns there, flying on.
constexpr bool entered_in_flight(Mode mode) { return mode_spec(mode).entered_from == Mode::full_control; }

// Whether the radio's arm switch arms `mode` (at some position of its mode switch).
constexpr bool armed_by_the_radio(Mode mode) { return mode_spec(mode).armed_at != ModeSwitch::none; }

// Each position of the mode switch arms one mode, one that flies and is entered from safe (the
// arm switch arms from safe only).
constexpr bool each_switch_position_arms_one_mode() {
  for (uint8_t position = 0; position < kModeSwitchPositions; ++position) {
    uint8_t modes = 0;
    for (const ModeSpec& row : kModeTable) {
      if (static_cast<uint8_t>(row.armed_at) != position) continue;
      if (!row.flies || row.entered_from != Mode::safe) return false;
      ++modes;
    }
    if (modes != 1) return false;
  }
  return true;
}
static_assert(each_switch_position_arms_one_mode(), "kModeTable: each mode switch position arms one flying mode");

// The column turned round: the mode at each position of the mode switch.
struct ModeSwitchModes {
  Mode at[kModeSwitchPositions];
};
constexpr ModeSwitchModes modes_at_switch() {
  ModeSwitchModes modes{};
  for (const ModeSpec& row : kModeTable) {
    if (row.armed_at != ModeSwitch::none) modes.at[static_cast<uint8_t>(row.armed_at)] = row.mode;
  }
  return modes;
}
inline constexpr ModeSwitchModes kModesAtSwitch = modes_at_switch();

// The mode the arm switch arms with the mode switch at `position` (0 low, 1 centre, 2 high, as
// drivers::rc_switch_position reads a channel; nothing else may be asked).
constexpr Mode mode_at_switch(uint8_t position) { return kModesAtSwitch.at[position]; }

}  // namespace wire
