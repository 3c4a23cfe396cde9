#include <pc/ui/joystick_wizard_screen.hpp>

#include <poll.h>
#include <unistd.h>

#include <vector>

#include <pc/core/joystick_wizard.hpp>
#include <pc/core/js_event_stream.hpp>
#include <pc/core/settings_text.hpp>
#include <pc/platform/clock.hpp>
#include <pc/platform/signals.hpp>
#include <pc/ui/screen_draw.hpp>

namespace qrterm {
namespace {

constexpr int kPollMs = 20;  // the rest's bar and the axes move smoothly at this
constexpr int kFirstStepRow = 2;
constexpr int kSummaryColumn = 12;
constexpr WizardStep kAsked[] = {WizardStep::rest, WizardStep::roll, WizardStep::pitch,
                                 WizardStep::yaw,  WizardStep::lift, WizardStep::fire};
constexpr int kAskedSteps = static_cast<int>(std::size(kAsked));

// Words onto lines of at most `width` characters.
std::vector<std::string> wrap(const std::string& words, int width) {
  std::vector<std::string> lines(1);
  size_t start = 0;
  while (start < words.size()) {
    size_t end = words.find(' ', start);
    if (end == std::string::npos) end = words.size();
    const std::string word = words.substr(start, end - start);
    if (!lines.back().empty() && static_cast<int>(lines.back().size() + 1 + word.size()) > width) lines.emplace_back();
    lines.back() += (lines.back().empty() ? "" : " ") + word;
    start = end + 1;
  }
  return lines;
}

// Puts wrapped text from `row`, indented; returns the row after it.
int put_wrapped(int row, int indent, const std::string& words, int width, short pair = 0) {
  for (const std::string& line : wrap(words, width - indent - 1)) put(row++, indent, line, pair);
  return row;
}

class WizardScreen {
 public:
  WizardScreen(const JoystickWizard& wizard, const WizardFiles& files) : wizard_(wizard), files_(files) {}

  void draw(uint32_t now_ms, const std::string& write_error) {
    erase();
    const int width = COLS;
    attron(COLOR_PAIR(kTitle));
    mvhline(0, 0, ' ', width);
    attroff(COLOR_PAIR(kTitle));
    put(0, 0, " qrterm joystick wizard | " + files_.joystick + " -> " + files_.map, kTitle);
    draw_steps();
    const int row = kFirstStepRow + kAskedSteps + 1;
    if (wizard_.step() == WizardStep::review) {
      draw_review(row, width, write_error);
    } else {
      draw_current(row, width, now_ms);
    }
    refresh();
  }

 private:
  // One row a step: done ones with what they found, the current one marked.
  void draw_steps() {
    const size_t current = static_cast<size_t>(wizard_.step());
    for (int i = 0; i < kAskedSteps; ++i) {
      const WizardStep step = kAsked[i];
      const size_t index = static_cast<size_t>(step);
      const int row = kFirstStepRow + i;
      put(row, 1, text("%s %d %s", index == current ? ">" : " ", i + 1, JoystickWizard::name(step)), 0,
          index == current ? A_BOLD : A_NORMAL);
      if (index < current) put(row, kSummaryColumn, done_text(step), kDim);
    }
  }

  std::string done_text(WizardStep step) const {
    if (step == WizardStep::rest) return "done";
    if (step == WizardStep::fire) {
      return wizard_.fire_button() ? text("button %u", *wizard_.fire_button()) : std::string("no button");
    }
    return wizard_.summary(step);
  }

  void draw_current(int row, int width, uint32_t now_ms) {
    const WizardStep step = wizard_.step();
    put(row++, 1, text("Step %zu of %d: %s", static_cast<size_t>(step) + 1, kAskedSteps, JoystickWizard::name(step)), 0,
        A_BOLD);
    row = put_wrapped(row, 1, JoystickWizard::instruction(step), width) + 1;
    put(row++, 1, live_text(now_ms), kQr);
    row = draw_axes(row + 1, width);
    put(LINES - 1, 1,
        step == WizardStep::rest && !wizard_.resting() ? "Enter: start the rest   ESC: leave without writing"
                                                       : "Enter: next step   ESC: leave without writing",
        kDim);
  }

