#include <pc/core/qr_reports.hpp>

#include <string>

#include <pc/core/log_room.hpp>
#include <pc/core/mode_names.hpp>

namespace qrterm {

std::vector<Notice> attitude_notices(const std::optional<wire::TelemetryAttitude>& before,
                                     const wire::TelemetryAttitude& now, const std::string& panic_asked_by) {
  std::vector<Notice> notices;
  if (!before || before->mode != now.mode) {
    const bool panic = now.mode == wire::Mode::panic;
    notices.push_back({panic ? Severity::warning : Severity::info,
                       std::string("QR mode: ") + mode_name(now.mode) +
                           (panic && !panic_asked_by.empty() ? ": asked by " + panic_asked_by : "")});
  }
  const auto rose = [&](uint8_t bit) { return (now.flags & bit) != 0 && (!before || (before->flags & bit) == 0); };
  if (rose(wire::kFlagCalibrated)) notices.push_back({Severity::info, "QR calibrated"});
  if (rose(wire::kFlagBatteryWarning)) notices.push_back({Severity::warning, "QR battery low"});
  return notices;
}

std::vector<Notice> log_status_notices(const std::optional<wire::LogStatus>& before, const wire::LogStatus& now,
                                       uint32_t log_divider, uint32_t control_hz) {
  std::vector<Notice> notices;
  const std::string filling = log_filling_warning(before.value_or(wire::LogStatus{}), now, log_divider, control_hz);
  if (!filling.empty()) notices.push_back({Severity::warning, filling});
  const bool was_full = before && (before->flags & wire::kLogStatusFull) != 0;
  if ((now.flags & wire::kLogStatusFull) != 0 && !was_full) {
    notices.push_back({Severity::warning,
                       "QR log full (" + std::to_string(now.capacity_lines) + " lines): it keeps its first lines"});
  }
  return notices;
}

}  // namespace qrterm
