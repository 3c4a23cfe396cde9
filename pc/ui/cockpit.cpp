#include <pc/ui/cockpit.hpp>

#include <ncurses.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include <pc/core/help_overlay.hpp>
#include <pc/core/key_map.hpp>
#include <pc/core/mode_names.hpp>
#include <pc/core/param_file.hpp>
#include <pc/core/radio_pilot.hpp>
#include <pc/core/task_figures.hpp>
#include <pc/platform/clock.hpp>
#include <pc/ui/screen_draw.hpp>
#include <pc/ui/screens.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {
namespace {

constexpr double kDegPerRad = 57.29577951308232;

double degrees(int32_t ten_thousandths_rad) { return ten_thousandths_rad * 1e-4 * kDegPerRad; }
double degrees_per_s(int32_t thousandths_rad_s) { return thousandths_rad_s * 1e-3 * kDegPerRad; }

short mode_color(wire::Mode mode) {
  if (mode == wire::Mode::panic) return kAlarm;
  if (is_flight_mode(mode) || mode == wire::Mode::motor_test) return kWarning;  // engines may turn
  return mode == wire::Mode::calibration ? kQr : kInfo;
}

short severity_color(Severity severity) {
  constexpr short kColors[] = {kInfo, kWarning, kError, kQr};
  return kColors[static_cast<size_t>(severity)];
}

// Engines, attitude and so on are blank until their telemetry group has arrived: a zero would
// look like data.
constexpr const char* kUnknown = "--";

}  // namespace

void Cockpit::draw_title(const Console& console, int width) {
  attron(COLOR_PAIR(kTitle));
  mvhline(0, 0, ' ', width);
  attroff(COLOR_PAIR(kTitle));
  std::string title = text(" qrterm | %s | %.1f s | logs %s", labels_.source.c_str(), console.uptime_ms() / 1000.0,
                           labels_.log_folder.c_str());
  put(0, 0, title, kTitle);
  const std::string screen = text(" %s (Tab) ", kScreenNames[static_cast<size_t>(console.screen())]);
  put(0, width - 11 - static_cast<int>(screen.size()), screen, kTitle, A_BOLD);
  put(0, width - 11, " h: help ", kTitle, A_BOLD);
}

void Cockpit::draw_mode_and_link(const Console& console, int width) {
  const TelemetryModel& t = console.telemetry();
  const LinkState state = console.link_state();
  put(1, 0, "MODE", 0, A_BOLD);
  if (!t.attitude) {
    put(1, 5, " unknown ", kDim);
  } else if (state != LinkState::up) {
    put(1, 5, text(" %s? ", mode_name(t.attitude->mode)), kDim);  // the last mode heard, maybe no longer true
  } else {
    put(1, 5, text(" %s ", mode_name(t.attitude->mode)), mode_color(t.attitude->mode), A_BOLD | A_REVERSE);
  }
  const LinkFigures& f = console.link().figures();
  const wire::LinkCounters& c = console.link().counters();
  if (state == LinkState::lost || state == LinkState::closed) {
    attron(COLOR_PAIR(kAlarm) | A_BOLD);
    mvhline(1, 20, ' ', width - 20);
    attroff(COLOR_PAIR(kAlarm) | A_BOLD);
    const std::string why = state == LinkState::closed ? "serial line gone"
                                                       : text("no valid frame for %.1f s",
                                                              console.link().silence_ms(console.now_ms()) / 1000.0);
    put(1, 21, "LINK LOST  " + why, kAlarm, A_BOLD | A_BLINK);
    return;
  }
  put(1, 20, "LINK", 0, A_BOLD);
  put(1, 25, state == LinkState::up ? "up" : "waiting", state == LinkState::up ? kInfo : kWarning, A_BOLD);
  // The descent warning takes the link's figures' place: on every screen, beside the mode, where
  // LINK LOST would be; the figures come back when it ends. A bell when it starts.
  const std::optional<double> sinking = console.sinking_m_s();
  if (sinking && !sinking_shown_) bell_ = true;
  sinking_shown_ = sinking.has_value();
  if (sinking) {
    put(1, 34, text(console.sinking_in_panic() ? " SINKING %.1f m/s (panic) " : " SINKING %.1f m/s: lift! ", *sinking),
        kAlarm, A_BOLD);
    return;
  }
  const std::string rtt = f.round_trip_ms >= 0 ? text("%d ms", f.round_trip_ms) : std::string(kUnknown);
  put(1, 34, text("%3u frames/s   round trip %-6s  bad %u", f.frames_per_s, rtt.c_str(), c.check_failures));
  (void)width;
}