  // What the joystick is doing for the step now.
  std::string live_text(uint32_t now_ms) const {
    const WizardStep step = wizard_.step();
    if (step == WizardStep::rest) {
      if (!wizard_.resting()) return wizard_.axes().empty() ? "waiting for the joystick to report" : "ready";
      const int32_t done = wizard_.rest_done_permille(now_ms);
      return "keep still [" + std::string(static_cast<size_t>(done / 50), '#') +
             std::string(static_cast<size_t>(20 - done / 50), ' ') + "]";
    }
    if (step == WizardStep::fire) return "waiting for a button";
    const ControlFound lead = wizard_.leading();
    if (lead.max == lead.min) return "nothing has moved yet";
    return text("found: axis %u, moved %d..%d%s", lead.axis, lead.min, lead.max,
                lead.moved ? (lead.invert ? ", reads - (inverted)" : ", reads +") : ": not yet half its range");
  }

  // Every axis and where it is, as jstest shows them.
  int draw_axes(int row, int width) {
    std::string line = "axes now:";
    for (const auto& [axis, value] : wizard_.axes()) {
      const std::string entry = text("  %u %+d", axis, value);
      if (static_cast<int>(line.size() + entry.size()) > width - 2) {
        put(row++, 1, line, kDim);
        line = "         ";
      }
      line += entry;
    }
    put(row++, 1, line, kDim);
    return row;
  }

  void draw_review(int row, int width, const std::string& write_error) {
    const bool writable = wizard_.errors().empty();
    put(row++, 1, text("deadband %d per mille", wizard_.map().deadband_permille), 0, A_BOLD);
    put(row++, 3, wizard_.deadband_reason(), kDim);
    ++row;
    if (!writable) put(row++, 1, "NOT WRITTEN: " + files_.map + " stays as it was", kError, A_BOLD);
    for (const std::string& error : wizard_.errors()) row = put_wrapped(row, 1, error, width, kError);
    for (const std::string& note : wizard_.notes()) row = put_wrapped(row, 1, note, width, kWarning);
    if (!write_error.empty()) put_wrapped(row, 1, write_error, width, kError);
    put(LINES - 1, 1,
        writable ? "Enter: write " + files_.map + "   r: start again   ESC: leave without writing"
                 : std::string("r: start again   ESC: leave without writing"),
        writable ? kInfo : kDim, A_BOLD);
  }

  const JoystickWizard& wizard_;
  const WizardFiles& files_;
};

}  // namespace

WizardOutcome run_joystick_wizard(const WizardFiles& files, Terminal& terminal) {
  JoystickWizard wizard;
  JsEventStream stream;
  WizardScreen screen(wizard, files);
  std::string write_error;
  const WizardOutcome left{1, "joystick wizard left: nothing written to " + files.map};
  for (;;) {
    pollfd fds[2] = {{STDIN_FILENO, POLLIN, 0}, {files.joystick_fd, POLLIN, 0}};
    ::poll(fds, 2, kPollMs);
    const uint32_t now = monotonic_ms();
    if (fds[1].revents != 0 && stream.read_from(files.joystick_fd, [&](const js_event& e) { wizard.event(e); }) ==
                                   JsEventStream::ReadResult::lost) {
      return {1, "the joystick at " + files.joystick + " went away: nothing written to " + files.map};
    }
    if (exit_signals() > 0) return left;
    for (Key key = terminal.next_key(); key != kKeyNone; key = terminal.next_key()) {
      if (key == kKeyEscape || key == kKeyInterrupt) return left;
      if (key == 'r' && wizard.step() == WizardStep::review) wizard.restart();
      if (key != kKeyEnter) continue;
      if (wizard.step() != WizardStep::review) {
        wizard.next(now);
      } else if (wizard.errors().empty()) {
        write_error = write_file_atomically(files.map, wizard.map_text());
        if (write_error.empty())
          return {0, "joystick map written to " + files.map + ": qrterm reads it at its next start"};
      }
    }
    wizard.tick(now);
    screen.draw(now, write_error);
  }
}

}  // namespace qrterm
