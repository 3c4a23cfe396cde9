#include <qr/sim_runner/soak.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <common/frame_parser.hpp>
#include <common/log_downloader.hpp>
#include <common/messages.hpp>
#include <common/mode.hpp>
#include <qr/boards/sim/sim_qr.hpp>
#include <qr/sim_runner/pilot.hpp>
#include <qr/sim_runner/preflight.hpp>

namespace qrsim {
namespace {

constexpr double kHoverHeight = 1.5;
constexpr uint16_t kLogDivider = 1000;  // a log line a second at 1 kHz: the log's longest reach
// The log is stopped after this much flight: 1,800 lines to download over the damaged line (the
// packed log would hold the hour, 3,600 lines, and double the download's simulated 950 s).
constexpr double kLogFlightS = 1800;
constexpr double kDownloadLimitS = 3600;  // over a line that loses 5 % of bytes a log takes long (section 9)
constexpr double kPreflightLimitS = 30;
// The simulated pack hovers about 12 minutes; the soak is of the software, not of the pack, so
// its vehicle carries one that lasts the hour and the download (same mass, same voltage curve).
constexpr double kPackCapacityScale = 8;

// The pilot's script: a slow round of small roll and pitch steps, a yaw now and then, so every
// loop works all hour. Stick units (full stick 1000).
wire::Control scripted_sticks(double t, uint16_t lift) {
  static constexpr int16_t kRound[][2] = {{120, 0}, {0, 120}, {-120, 0}, {0, -120}, {0, 0}};
  const auto step = static_cast<size_t>(std::fmod(t / 2.0, 5.0));
  const int16_t yaw = std::fmod(t, 10.0) < 1.0 ? int16_t{150} : int16_t{0};
  return {lift, kRound[step][0], kRound[step][1], yaw};
}

// What the QR reads: every byte that went up the line after the damage, cut into frames by a
// parser like the firmware's; a frame that decodes with its fields in range is life (rule 7).
// The line is mirrored (one byte every 86.8 µs after the one before, serial_line.hpp), so the
// referee knows the tick that read each frame's last byte: the QR's own clock of life.
class LineReferee {
 public:
  void byte(uint8_t b, uint64_t now_us) {
    line_free_ns_ = std::max(line_free_ns_, now_us * 1000) + kByteTimeNs;
    parser_.push(b, [&](const wire::Frame& frame) {
      struct Nothing {};
      Nothing handler;
      if (wire::dispatch(frame, handler) == wire::DispatchResult::invalid_payload) return;
      const uint64_t period_ns = uint64_t{qr::kPeriodUs} * 1000;
      last_life_us_ = (line_free_ns_ + period_ns - 1) / period_ns * qr::kPeriodUs;  // the tick that reads it
    });
  }
  // Silence as the QR sees it at tick `now_us`: since the tick that read the last good frame.
  uint64_t silence_us(uint64_t now_us) const { return now_us > last_life_us_ ? now_us - last_life_us_ : 0; }

 private:
  wire::FrameParser parser_{wire::Listen::pc_to_qr};
  uint64_t line_free_ns_ = 0;
  uint64_t last_life_us_ = 0;
};

// What the soak's pilot does, one phase after the other; a link-loss panic in flight sends it
// back to safe, from where the pilot arms again (relaunch).
enum class Phase : uint8_t { preflight, fly, relaunch, stop_log, download, done };

// The soak's pre-flight: the log's divider goes up, calibration asked with it, and the telemetry
// log starts as the pilot arms, so that the log holds the whole flight.
PreflightPlan soak_preflight() {
  PreflightPlan plan;
  plan.parameters = {{wire::ParamId::log_divider, kLogDivider}};
  plan.calibrate_with_upload = true;
  plan.log_from_arming = true;
  return plan;
}

// The downloaded log's lines against the firmware's own: each line whole, none twice, and the
// time between neighbouring lines one log period.
class LogCheck {
 public:
  void line(const wire::TelemetryLogRecord& r, const SimQr& qr) {
    if (!whole(r, qr)) ++altered;
    // Lines come in order on a clean pass; a re-request fills holes later, so judge the time
    // step only between neighbouring line numbers.
    if (have_previous_ && r.line == previous_line_ + 1 &&
        r.time_us - previous_time_us_ != kLogDivider * qr::kPeriodUs) {
      ++gaps;
    }
    if (have_previous_ && r.line == previous_line_) ++doubled;
    have_previous_ = true;
    previous_line_ = r.line;
    previous_time_us_ = r.time_us;
  }

