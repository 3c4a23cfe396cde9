#include <qr/sim_runner/soak.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <common/frame_parser.hpp>
#include <common/log_downloader.hpp>
#include <common/messages.hpp>
#include <common/mode.hpp>
#include <qr/sim_runner/pilot.hpp>
#include <qr/boards/sim/sim_qr.hpp>

namespace qrsim {
namespace {

constexpr double kHoverHeight = 1.5;
constexpr uint16_t kLogDivider = 1000;    // a log line a second at 1 kHz: the log's longest reach
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

enum class Phase : uint8_t { power_up, calibrate, arm, fly, relaunch, stop_log, download, done };

}  // namespace

bool run_soak(const SoakOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  sim::VehicleParams vehicle = sim::default_vehicle();
  vehicle.battery_capacity_mah *= kPackCapacityScale;
  auto qr = make_qr(vehicle, sim::WorldConfig{.seed = options.seed});
  sim::World& world = qr->world;
  Pilot pilot(qr->board);
  LineReferee referee;
  pilot.on_bytes_up([&](uint8_t b) { referee.byte(b, world.now_us()); });
  pilot.damage_line(
      LineFaults{options.byte_loss, static_cast<uint64_t>(options.garbage_every_s * 1e6), 64, options.seed * 7919 + 1});

  const uint64_t timeout_us = static_cast<uint64_t>(qr->firmware.parameters().get(wire::ParamId::link_timeout_ms)) *
                              1000;
  // The referee knows the tick a frame was read in; a tick either side of the timeout is the
  // only doubt (the order of the link task and the watchdog within one tick).
  constexpr uint64_t kSlackUs = 2 * qr::kPeriodUs;

  wire::LogDownloader<wire::TelemetryLogRecord> downloader;
  uint32_t log_lines_delivered = 0, log_gaps = 0, log_double = 0, log_altered = 0;
  bool have_previous_line = false;
  uint32_t previous_time_us = 0;
  uint16_t previous_line = 0;
  const auto on_line = [&](const wire::TelemetryLogRecord& r) {
    ++log_lines_delivered;
    for (uint8_t p = 0; p < wire::TelemetryLogRecord::kParts; ++p) {
      if (!(wire::make_log_part(r, p) == qr->firmware.log().telemetry_part(r.line, p))) {
        ++log_altered;
        const wire::TelemetryLogPart want = qr->firmware.log().telemetry_part(r.line, p);
        const wire::TelemetryLogPart got = wire::make_log_part(r, p);
        std::fprintf(stderr, "soak: log line %u part %u altered:", r.line, p);
        for (size_t i = 0; i < wire::kLogPartDataBytes; ++i)
          std::fprintf(stderr, " %02x/%02x", got.data[i], want.data[i]);
        std::fprintf(stderr, "\n");
        break;
      }
    }
    // Lines come in order on a clean pass; a re-request fills holes later, so judge the time
    // step only between neighbouring line numbers.
    if (have_previous_line && r.line == previous_line + 1 &&
        r.time_us - previous_time_us != kLogDivider * qr::kPeriodUs) {
      ++log_gaps;
    }
    if (have_previous_line && r.line == previous_line) ++log_double;
    have_previous_line = true;
    previous_line = r.line;
    previous_time_us = r.time_us;
  };
  pilot.on_every_frame([&](const wire::Frame& frame, const wire::LinkCounters& seen) {
    downloader.frame_accepted(seen.bytes_skipped + seen.check_failures, on_line);
    wire::TelemetryLogPart part;
    if (frame.type != wire::TelemetryLogPart::kType || !wire::decode(frame, part)) return;
    downloader.on_part(part, static_cast<uint32_t>(world.now_us() / 1000), on_line);
  });

  Phase phase = Phase::power_up;
  double phase_start = 0, flight_start = -1, download_start = 0, flown_s = 0;
  wire::Mode requested = wire::Mode::safe;
  wire::Mode last_mode = qr->firmware.mode();
  uint32_t link_loss_panics = 0, missed_link_losses = 0, unexplained = 0, relaunches = 0, outages = 0;
  bool silence_judged = false;
  double next_outage = options.outage_every_s, outage_end = -1;
  uint16_t log_lines = 0, log_capacity = 0;
  std::string failure;

  for (;;) {
    const uint64_t now_us = world.now_us();
    const double t = static_cast<double>(now_us) * 1e-6;
    const wire::Mode mode = qr->firmware.mode();
    const ConsoleView& view = pilot.view();
    const auto enter = [&](Phase next) {
      phase = next;
      phase_start = t;
    };
    const auto request = [&](wire::Mode m) {
      requested = m;
      pilot.request_mode(m);
    };

    // ---- the referee ----
    if (mode != last_mode) {
      const bool explained = mode == requested || (last_mode == wire::Mode::panic && mode == wire::Mode::safe) ||
                             (last_mode == wire::Mode::calibration && mode == wire::Mode::safe);
      if (mode == wire::Mode::panic && wire::flies(last_mode) && referee.silence_us(now_us) + kSlackUs >= timeout_us) {
        ++link_loss_panics;
        std::fprintf(stderr, "soak: at %.3f s a link-loss panic, the line silent %.0f ms (rule 7)\n", t,
                     static_cast<double>(referee.silence_us(now_us)) * 1e-3);
      } else if (!explained) {
        ++unexplained;
        std::fprintf(stderr, "soak: at %.3f s %s -> %s, not asked for (line silent %.0f ms)\n", t,
                     wire::mode_key(last_mode), wire::mode_key(mode),
                     static_cast<double>(referee.silence_us(now_us)) * 1e-3);
      }
      last_mode = mode;
    }
    const uint64_t silence = referee.silence_us(now_us);
    if (silence < timeout_us) silence_judged = false;
    if (!silence_judged && wire::flies(mode) && silence > timeout_us + kSlackUs) {
      silence_judged = true;
      ++missed_link_losses;
      std::fprintf(stderr, "soak: at %.3f s the line was silent %.0f ms and the QR flies on in %s\n", t,
                   static_cast<double>(silence) * 1e-3, wire::mode_key(mode));
    }

    // ---- the line's outages ----
    if (t >= next_outage && outage_end < 0) {
      pilot.go_silent(true);
      outage_end = t + options.outage_s;
      next_outage += options.outage_every_s;
      ++outages;
    }
    if (outage_end >= 0 && t >= outage_end) {
      pilot.go_silent(false);
      outage_end = -1;
    }

    // ---- the pilot ----
    const double flown = flight_start < 0 ? 0 : t - flight_start;
    const auto hover = [&](double ramp) {
      return scripted_sticks(t, lift_for_height(world.plant(), kHoverHeight, ramp));
    };
    switch (phase) {
      case Phase::power_up:
        if (t >= 0.3) {
          pilot.set_parameter(wire::ParamId::log_divider, kLogDivider);
          request(wire::Mode::calibration);
          enter(Phase::calibrate);
        }
        break;
      case Phase::calibrate:
        if (view.heard && (view.flags & wire::kFlagCalibrated) != 0 && mode == wire::Mode::safe &&
            !pilot.request_pending(wire::MessageType::param_set) &&
            !pilot.request_pending(wire::MessageType::mode_change)) {
          pilot.request(wire::LogStart{0, wire::kLogTelemetry});
          request(wire::Mode::full_control);
          enter(Phase::arm);
        }
        break;
      case Phase::arm:
      case Phase::relaunch:
        if (mode == wire::Mode::full_control) {
          if (flight_start < 0) flight_start = t;
          enter(Phase::fly);
        } else if (mode == wire::Mode::safe && phase == Phase::relaunch && t - phase_start > 1 &&
                   !pilot.request_pending(wire::MessageType::mode_change)) {
          request(wire::Mode::full_control);  // sticks neutral for a second: arm again
          phase_start = t;
        }
        break;
      case Phase::fly:
        if (mode != wire::Mode::full_control) {  // a link-loss panic: wait for safe, then arm again
          pilot.set_sticks({});
          if (mode == wire::Mode::safe) {
            ++relaunches;
            enter(Phase::relaunch);
          }
          break;
        }
        pilot.set_sticks(hover(t - phase_start));
        if (flown >= options.seconds) {
          flown_s = flown;
          pilot.request(wire::LogStop{});
          enter(Phase::stop_log);
        }
        break;
      case Phase::stop_log:
        pilot.set_sticks(mode == wire::Mode::full_control ? hover(1) : wire::Control{});
        if (!pilot.request_pending(wire::MessageType::log_stop)) {
          const wire::LogStatus status = qr->firmware.log().status();
          log_lines = status.telemetry_lines;
          log_capacity = status.capacity_lines;
          downloader.begin(log_lines);
          download_start = t;
          enter(Phase::download);
        }
        break;
      case Phase::download: {
        pilot.set_sticks(mode == wire::Mode::full_control ? hover(1) : wire::Control{});
        // As the console does (pc/core/log_downloader.cpp): the stream once, then the lost parts
        // by part while it goes on, one log_resend at a time.
        const uint32_t now_ms = static_cast<uint32_t>(now_us / 1000);
        uint16_t first = 0, count = 0;
        if (downloader.next_download(now_ms, first, count)) {
          pilot.request(wire::LogDownload{0, wire::LogKind::telemetry, first, count});
        }
        wire::LogResend resend;
        resend.log = wire::LogKind::telemetry;
        if (!pilot.request_pending(wire::MessageType::log_resend) && downloader.next_resend(now_ms, resend)) {
          pilot.request(resend);
        }
        if (downloader.done()) enter(Phase::done);
        if (t - download_start > kDownloadLimitS) {
          failure = "the log download did not finish";
          enter(Phase::done);
        }
        break;
      }
      case Phase::done: break;
    }
    if (phase == Phase::done) break;
    if (flight_start < 0 && t > kPreflightLimitS) {
      failure = "preflight did not finish";
      break;
    }
    pilot.step();
    if (!qr->tick()) {
      failure = "the firmware stopped";
      break;
    }
  }

  const double sim_seconds = static_cast<double>(world.now_us()) * 1e-6;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const uint32_t deadline_misses = qr->scheduler.stats().deadline_misses;
  const LineFaultCounts& line = pilot.line_counts();
  const uint32_t log_lost = log_lines - downloader.received();
  const bool pass = failure.empty() && deadline_misses == 0 && unexplained == 0 && missed_link_losses == 0 &&
                    log_lost == 0 && log_gaps == 0 && log_double == 0 && log_altered == 0 && log_lines > 0;
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
      sim_seconds, flown_s, static_cast<unsigned long long>(options.seed), wall, sim_seconds / wall, options.byte_loss,
      static_cast<unsigned long long>(line.bytes_up), static_cast<unsigned long long>(line.bytes_up_lost),
      static_cast<unsigned long long>(line.bytes_down), static_cast<unsigned long long>(line.bytes_down_lost),
      static_cast<unsigned long long>(line.garbage_bursts), static_cast<unsigned long long>(line.garbage_bytes),
      outages, options.outage_s * 1e3, static_cast<unsigned long long>(timeout_us / 1000), deadline_misses,
      link_loss_panics, missed_link_losses, unexplained, relaunches, pilot.view().requests_given_up, kLogDivider,
      log_lines, log_capacity, downloader.received(), log_lost, log_altered, log_gaps, downloader.rerequests(),
      phase == Phase::done ? sim_seconds - download_start : 0.0, failure.empty() ? "" : "\"",
      failure.empty() ? "null" : failure.c_str(), failure.empty() ? "" : "\"", pass ? "true" : "false");
  return pass;
}

}  // namespace qrsim
