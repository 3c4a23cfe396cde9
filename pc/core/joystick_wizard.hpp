// The joystick wizard's logic (qrterm --joystick-wizard): the pilot lets go of everything, moves
// each control through its range in turn, then presses the fire button; from the driver's events
// the wizard finds each control's axis, which way round it reads, its range and, from the rest,
// the deadband, and writes them as a joystick map (joystick_map.hpp). A result it cannot trust (a
// control never moved, two controls on one axis, a control not at rest while resting, no button)
// is refused with the reasons, and nothing is written. No terminal, no device: the driver's events,
// the pilot's Enter and the time come in; the step, what was found and the map's text go out.
#pragma once

#include <linux/joystick.h>
#include <stddef.h>
#include <stdint.h>

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pc/core/joystick_map.hpp>

namespace qrterm {

// In the order the pilot is asked; review is the end, where the result is shown.
enum class WizardStep : uint8_t { rest, roll, pitch, yaw, lift, fire, review };
inline constexpr size_t kWizardSteps = 7;

// What one control's step found.
struct ControlFound {
  bool moved = false;  // an axis travelled at least half its range in the step
  uint8_t axis = 0;
  bool invert = false;  // the direction the pilot was asked for first read negative
  int32_t min = 0;      // the axis's raw range in the step
  int32_t max = 0;
  std::optional<int32_t> rest_permille;  // its highest reading while resting, before any deadband
};

class JoystickWizard {
 public:
  static constexpr uint32_t kRestMs = 1000;  // how long the pilot keeps still
  static constexpr size_t kMaxAxes = 64;     // the Linux API numbers axes in a byte; no stick has more

  // One event as the driver delivers it (the state reported at open, flagged JS_EVENT_INIT, too).
  void event(const js_event& event);
  // The pilot's Enter: starts the rest, ends a move step, ends the fire step without a button.
  void next(uint32_t now_ms);
  // Ends the rest once it has lasted kRestMs.
  void tick(uint32_t now_ms);
  // From the first step again; the axes' positions are kept.
  void restart();

  WizardStep step() const { return step_; }
  bool resting() const { return resting_; }
  // How much of the rest has passed, per mille (for a bar).
  int32_t rest_done_permille(uint32_t now_ms) const;

  // The step's name ("roll") and what the pilot is asked to do in it.
  static const char* name(WizardStep step);
  static const char* instruction(WizardStep step);

  // In a move step: the axis moved most so far, as it would be found if the step ended now.
  ControlFound leading() const;
  // A finished step's findings: for roll, pitch, yaw and lift.
  const ControlFound& found(WizardStep control) const;
  std::optional<uint8_t> fire_button() const { return fire_button_; }
  // "axis 1, -32767..32767, right reads +", or why nothing was found.
  std::string summary(WizardStep control) const;

  // At review: why the result cannot be written (empty: it can), and what is worth knowing but
  // does not stop it (a control short of full deflection).
  const std::vector<std::string>& errors() const { return errors_; }
  const std::vector<std::string>& notes() const { return notes_; }
  const JoystickMap& map() const { return map_; }
  // Where the deadband came from: "twice the 30 per mille roll read at rest".
  std::string deadband_reason() const;
  // The file to write: what each step found, as comments, then the map.
  std::string map_text() const;

  // Every axis reported so far and where it is now, for the screen: (number, value).
  std::vector<std::pair<uint8_t, int32_t>> axes() const;

 private:
  // One axis's movement since a step (or the rest) began.
  struct Travel {
    bool seen = false;
    int32_t start = 0;
    int32_t min = 0;
    int32_t max = 0;
    int8_t first_sign = 0;  // the side of the first large excursion from start
  };
  using Travels = std::array<Travel, kMaxAxes>;

  static void follow(Travel& travel, int32_t value);
  void from_here(Travels& travels) const;  // every axis reported starts where it is now
  void begin(WizardStep step);
  void finish_move_step();
  void review();
  void check_control(WizardStep control);
  ControlFound most_moved(const Travels& travels) const;
  std::optional<int32_t> rest_reading(WizardStep control, const ControlFound& found) const;

  WizardStep step_ = WizardStep::rest;
  bool resting_ = false;
  uint32_t rest_start_ms_ = 0;
  std::array<int32_t, kMaxAxes> value_{};
  std::array<bool, kMaxAxes> seen_{};
  Travels rest_{};
  Travels travel_{};  // the current move step's
  std::array<ControlFound, kWizardSteps> found_{};
  std::optional<uint8_t> fire_button_;
  std::vector<std::string> errors_;
  std::vector<std::string> notes_;
  JoystickMap map_;
};

}  // namespace qrterm