void Cockpit::draw_system(const Console& console, int width) {
  const TelemetryModel& t = console.telemetry();
  put(2, 0, "battery", 0, A_BOLD);
  if (t.system) {
    const wire::TelemetrySystem& s = *t.system;
    const bool low = t.flag(wire::kFlagBatteryWarning);
    put(2, 8, text("%5.2f V", s.battery_mv / 1000.0), low ? kError : kInfo, low ? A_BOLD | A_REVERSE : A_NORMAL);
    // The charge and the time to the QR's battery panic; yellow once it is near (battery_gauge.hpp).
    if (const std::optional<BatteryReading> charge = console.battery()) {
      put(2, 16, charge_text(*charge), charge->near_panic ? kWarning : kInfo, charge->near_panic ? A_BOLD : A_NORMAL);
    }
    // What the figures are depends on what flies (task_figures.hpp): none on the simulator's host
    // build, the devboard's instructions or its core's load, a board's own.
    const CpuRow cpu = cpu_row(s, console.figures_from(), console.devboard());
    put(2, 37, cpu.text, cpu.figures ? 0 : kDim);
  } else {
    put(2, 8, "-- V", kDim);
    put(2, 37, "cpu -- %  loop -- us  misses --", kDim);
  }
  int column = 0;
  put(3, column, "QR", 0, A_BOLD);
  column += 3;
  struct Flag {
    uint8_t bit;
    const char* name;
    short pair;
  };
  constexpr Flag kFlags[] = {{wire::kFlagCalibrated, "calibrated", kInfo},
                             {wire::kFlagLogging, "logging", kQr},
                             {wire::kFlagBatteryWarning, "battery low", kError},
                             {wire::kFlagLogFull, "log full", kWarning},
                             {wire::kFlagFlying, "flying", kInfo}};
  // The first thing to do, said where the pilot looks first (a newcomer chose a mode at once).
  if (t.attitude && !t.flag(wire::kFlagCalibrated)) {
    const std::string hint = "not calibrated: calibrate (3), keep it still, then choose a mode";
    put(3, column, hint, kWarning);
    column += static_cast<int>(hint.size()) + 1;
  }
  for (const Flag& flag : kFlags) {
    if (!t.flag(flag.bit)) continue;
    put(3, column, flag.name, flag.pair, A_BOLD);
    column += static_cast<int>(std::string(flag.name).size()) + 1;
  }
  // What the QR believes besides: on the ground (no "flying"), and the lift it learnt carries it.
  if (t.attitude && !t.flag(wire::kFlagFlying)) {
    const std::string landed = "landed";
    put(3, column, landed, kDim);
    column += static_cast<int>(landed.size()) + 1;
  }
  if (t.height && t.height->hover_lift > 0) {
    const std::string hover = text("hover lift %u", static_cast<unsigned>(t.height->hover_lift));
    put(3, column, hover, kInfo);
    column += static_cast<int>(hover.size()) + 1;
  }
  // The QR's logs: lines kept of the room there is (both logs keep the same number).
  if (const std::optional<wire::LogStatus>& logs = t.log_status;
      logs && (logs->sensor_lines > 0 || logs->telemetry_lines > 0)) {
    const std::string s = text("log %u/%u", std::max(logs->sensor_lines, logs->telemetry_lines), logs->capacity_lines);
    put(3, column + 1, s, (logs->flags & wire::kLogStatusFull) != 0 ? kWarning : kDim);
    column += static_cast<int>(s.size()) + 2;
  }
  std::string status = console.download_status();
  if (console.parameters_to_send() > 0)
    status += text("%sparameters to send: %zu", status.empty() ? "" : "  ", console.parameters_to_send());
  if (console.exiting()) status = "exiting: waiting for the QR";
  put(3, std::max(column + 2, 44), status, kQr, A_BOLD);
  (void)width;
}

