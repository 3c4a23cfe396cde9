// The keyboard, as one table: key -> action. The IN4073 map (ESC, 0-5, 7, a/z, arrows, q/w, u/j,
// i/k, o/l) plus our keys for the coarse lift and the hover, the filter constants, logs,
// parameters, the simulator's push, reset, turn and radio arm switch, the orientation check, the
// motor test, and help.
#pragma once

#include <stddef.h>

#include <string>
#include <vector>

#include <pc/core/action.hpp>
#include <pc/core/key.hpp>

namespace qrterm {

struct KeyBinding {
  Key key;
  Action action;
};

inline constexpr KeyBinding kKeyMap[] = {
    {kKeyEscape, Action::abort},
    {'x', Action::exit},
    {kKeyInterrupt, Action::exit},
    {'0', Action::mode_safe},
    {'1', Action::mode_panic},
    {'2', Action::mode_manual},
    {'3', Action::mode_calibration},
    {'4', Action::mode_yaw_control},
    {'5', Action::mode_full_control},
    {'7', Action::height_hold},    // IN4073's height mode key
    {'8', Action::mode_acro},      // after IN4073's keys: the rate loops alone
    {'=', Action::mode_autotune},  // every letter and digit is taken (capitals fold to small ones)
    {'a', Action::lift_up},
    {'z', Action::lift_down},
    {kKeyPageUp, Action::lift_up_coarse},
    {kKeyPageDown, Action::lift_down_coarse},
    {kKeyHome, Action::lift_hover},  // beside PgUp and PgDn, the other lift keys
    {kKeyLeft, Action::roll_left},
    {kKeyRight, Action::roll_right},
    {kKeyUp, Action::pitch_down},
    {kKeyDown, Action::pitch_up},
    {'q', Action::yaw_left},
    {'w', Action::yaw_right},
    {'c', Action::trims_center},
    {'u', Action::yaw_p_up},
    {'j', Action::yaw_p_down},
    {'i', Action::p1_up},
    {'k', Action::p1_down},
    {'o', Action::p2_up},
    {'l', Action::p2_down},
    {'e', Action::c1_up},
    {'d', Action::c1_down},
    {'r', Action::c2_up},
    {'f', Action::c2_down},
    {'s', Action::log_start},
    {'t', Action::log_stop},
    {'g', Action::log_download},
    {'p', Action::params_read},
    {'b', Action::tasks_print},
    {'n', Action::sim_push},
    {'v', Action::sim_reset},
    {'y', Action::sim_turn},
    {'m', Action::sim_radio_off},
    {'9', Action::orientation_check},  // beside the mode keys: a step before the first flight, in safe
    // IN4073's raw-mode key, a mode this firmware does not have: the other bench step, in safe.
    {'6', Action::motor_test},
    {'h', Action::help},
    {'?', Action::help},
};

inline constexpr size_t kKeyBindingCount = sizeof(kKeyMap) / sizeof(kKeyMap[0]);

// The action bound to a key; Action::none for an unbound key. Capital letters act like small ones,
// so a pilot with caps lock on still has every key (the map binds no capital letter).
Action action_for(Key key);

// The help overlay's entries: the key map in its order, keys that do the same sharing one entry
// ("x ^C", "h ?").
struct HelpEntry {
  std::string keys;
  Action action;
};
std::vector<HelpEntry> help_entries();

// The help overlay at 80x24 holds three columns of 15 entries under the engine rows.
inline constexpr size_t kHelpEntriesAt80x24 = 3 * 15;

}  // namespace qrterm