  uint32_t gaps = 0, doubled = 0, altered = 0;

 private:
  // False, and the first part that differs said byte by byte on stderr, when the line came
  // otherwise than the firmware wrote it.
  static bool whole(const wire::TelemetryLogRecord& r, const SimQr& qr) {
    for (uint8_t p = 0; p < wire::TelemetryLogRecord::kParts; ++p) {
      if (wire::make_log_part(r, p) == qr.firmware.log().telemetry_part(r.line, p)) continue;
      const wire::TelemetryLogPart want = qr.firmware.log().telemetry_part(r.line, p);
      const wire::TelemetryLogPart got = wire::make_log_part(r, p);
      std::fprintf(stderr, "soak: log line %u part %u altered:", r.line, p);
      for (size_t i = 0; i < wire::kLogPartDataBytes; ++i)
        std::fprintf(stderr, " %02x/%02x", got.data[i], want.data[i]);
      std::fprintf(stderr, "\n");
      return false;
    }
    return true;
  }

  bool have_previous_ = false;
  uint32_t previous_time_us_ = 0;
  uint16_t previous_line_ = 0;
};

// Every mode change the firmware makes, judged: one the pilot asked for, a panic's or a
// calibration's return to safe, or a link-loss panic when the line has been silent for the
// link timeout (rule 7); and a line silent past the timeout must not find the QR still flying.
class ModeReferee {
 public:
  ModeReferee(wire::Mode first, uint64_t timeout_us) : last_mode_(first), timeout_us_(timeout_us) {}

  void judge(double t, uint64_t now_us, wire::Mode mode, const LineReferee& line) {
    if (mode != last_mode_) judge_change(t, now_us, mode, line);
    const uint64_t silence = line.silence_us(now_us);
    if (silence < timeout_us_) silence_judged_ = false;
    if (!silence_judged_ && wire::flies(mode) && silence > timeout_us_ + kSlackUs) {
      silence_judged_ = true;
      ++missed_link_losses;
      std::fprintf(stderr, "soak: at %.3f s the line was silent %.0f ms and the QR flies on in %s\n", t,
                   static_cast<double>(silence) * 1e-3, wire::mode_key(mode));
    }
  }

  wire::Mode requested = wire::Mode::safe;  // the last mode the pilot asked for
  uint32_t link_loss_panics = 0, missed_link_losses = 0, unexplained = 0;

 private:
  // The referee knows the tick a frame was read in; a tick either side of the timeout is the
  // only doubt (the order of the link task and the watchdog within one tick).
  static constexpr uint64_t kSlackUs = 2 * qr::kPeriodUs;

  void judge_change(double t, uint64_t now_us, wire::Mode mode, const LineReferee& line) {
    const bool explained = mode == requested || (last_mode_ == wire::Mode::panic && mode == wire::Mode::safe) ||
                           (last_mode_ == wire::Mode::calibration && mode == wire::Mode::safe);
    if (mode == wire::Mode::panic && wire::flies(last_mode_) && line.silence_us(now_us) + kSlackUs >= timeout_us_) {
      ++link_loss_panics;
      std::fprintf(stderr, "soak: at %.3f s a link-loss panic, the line silent %.0f ms (rule 7)\n", t,
                   static_cast<double>(line.silence_us(now_us)) * 1e-3);
    } else if (!explained) {
      ++unexplained;
      std::fprintf(stderr, "soak: at %.3f s %s -> %s, not asked for (line silent %.0f ms)\n", t,
                   wire::mode_key(last_mode_), wire::mode_key(mode),
                   static_cast<double>(line.silence_us(now_us)) * 1e-3);
    }
    last_mode_ = mode;
  }