void Cockpit::draw_engines_and_attitude(const Console& console, int width) {
  const TelemetryModel& t = console.telemetry();
  constexpr const char* kEngineNames[] = {"front", "right", "back", "left"};
  const int half = width / 2;
  const int bar = std::max(10, half - 14);
  for (int i = 0; i < 4; ++i) {
    const int row = 4 + i;
    put(row, 0, kEngineNames[i], 0, A_BOLD);
    if (!t.engines) {
      put(row, 6, text("%4s", kUnknown), kDim);
      continue;
    }
    const int value = t.engines->engine[i];
    put(row, 6, text("%4d", value));
    const int filled = value * bar / 1000;
    put(row, 11, std::string(static_cast<size_t>(filled), '#'), kBar, A_BOLD);
    put(row, 11 + filled, std::string(static_cast<size_t>(bar - filled), '.'), kDim);
  }
  const int x = half + 2;
  // Before calibration the gyro biases are unknown and the estimate drifts (12-15 degrees of roll
  // at rest were seen): shown as not valid rather than as an attitude.
  const bool valid = t.flag(wire::kFlagCalibrated);
  put(4, x, "        angle deg   rate deg/s", 0, A_BOLD);
  constexpr const char* kAxes[] = {"roll", "pitch", "yaw"};
  for (int i = 0; i < 3; ++i) {
    std::string angle = kUnknown;
    std::string rate = kUnknown;
    if (t.attitude && !valid) {
      put(5 + i, x, text("%-6s %9s %12s", kAxes[i], "not valid", "not valid"), kDim);
      continue;
    }
    if (t.attitude) {
      const int16_t a[] = {t.attitude->phi, t.attitude->theta, t.attitude->psi};
      angle = text("%+8.2f", degrees(a[i]));
    }
    if (t.rates) {
      const int16_t r[] = {t.rates->p, t.rates->q, t.rates->r};
      rate = text("%+8.1f", degrees_per_s(r[i]));
    }
    put(5 + i, x, text("%-6s %9s %12s", kAxes[i], angle.c_str(), rate.c_str()));
  }
}

