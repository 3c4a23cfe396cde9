// The screen: status on top (mode, link, battery, engines, attitude, set-points, trims, gains),
// the scrolling log below, LINK LOST across it when the QR is silent, the key help over it on
// request. 80x24 is enough; more rows go to the log, more columns to the bars and log lines.
// Two steps, so the terminal never holds up the link: compose() reads the Console and builds the
// screen in memory (under the lock the link thread shares); show() writes it to the terminal,
// which may block (a slow or frozen terminal), with the lock released.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <pc/core/console.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {

struct CockpitLabels {
  std::string source;  // "sim /dev/pts/3" or "/dev/ttyUSB0 115200"
  std::string log_folder;
  std::string joystick;  // "/dev/input/js0", or empty without one
};

class Cockpit {
 public:
  explicit Cockpit(CockpitLabels labels) : labels_(std::move(labels)) {}

  void compose(const Console& console);
  void show();

  // The plot's latency from the QR's tick to the screen, on the simulator with a time_ms trace:
  // "plot latency, tick to screen: median 23 ms over 240 screens (time_ms against qrsim's clock)",
  // or empty when there was nothing to measure.
  std::string latency_summary() const;

  static constexpr int kMinRows = 24;
  static constexpr int kMinColumns = 80;

 private:
  void draw_title(const Console& console, int width);
  void draw_mode_and_link(const Console& console, int width);
  void draw_system(const Console& console, int width);
  void draw_engines_and_attitude(const Console& console, int width);
  void draw_pilot(const Console& console, int width);
  void draw_height(const Console& console, int width);
  void draw_hardware(const Console& console, int width);
  void draw_log(const Console& console, int top, int rows, int width);
  void draw_link_alarm(const Console& console, int width);
  void draw_help(int rows, int width);
  void note_plotted_sample(const Console& console);

  CockpitLabels labels_;
  bool braille_ = terminal_speaks_utf8();
  // The newest time_ms sample in the screen being written, on the console's clock (ms), and the
  // last one measured: each sample is measured on the first screen that shows it.
  std::optional<int64_t> shown_sample_ms_;
  int64_t measured_sample_ms_ = -1;
  std::vector<uint32_t> latencies_ms_;
  LinkState alarmed_ = LinkState::waiting;
  bool bell_ = false;  // the link was just lost, or the descent warning came up: ring once
  bool sinking_shown_ = false;
};

}  // namespace qrterm
