#include <pc/core/log_room.hpp>

#include <algorithm>
#include <cstdio>

namespace qrterm {
namespace {

uint32_t lines_kept(const wire::LogStatus& status) { return std::max(status.sensor_lines, status.telemetry_lines); }

bool past_warning(const wire::LogStatus& status) {
  return status.capacity_lines > 0 && lines_kept(status) * 100u >= status.capacity_lines * kLogWarnPercent;
}

}  // namespace

double log_seconds(uint32_t lines, uint32_t divider, uint32_t control_hz) {
  return control_hz == 0 ? 0.0 : static_cast<double>(lines) * divider / control_hz;
}

std::string log_room_text(const wire::LogStatus& status, uint32_t divider, uint32_t control_hz) {
  const double seconds = log_seconds(status.capacity_lines, divider, control_hz);
  char text[200];
  std::snprintf(text, sizeof text, "room for %u lines: %.0f s at log_divider %u (%.0f lines/s)",
                static_cast<unsigned>(status.capacity_lines), seconds, static_cast<unsigned>(divider),
                divider == 0 ? 0.0 : static_cast<double>(control_hz) / divider);
  std::string said = text;
  if (seconds < kUsefulFlightS && status.capacity_lines > 0) {
    const uint32_t useful = (kUsefulFlightS * control_hz + status.capacity_lines - 1) / status.capacity_lines;
    said += "; log_divider " + std::to_string(useful) + " logs " + std::to_string(kUsefulFlightS) +
            " s (parameter screen)";
  }
  return said;
}

std::string log_filling_warning(const wire::LogStatus& before, const wire::LogStatus& now, uint32_t divider,
                                uint32_t control_hz) {
  if (!past_warning(now) || past_warning(before) || (now.flags & wire::kLogStatusFull) != 0) return "";
  const uint32_t left = now.capacity_lines - std::min<uint32_t>(lines_kept(now), now.capacity_lines);
  char text[200];
  std::snprintf(text, sizeof text,
                "QR log %u %% full: about %.0f s left at log_divider %u, then it keeps its first lines "
                "(t stops, g downloads; a larger log_divider logs longer)",
                static_cast<unsigned>(lines_kept(now) * 100u / now.capacity_lines),
                log_seconds(left, divider, control_hz), static_cast<unsigned>(divider));
  return text;
}

std::string log_restart_warning(const wire::LogStatus& status, uint32_t divider, uint32_t control_hz) {
  if (lines_kept(status) == 0) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                "the QR's log holds %u lines (%.0f s): s again within %u s starts a new log without them "
                "(t stops, g downloads)",
                static_cast<unsigned>(lines_kept(status)), log_seconds(status.sensor_lines, divider, control_hz),
                static_cast<unsigned>(kLogRestartConfirmMs / 1000));
  return text;
}

}  // namespace qrterm