void Cockpit::draw_pilot(const Console& console, int width) {
  const TelemetryModel& t = console.telemetry();
  put(8, 0, "set-point", 0, A_BOLD);
  if (t.setpoints) {
    const wire::TelemetrySetpoints& s = *t.setpoints;
    put(8, 10,
        text("lift %4u  roll %+6.1f deg  pitch %+6.1f deg  yaw rate %+6.1f deg/s", s.lift, degrees(s.roll),
             degrees(s.pitch), degrees_per_s(s.yaw_rate)));
  } else {
    put(8, 10, "--", kDim);
  }
  const wire::Control& c = console.last_control();
  put(9, 0, "sending", 0, A_BOLD);
  put(9, 10, text("lift %4u  roll %+5d  pitch %+5d  yaw %+5d", c.lift, c.roll, c.pitch, c.yaw));
  const Sticks& trims = console.controls().trims();
  put(10, 0, "trims", 0, A_BOLD);
  put(10, 10, text("lift %4d  roll %+5d  pitch %+5d  yaw %+5d", trims.lift, trims.roll, trims.pitch, trims.yaw),
      trims == Sticks{} ? 0 : kWarning);

  const int js = 57;
  put(9, js, "joystick", 0, A_BOLD);
  switch (console.joystick_state()) {
    case JoystickState::none: put(9, js + 9, "none (keys)", kDim); break;
    case JoystickState::lost: put(9, js + 9, "LOST", kError, A_BOLD | A_REVERSE); break;
    case JoystickState::ok: {
      const bool neutral = console.controls().joystick() == Sticks{};
      put(9, js + 9,
          !console.joystick_position_known() ? "no position"
          : neutral                          ? "neutral"
                                             : "active",
          !console.joystick_position_known() ? kWarning : kInfo);
      break;
    }
  }
  const Sticks& j = console.controls().joystick();
  if (console.joystick_state() == JoystickState::ok)
    put(10, js, text("js %4d %+5d %+5d %+5d", j.lift, j.roll, j.pitch, j.yaw), kDim);

  // Gains as the QR reported them; '*' marks a value the QR has not confirmed (yet).
  put(11, 0, "gains", 0, A_BOLD);
  struct Gain {
    wire::ParamId id;
    const char* label;
  };
  constexpr Gain kGains[] = {{wire::ParamId::yaw_p, "yaw P"},
                             {wire::ParamId::roll_pitch_p1, "P1"},
                             {wire::ParamId::roll_pitch_p2, "P2"},
                             {wire::ParamId::attitude_c1, "C1"},
                             {wire::ParamId::attitude_c2, "C2"}};
  int column = 10;
  bool unconfirmed = false;
  for (const Gain& gain : kGains) {
    const wire::ParameterSpec& spec = *wire::find_parameter(static_cast<uint8_t>(gain.id));
    const int32_t wanted = console.params().get(gain.id);
    const std::optional<int32_t> in_force = console.reported(gain.id);
    const bool confirmed = in_force && *in_force == wanted;
    unconfirmed = unconfirmed || !confirmed;
    const std::string s = text("%s %s%s", gain.label, format_real(spec, wanted).c_str(), confirmed ? "" : "*");
    put(11, column, s, confirmed ? 0 : kWarning);
    column += static_cast<int>(s.size()) + 2;
  }
  if (unconfirmed) put(11, column, "*unconfirmed", kDim);

  const LinkFigures& f = console.link().figures();
  put(12, 0, "link", 0, A_BOLD);
  // Overruns (bytes the QR's receiver had no room for) only when there were any: the line has
  // room for the usual counts, and lost bytes are what must not go unseen.
  std::string uplink;
  if (t.qr_link && t.qr_link->rx_overruns != 0) {
    uplink = text("   QR rx %u ok, %u bad, %u overrun", t.qr_link->frames_ok, t.qr_link->check_failures,
                  t.qr_link->rx_overruns);
  } else if (t.qr_link) {
    uplink = text("   QR received %u ok, %u bad", t.qr_link->frames_ok, t.qr_link->check_failures);
  }
  put(12, 10,
      text("resent %u  no answer %u  telemetry lost %u%s", f.resends, f.gave_up, t.attitude_lost, uplink.c_str()));
  (void)width;
}

// The height estimate and whether height hold flies the lift.
void Cockpit::draw_height(const Console& console, int width) {
  const TelemetryModel& t = console.telemetry();
  put(13, 0, "height", 0, A_BOLD);
  if (!t.height) {
    put(13, 10, "-- m  climb -- m/s", kDim);
  } else if ((t.height->flags & wire::kHeightValid) == 0) {
    put(13, 10, "-- m  (no reference: calibrate)", kDim);  // ends before column 44
  } else {
    const bool sinking = console.sinking_m_s().has_value();
    put(13, 10, text("%+7.2f m  climb %+5.2f m/s", t.height->height_mm / 1000.0, t.height->climb_mm_s / 1000.0),
        sinking ? kError : 0, sinking ? A_BOLD : A_NORMAL);
  }
  const bool holding = t.attitude && t.attitude->mode == wire::Mode::height_hold;
  put(13, 44, holding ? " HEIGHT HOLD " : "height hold off (7)", holding ? kWarning : kDim,
      holding ? A_BOLD | A_REVERSE : A_NORMAL);
  (void)width;
}