  wire::Mode last_mode_;
  const uint64_t timeout_us_;
  bool silence_judged_ = false;
};

// The line's outages: silent for outage_s every outage_every_s, shorter than the link timeout.
class Outages {
 public:
  explicit Outages(const SoakOptions& options) : options_(options), next_(options.outage_every_s) {}

  void step(double t, Pilot& pilot) {
    if (t >= next_ && end_ < 0) {
      pilot.go_silent(true);
      end_ = t + options_.outage_s;
      next_ += options_.outage_every_s;
      ++count;
    }
    if (end_ >= 0 && t >= end_) {
      pilot.go_silent(false);
      end_ = -1;
    }
  }

  uint32_t count = 0;

 private:
  const SoakOptions& options_;
  double next_;
  double end_ = -1;
};

// The simulated pack hovers about 12 minutes; the soak is of the software, not of the pack.
sim::VehicleParams soak_vehicle() {
  sim::VehicleParams vehicle = sim::default_vehicle();
  vehicle.battery_capacity_mah *= kPackCapacityScale;
  return vehicle;
}

// One soak as it flies: the QR, the pilot on the damaged line, the referees beside it, where the
// pilot is in the flight and what came of the log.
class Soak {
 public:
  explicit Soak(const SoakOptions& options);
  Soak(const Soak&) = delete;  // the pilot's callbacks hold this
  Soak& operator=(const Soak&) = delete;

  // Control period after control period until the log is downloaded or the soak fails.
  void fly();
  // The figures as one JSON line; true when the soak passed.
  bool report() const;

 private:
  void fly_pilot(double t, uint64_t now_us, wire::Mode mode);
  void fly_hour(double t, wire::Mode mode);
  void relaunch(double t, wire::Mode mode);
  void stop_log(double t, wire::Mode mode);
  void download(double t, uint64_t now_us, wire::Mode mode);
  void enter(Phase next, double t);
  // The scripted sticks at the hover height, the thumb's ramp `ramp` of the way up.
  wire::Control hover(double t, double ramp) const {
    return scripted_sticks(t, lift_for_height(world_.plant(), kHoverHeight, ramp));
  }

