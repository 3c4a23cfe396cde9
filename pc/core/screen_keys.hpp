// The keys of the plot, parameter, radio and orientation check screens, as one table. They are
// looked up before the cockpit's key map, and only on their screen; every other key (the abort
// keys, modes, lift and the trims, exit) still does what the cockpit's map says, so the pilot flies
// from any screen. Tab cycles the cockpit, plot, parameter and radio screens; the orientation check
// is entered by its key in safe (key_map.hpp) and left by Tab, to the cockpit. The motor test's
// screen (motor_bench.hpp) is entered by its key in safe too; it takes every key but the abort and
// exit keys (any key stops a spinning engine).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <pc/core/key.hpp>

namespace qrterm {

enum class Screen : uint8_t { cockpit, plot, parameters, radio, orientation, motor_test };
inline constexpr size_t kScreenCount = 6;
inline constexpr size_t kTabScreens = 4;  // the screens Tab goes round, the first four
inline constexpr const char* kScreenNames[kScreenCount] = {"cockpit",           "plot",      "parameters", "radio",
                                                           "orientation check", "motor test"};

enum class ScreenAction : uint8_t {
  none,
  plot_pick,  // opens the prompt: observable names
  plot_remove_last,
  plot_window,
  plot_scale,
  plot_zoom_in,
  plot_zoom_out,
  plot_freeze,
  plot_faster,
  plot_slower,
  param_previous,
  param_next,
  param_step_down,
  param_step_up,
  param_type,  // opens the prompt: a value
  param_default,
  param_all_defaults,
  param_save,  // opens the prompt: a file name
  param_load,
  param_take_tuned,       // autotune's new gains to the QR
  param_back_from_tuned,  // the gains flown before autotune to the QR again
  radio_ends_again,
  orientation_enter,    // start the step; on the verdict, set it or check again
  orientation_restart,  // from the first step again
};

struct ScreenKey {
  Screen screen;
  Key key;
  ScreenAction action;
  const char* text;  // the screen's key line and docs/console.md
};

inline constexpr Key kKeyCtrlS = 19;
inline constexpr Key kKeyCtrlO = 15;
inline constexpr Key kKeyCtrlT = 20;
inline constexpr Key kKeyCtrlR = 18;  // not ^B: the prefix of tmux, where many run the console

inline constexpr ScreenKey kScreenKeys[] = {
    {Screen::plot, '/', ScreenAction::plot_pick, "pick observables by name"},
    {Screen::plot, kKeyBackspace, ScreenAction::plot_remove_last, "remove the last trace"},
    {Screen::plot, 'm', ScreenAction::plot_window, "time window 2/5/10/30 s"},
    {Screen::plot, 'y', ScreenAction::plot_scale, "autoscale / fixed scale"},
    {Screen::plot, '+', ScreenAction::plot_zoom_in, "fixed scale, zoom in"},
    {Screen::plot, '-', ScreenAction::plot_zoom_out, "fixed scale, zoom out"},
    {Screen::plot, ' ', ScreenAction::plot_freeze, "freeze / resume"},
    {Screen::plot, '.', ScreenAction::plot_faster, "sample rate up"},
    {Screen::plot, ',', ScreenAction::plot_slower, "sample rate down"},
    {Screen::parameters, kKeyUp, ScreenAction::param_previous, "previous parameter"},
    {Screen::parameters, kKeyDown, ScreenAction::param_next, "next parameter"},
    {Screen::parameters, kKeyLeft, ScreenAction::param_step_down, "step down, sent at once"},
    {Screen::parameters, kKeyRight, ScreenAction::param_step_up, "step up, sent at once"},
    {Screen::parameters, kKeyEnter, ScreenAction::param_type, "type a value"},
    {Screen::parameters, '=', ScreenAction::param_default, "back to the default"},
    {Screen::parameters, '!', ScreenAction::param_all_defaults, "every parameter to its default"},
    {Screen::parameters, kKeyCtrlS, ScreenAction::param_save, "save to a named file"},
    {Screen::parameters, kKeyCtrlO, ScreenAction::param_load, "load a named file"},
    {Screen::parameters, kKeyCtrlT, ScreenAction::param_take_tuned, "take autotune's new gains"},
    {Screen::parameters, kKeyCtrlR, ScreenAction::param_back_from_tuned, "back to the gains before autotune"},
    {Screen::radio, ' ', ScreenAction::radio_ends_again, "count the sticks' ends again from now"},
    {Screen::orientation, kKeyEnter, ScreenAction::orientation_enter, "start the step / set it"},
    {Screen::orientation, kKeyBackspace, ScreenAction::orientation_restart, "from step 1 again"},
};

constexpr ScreenAction screen_action(Screen screen, Key key) {
  for (const ScreenKey& k : kScreenKeys) {
    if (k.screen == screen && k.key == key) return k.action;
  }
  return ScreenAction::none;
}

}  // namespace qrterm
