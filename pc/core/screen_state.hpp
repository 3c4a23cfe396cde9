// What the pilot looks at (docs/console.md "The screen"): which screen, the help over it, and the
// line being typed on the plot or parameter screen. The keys those screens own (screen_keys.hpp)
// act here, on the plot's streams, the parameter editor, the radio screen's ends and the
// orientation check; every other key is the cockpit's, so the pilot flies from any screen. Showing
// the radio screen gives it the QR's streams, leaving it gives them back to the plot.
#pragma once

#include <stdint.h>

#include <functional>
#include <optional>
#include <string>

#include <pc/core/autotune_session.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/key.hpp>
#include <pc/core/orientation_check.hpp>
#include <pc/core/parameter_editor.hpp>
#include <pc/core/parameter_sync.hpp>
#include <pc/core/screen_keys.hpp>
#include <pc/core/stream_session.hpp>

namespace qrterm {

// A line the pilot is typing on the plot or parameter screen.
enum class PromptKind : uint8_t { observables, value, save, load };
struct Prompt {
  PromptKind kind;
  std::string text;
};

class ScreenState {
 public:
  using Note = std::function<void(Severity, const std::string&)>;

  ScreenState(StreamSession& streams, ParameterEditor& editor, ParameterSync& parameters, OrientationCheck& check,
              AutotuneSession& autotune, Note note)
      : streams_(streams), editor_(editor), parameters_(parameters), check_(check), autotune_(autotune),
        note_(std::move(note)) {}

  enum class Taken : uint8_t {
    no,         // the cockpit's key
    by_prompt,  // typed into the prompt
    by_screen,  // Tab, or a key of the screen shown
  };
  // A key, before the cockpit's key map. The prompt takes the typing; the abort keys and ^C still
  // act, and close it. `now_s`: the console's clock, for the plot.
  Taken key(Key key, double now_s);

  // The orientation check's screen, from its first step (the console has checked the QR is in safe).
  void show_orientation_check() {
    help_ = false;
    prompt_.reset();
    screen_ = Screen::orientation;
    check_.start();
  }

  void toggle_help() { help_ = !help_; }
  // A screen opened by a key of the cockpit's (the motor test), and back to the cockpit.
  void show(Screen screen) {
    help_ = false;
    prompt_.reset();
    screen_ = screen;
  }
  // Any key but the help key closes the help, and still acts.
  void close_help() { help_ = false; }

  Screen screen() const { return screen_; }
  bool help_visible() const { return help_; }
  const std::optional<Prompt>& prompt() const { return prompt_; }

 private:
  bool screen_key(Key key, double now_s);
  void prompt_key(Key key);
  void submit(const Prompt& prompt);

  StreamSession& streams_;
  ParameterEditor& editor_;
  ParameterSync& parameters_;
  OrientationCheck& check_;
  AutotuneSession& autotune_;
  Note note_;
  Screen screen_ = Screen::cockpit;
  bool help_ = false;
  std::optional<Prompt> prompt_;
};

}  // namespace qrterm