  const SoakOptions& options_;
  const std::chrono::steady_clock::time_point wall_start_ = std::chrono::steady_clock::now();
  const sim::VehicleParams vehicle_ = soak_vehicle();
  const std::unique_ptr<SimQr> qr_;
  sim::World& world_;
  Pilot pilot_;
  LineReferee line_;
  const uint64_t timeout_us_;
  wire::LogDownloader<wire::TelemetryLogRecord> downloader_;
  LogCheck log_;
  Preflight preflight_{soak_preflight()};
  ModeReferee modes_;
  Outages outages_;
  Phase phase_ = Phase::preflight;
  double phase_start_ = 0, flight_start_ = -1, download_start_ = 0, flown_s_ = 0;
  bool log_stopped_ = false;  // after kLogFlightS of flight
  uint32_t relaunches_ = 0;
  uint16_t log_lines_ = 0, log_capacity_ = 0;  // as the firmware's log status said when it stopped
  std::string failure_;
};

Soak::Soak(const SoakOptions& options)
    : options_(options), qr_(make_qr(vehicle_, sim::WorldConfig{.seed = options.seed})), world_(qr_->world),
      pilot_(qr_->board),
      timeout_us_(static_cast<uint64_t>(qr_->firmware.parameters().get(wire::ParamId::link_timeout_ms)) * 1000),
      modes_(qr_->firmware.mode(), timeout_us_), outages_(options) {
  pilot_.on_bytes_up([this](uint8_t b) { line_.byte(b, world_.now_us()); });
  pilot_.damage_line(
      LineFaults{options.byte_loss, static_cast<uint64_t>(options.garbage_every_s * 1e6), 64, options.seed * 7919 + 1});
  pilot_.on_every_frame([this](const wire::Frame& frame, const wire::LinkCounters& seen) {
    const auto on_line = [this](const wire::TelemetryLogRecord& r) { log_.line(r, *qr_); };
    downloader_.frame_accepted(seen.bytes_skipped + seen.check_failures, on_line);
    wire::TelemetryLogPart part;
    if (frame.type != wire::TelemetryLogPart::kType || !wire::decode(frame, part)) return;
    downloader_.on_part(part, static_cast<uint32_t>(world_.now_us() / 1000), on_line);
  });
}

void Soak::fly() {
  for (;;) {
    const uint64_t now_us = world_.now_us();
    const double t = static_cast<double>(now_us) * 1e-6;
    const wire::Mode mode = qr_->firmware.mode();
    modes_.judge(t, now_us, mode, line_);
    if (modes_.unexplained > 0) {
      // The soak has failed: flying on, its pilot may never get back to full control, and the
      // run then ends only at CTest's timeout, without its figures.
      failure_ = "a mode change nobody asked for (above): the soak ends there";
      break;
    }
    outages_.step(t, pilot_);
    fly_pilot(t, now_us, mode);
    if (phase_ == Phase::done) break;
    if (phase_ == Phase::preflight && t > kPreflightLimitS) {
      failure_ = "preflight did not finish";
      break;
    }
    pilot_.step();
    if (!qr_->tick()) {
      failure_ = "the firmware stopped";
      break;
    }
  }
}

void Soak::fly_pilot(double t, uint64_t now_us, wire::Mode mode) {
  switch (phase_) {
    case Phase::preflight: {
      const bool ready = preflight_.step(t, mode, pilot_);
      modes_.requested = preflight_.requested();
      if (ready) {
        flight_start_ = t;
        enter(Phase::fly, t);
      }
      break;
    }
    case Phase::fly: fly_hour(t, mode); break;
    case Phase::relaunch: relaunch(t, mode); break;
    case Phase::stop_log: stop_log(t, mode); break;
    case Phase::download: download(t, now_us, mode); break;
    case Phase::done: break;
  }
}

void Soak::enter(Phase next, double t) {
  phase_ = next;
  phase_start_ = t;
}

// The scripted round in full control until the hour is flown, then the log stops.
void Soak::fly_hour(double t, wire::Mode mode) {
  if (mode != wire::Mode::full_control) {  // a link-loss panic: wait for safe, then arm again
    pilot_.set_sticks({});
    if (mode == wire::Mode::safe) {
      ++relaunches_;
      enter(Phase::relaunch, t);
    }
    return;
  }
  pilot_.set_sticks(hover(t, t - phase_start_));
  const double flown = t - flight_start_;
  if (flown >= kLogFlightS && !log_stopped_) {
    pilot_.request(wire::LogStop{});
    log_stopped_ = true;
  }
  if (flown >= options_.seconds) {
    flown_s_ = flown;
    pilot_.request(wire::LogStop{});
    enter(Phase::stop_log, t);
  }
}

// Back in safe after a panic: sticks neutral for a second, then arm again, until full control.
void Soak::relaunch(double t, wire::Mode mode) {
  if (mode == wire::Mode::full_control) {
    enter(Phase::fly, t);
  } else if (mode == wire::Mode::safe && t - phase_start_ > 1 &&
             !pilot_.request_pending(wire::MessageType::mode_change)) {
    modes_.requested = wire::Mode::full_control;
    pilot_.request_mode(wire::Mode::full_control);
    phase_start_ = t;
  }
}

// Hovering on until the log stop is acked; then the download of as many lines as the log holds.
void Soak::stop_log(double t, wire::Mode mode) {
  pilot_.set_sticks(mode == wire::Mode::full_control ? hover(t, 1) : wire::Control{});
  if (pilot_.request_pending(wire::MessageType::log_stop)) return;
  const wire::LogStatus status = qr_->firmware.log().status();
  log_lines_ = status.telemetry_lines;
  log_capacity_ = status.capacity_lines;
  downloader_.begin(log_lines_);
  download_start_ = t;
  enter(Phase::download, t);
}

// As the console does (pc/core/log_downloader.cpp): the stream once, then the lost parts by part
// while it goes on, one log_resend at a time.
void Soak::download(double t, uint64_t now_us, wire::Mode mode) {
  pilot_.set_sticks(mode == wire::Mode::full_control ? hover(t, 1) : wire::Control{});
  const uint32_t now_ms = static_cast<uint32_t>(now_us / 1000);
  uint16_t first = 0, count = 0;
  if (downloader_.next_download(now_ms, first, count)) {
    pilot_.request(wire::LogDownload{0, wire::LogKind::telemetry, first, count});
  }
  wire::LogResend resend;
  resend.log = wire::LogKind::telemetry;
  if (!pilot_.request_pending(wire::MessageType::log_resend) && downloader_.next_resend(now_ms, resend)) {
    pilot_.request(resend);
  }
  if (downloader_.done()) enter(Phase::done, t);
  if (t - download_start_ > kDownloadLimitS) {
    failure_ = "the log download did not finish";
    enter(Phase::done, t);
  }
}

bool Soak::report() const {
  const double sim_seconds = static_cast<double>(world_.now_us()) * 1e-6;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
  const uint32_t deadline_misses = qr_->scheduler.stats().deadline_misses;
  const LineFaultCounts& line = pilot_.line_counts();
  const uint32_t log_lost = log_lines_ - downloader_.received();
  const bool pass = failure_.empty() && deadline_misses == 0 && modes_.unexplained == 0 &&
                    modes_.missed_link_losses == 0 && log_lost == 0 && log_.gaps == 0 && log_.doubled == 0 &&
                    log_.altered == 0 && log_lines_ > 0;
  std::printf(
      "{\"soak\": %.3f, \"flown_seconds\": %.3f, \"seed\": %llu, \"wall_seconds\": %.2f, \"speedup\": %.1f, "
      "\"byte_loss\": %g, \"bytes_up\": %llu, \"bytes_up_lost\": %llu, \"bytes_down\": %llu, \"bytes_down_lost\": "
      "%llu, "
      "\"garbage_bursts\": %llu, \"garbage_bytes\": %llu, \"outages\": %u, \"outage_ms\": %.0f, \"link_timeout_ms\": "
      "%llu, "
      "\"deadline_misses\": %u, \"link_loss_panics\": %u, \"missed_link_losses\": %u, \"unexplained_mode_changes\": "
      "%u, "
      "\"relaunches\": %u, \"requests_given_up\": %u, \"log_divider\": %u, \"log_lines\": %u, \"log_capacity\": %u, "
      "\"log_lines_downloaded\": %u, \"log_lines_lost\": %u, \"log_lines_altered\": %u, \"log_time_gaps\": %u, "
      "\"log_rerequests\": %u, "
      "\"download_seconds\": %.1f, \"error\": %s%s%s, \"pass\": %s}\n",
      sim_seconds, flown_s_, static_cast<unsigned long long>(options_.seed), wall, sim_seconds / wall,
      options_.byte_loss, static_cast<unsigned long long>(line.bytes_up),
      static_cast<unsigned long long>(line.bytes_up_lost), static_cast<unsigned long long>(line.bytes_down),
      static_cast<unsigned long long>(line.bytes_down_lost), static_cast<unsigned long long>(line.garbage_bursts),
      static_cast<unsigned long long>(line.garbage_bytes), outages_.count, options_.outage_s * 1e3,
      static_cast<unsigned long long>(timeout_us_ / 1000), deadline_misses, modes_.link_loss_panics,
      modes_.missed_link_losses, modes_.unexplained, relaunches_, pilot_.view().requests_given_up, kLogDivider,
      log_lines_, log_capacity_, downloader_.received(), log_lost, log_.altered, log_.gaps, downloader_.rerequests(),
      phase_ == Phase::done ? sim_seconds - download_start_ : 0.0, failure_.empty() ? "" : "\"",
      failure_.empty() ? "null" : failure_.c_str(), failure_.empty() ? "" : "\"", pass ? "true" : "false");
  return pass;
}

}  // namespace

bool run_soak(const SoakOptions& options) {
  Soak soak(options);
  soak.fly();
  return soak.report();
}

}  // namespace qrsim
