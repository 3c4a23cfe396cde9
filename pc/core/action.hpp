// Everything the pilot can ask of the console, whichever device the request comes from (a key,
// the joystick's fire button). Each action has one line of text, used by the help overlay and
// checked against docs/console.md by a test.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace qrterm {

enum class Action : uint8_t {
  none,
  abort,  // panic now; the QR then settles in safe by itself
  exit,   // command exit, wait for the QR's confirmation, quit
  mode_safe,
  mode_panic,
  mode_manual,
  mode_calibration,
  mode_yaw_control,
  mode_full_control,
  mode_acro,
  mode_autotune,  // the identification flight, from full control (issue 34)
  motor_test,     // the motor test screen (in safe, propellers off)
  height_hold,    // toggles: height hold from full control, full control from height hold
  lift_up,
  lift_down,
  lift_up_coarse,  // ten steps at once: from the ground to a hover in a few presses
  lift_down_coarse,
  lift_hover,  // the lift to the hover lift the QR learnt in flight (nothing while it has learnt none)
  roll_left,
  roll_right,
  pitch_down,  // nose down: the stick pushed forward
  pitch_up,    // nose up: the stick pulled back
  yaw_left,
  yaw_right,
  trims_center,
  yaw_p_up,
  yaw_p_down,
  p1_up,
  p1_down,
  p2_up,
  p2_down,
  c1_up,
  c1_down,
  c2_up,
  c2_down,
  log_start,
  log_stop,
  log_download,
  params_read,
  tasks_print,
  sim_push,       // the simulator pushes the QR (0.3 N m about roll for 0.1 s); not on a real QR
  sim_reset,      // the simulator sets the vehicle down upright (after a crash); not on a real QR
  sim_turn,       // the simulator's hand turns the vehicle twice about a body axis (z, x, y in turn); not on a real QR
  sim_radio_off,  // the simulator's radio: its arm switch off (a panic in flight); not on a real QR
  orientation_check,  // the orientation check's screen, in safe: is the IMU mounted as the QR takes it?
  help,
};

struct ActionSpec {
  Action action;
  const char* text;
};

// Texts stay within kActionTextMax characters: at 80x24 the help overlay shows three columns under
// the engine rows, so the pilot still sees mode, link and engines while reading it, with two
// spaces between the columns (help_overlay.hpp).
inline constexpr ActionSpec kActions[] = {
    {Action::abort, "panic (2x: exit)"},
    {Action::exit, "exit (QR to safe)"},
    {Action::mode_safe, "mode safe"},
    {Action::mode_panic, "mode panic"},
    {Action::mode_manual, "mode manual"},
    {Action::mode_calibration, "mode calibration"},
    {Action::mode_yaw_control, "mode yaw control"},
    {Action::mode_full_control, "mode full control"},
    {Action::mode_acro, "mode acro"},
    {Action::mode_autotune, "autotune"},
    {Action::motor_test, "motor test (bench)"},
    {Action::height_hold, "height hold on/off"},
    {Action::lift_up, "lift up"},
    {Action::lift_down, "lift down"},
    {Action::lift_up_coarse, "lift up x10"},
    {Action::lift_down_coarse, "lift down x10"},
    {Action::lift_hover, "lift to the hover"},
    {Action::roll_left, "roll left"},
    {Action::roll_right, "roll right"},
    {Action::pitch_down, "pitch: nose down"},
    {Action::pitch_up, "pitch: nose up"},
    {Action::yaw_left, "yaw left"},
    {Action::yaw_right, "yaw right"},
    {Action::trims_center, "all trims to zero"},
    {Action::yaw_p_up, "yaw P up"},
    {Action::yaw_p_down, "yaw P down"},
    {Action::p1_up, "P1 angle gain up"},
    {Action::p1_down, "P1 angle gain down"},
    {Action::p2_up, "P2 rate gain up"},
    {Action::p2_down, "P2 rate gain down"},
    {Action::c1_up, "C1 (filter) x2"},
    {Action::c1_down, "C1 (filter) /2"},
    {Action::c2_up, "C2 filter bias x2"},
    {Action::c2_down, "C2 filter bias /2"},
    {Action::log_start, "QR logging start"},
    {Action::log_stop, "QR logging stop"},
    {Action::log_download, "download QR logs"},
    {Action::params_read, "read params back"},
    {Action::tasks_print, "task costs to log"},
    {Action::sim_push, "sim: push (roll)"},
    {Action::sim_reset, "sim: set upright"},
    {Action::sim_turn, "sim: turn z, x, y"},
    {Action::sim_radio_off, "sim radio: arm off"},
    {Action::orientation_check, "orientation check"},
    {Action::help, "help on/off"},
};

inline constexpr size_t kActionTextMax = 18;

const char* action_text(Action action);

}  // namespace qrterm