// The hobbyist's hardware (docs/drivers.md), once the QR reports it: who flies and the radio's
// link as its CRSF link statistics say, and the engines' RPM from bidirectional DShot ESCs.
void Cockpit::draw_hardware(const Console& console, int width) {
  const TelemetryModel& t = console.telemetry();
  int column = 10;
  if (t.radio) {
    const wire::TelemetryRadio& r = *t.radio;
    const bool radio = radio_flies(t);
    const bool up = (r.flags & wire::kRadioLinkUp) != 0;
    put(14, 0, "radio", 0, A_BOLD);
    put(14, column, radio ? " RADIO FLIES " : "PC flies", radio ? kWarning : kDim,
        radio ? A_BOLD | A_REVERSE : A_NORMAL);
    column += 14;
    put(14, column, up ? "link up" : "LINK LOST", up ? kInfo : kError, up ? A_NORMAL : A_BOLD | A_REVERSE);
    column += 10;
    const std::string stats = text("arm %s  RSSI -%u dBm  LQ %u %%  SNR %+d dB  down LQ %u %%",
                                   (r.flags & wire::kRadioArmSwitch) != 0 ? "ON " : "off", r.uplink_rssi, r.uplink_lq,
                                   r.uplink_snr, r.downlink_lq);
    put(14, column, stats);
    column += static_cast<int>(stats.size()) + 3;
  }
  if (t.rpm) {
    const std::string rpm = text("rpm %u %u %u %u", t.rpm->rpm[0], t.rpm->rpm[1], t.rpm->rpm[2], t.rpm->rpm[3]);
    if (!t.radio) {
      put(14, 0, "engines", 0, A_BOLD);
    } else if (column + static_cast<int>(rpm.size()) > width) {
      return;  // a narrow terminal shows the radio, the pilot's concern
    }
    put(14, column, rpm, kDim);
  }
}

void Cockpit::draw_log(const Console& console, int top, int rows, int width) {
  // A plain '-' rule: line-drawing characters turn into letters in some terminals and captures.
  put(top - 1, 0, std::string(static_cast<size_t>(width), '-'), kDim);
  put(top - 1, 2, " log ", kDim);
  // Newest at the bottom; long lines wrap under their time stamp.
  constexpr int kStamp = 9;
  const int room = std::max(10, width - kStamp);
  int row = top + rows - 1;
  const auto& lines = console.log().lines();
  for (auto it = lines.rbegin(); it != lines.rend() && row >= top; ++it) {
    std::vector<std::string> pieces;
    const std::string shown = it->repeats > 0 ? it->text + text(" (x%u)", it->repeats + 1) : it->text;
    for (size_t at = 0; at < shown.size() || pieces.empty(); at += static_cast<size_t>(room)) {
      pieces.push_back(shown.substr(at, static_cast<size_t>(room)));
    }
    for (auto piece = pieces.rbegin(); piece != pieces.rend() && row >= top; ++piece, --row) {
      if (piece + 1 == pieces.rend()) put(row, 0, format_seconds(it->time_ms), kDim);
      put(row, kStamp, *piece, severity_color(it->severity), it->severity == Severity::error ? A_BOLD : A_NORMAL);
    }
  }
}

void Cockpit::draw_link_alarm(const Console& console, int width) {
  const LinkState state = console.link_state();
  if (state != alarmed_ && (state == LinkState::lost || state == LinkState::closed)) bell_ = true;
  alarmed_ = state;
  if (state != LinkState::lost && state != LinkState::closed) return;
  const int box = 40;
  const int left = (width - box) / 2;
  const std::string line2 = state == LinkState::closed ? "the serial line is gone"
                                                       : text("no valid frame for %.1f s",
                                                              console.link().silence_ms(console.now_ms()) / 1000.0);
  const std::string rows[] = {"", "L I N K   L O S T", line2, "x: exit", ""};
  for (int i = 0; i < 5; ++i) {
    std::string s = rows[i];
    const int pad = (box - static_cast<int>(s.size())) / 2;
    s = std::string(static_cast<size_t>(std::max(0, pad)), ' ') + s;
    s.resize(static_cast<size_t>(box), ' ');
    put(4 + i, left, s, kAlarm, A_BOLD);
  }
}

void Cockpit::draw_help(int rows, int width) {
  // Its rows come from the core (help_overlay.hpp), which a test reads at 80x24.
  const HelpOverlay overlay = help_overlay(rows, width);
  for (size_t r = 0; r < overlay.rows.size(); ++r) {
    put(overlay.top + static_cast<int>(r), overlay.left, overlay.rows[r], kTitle, r == 0 ? A_BOLD : A_NORMAL);
  }
}

void Cockpit::show() {
  if (bell_) beep();
  bell_ = false;
  doupdate();
  // On the screen now: how long since the QR's tick that took the newest sample.
  if (shown_sample_ms_ && *shown_sample_ms_ != measured_sample_ms_) {
    measured_sample_ms_ = *shown_sample_ms_;
    const int64_t age = static_cast<int64_t>(monotonic_ms()) - *shown_sample_ms_;
    if (age >= 0 && age < 10000) latencies_ms_.push_back(static_cast<uint32_t>(age));
  }
}

std::string Cockpit::latency_summary() const {
  if (latencies_ms_.empty()) return "";
  std::vector<uint32_t> sorted = latencies_ms_;
  std::sort(sorted.begin(), sorted.end());
  return text(
      "plot latency, tick to screen: median %u ms, 90th percentile %u ms over %zu screens (time_ms against "
      "qrsim's clock)",
      sorted[sorted.size() / 2], sorted[sorted.size() * 9 / 10], sorted.size());
}

// The newest time_ms sample of the plot as a time on the console's clock: its QR time (16 bits of
// ms) unwrapped near the simulator's clock now.
void Cockpit::note_plotted_sample(const Console& console) {
  shown_sample_ms_.reset();
  const std::optional<int64_t> offset = console.sim_clock_offset_ms();
  if (console.screen() != Screen::plot || !offset) return;
  for (const Trace& t : console.streams().plot().traces()) {
    if (t.name != "time_ms" || t.points.empty() || console.streams().plot().frozen()) continue;
    const int64_t qr_now = static_cast<int64_t>(console.now_ms()) - *offset;
    const int64_t sample = static_cast<int64_t>(std::llround(t.points.back().value));
    const int64_t behind = ((qr_now - sample) % 65536 + 65536) % 65536;
    shown_sample_ms_ = static_cast<int64_t>(console.now_ms()) - behind;
  }
}

void Cockpit::compose(const Console& console) {
  erase();
  const int rows = LINES;
  const int width = COLS;
  if (rows < kMinRows || width < kMinColumns) {
    put(0, 0, text("qrterm needs %dx%d, this terminal is %dx%d", kMinColumns, kMinRows, width, rows), kError, A_BOLD);
    const LinkState state = console.link_state();
    put(1, 0,
        text("mode %s, link %s; x exits",
             console.telemetry().attitude ? mode_name(console.telemetry().attitude->mode) : "?",
             link_state_name(state)),
        state == LinkState::up ? kInfo : kAlarm);
    draw_log(console, 3, std::max(0, rows - 3), width);
    wnoutrefresh(stdscr);
    return;
  }
  // The status rows live on every screen; Tab changes what is below them.
  draw_title(console, width);
  draw_mode_and_link(console, width);
  draw_system(console, width);
  if (console.screen() == Screen::plot) {
    draw_plot_screen(console, 4, rows - 4, width, braille_);
  } else if (console.screen() == Screen::parameters) {
    draw_parameter_screen(console, 4, rows - 4, width);
  } else if (console.screen() == Screen::motor_test) {
    const int below = draw_motor_test_screen(console, 4, width);
    draw_log(console, below, rows - below, width);
  } else if (console.screen() == Screen::radio) {
    draw_radio_screen(console, 4, rows - 4, width);
  } else if (console.screen() == Screen::orientation) {
    draw_orientation_screen(console, 4, rows - 4, width);
  } else {
    draw_engines_and_attitude(console, width);
    draw_pilot(console, width);
    draw_height(console, width);
    draw_hardware(console, width);
    draw_log(console, 16, rows - 16, width);
    // The simulator's truth, across the log's rule: beside the QR's estimate above it.
    if (!console.truth().empty()) put(15, 10, " " + console.truth() + " ", kInfo);
  }
  draw_link_alarm(console, width);
  if (console.help_visible()) draw_help(rows, width);
  note_plotted_sample(console);
  wnoutrefresh(stdscr);
}

}  // namespace qrterm
