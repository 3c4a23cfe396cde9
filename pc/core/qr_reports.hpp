// What the pilot is told when the QR's reports change: a new mode, calibrated, battery low, its
// logs filling up or full. Said once, when the change comes, not at every report.
#pragma once

#include <stdint.h>

#include <optional>
#include <string>
#include <vector>

#include <common/log_records.hpp>
#include <common/telemetry.hpp>
#include <pc/core/console_log.hpp>

namespace qrterm {

// `before`: the last attitude report (empty: this is the first). `panic_asked_by`: who asked for
// the panic the QR may now be in, in the pilot's words ("the pilot (key 0, ...)",
// PilotRequests::panic_asked_by), or empty: the QR's debug text says its own cause ("mode: panic
// (requested)"), which names no key.
std::vector<Notice> attitude_notices(const std::optional<wire::TelemetryAttitude>& before,
                                     const wire::TelemetryAttitude& now, const std::string& panic_asked_by = {});

// With the log_divider the console holds and the QR's control rate, for the time left.
std::vector<Notice> log_status_notices(const std::optional<wire::LogStatus>& before, const wire::LogStatus& now,
                                       uint32_t log_divider, uint32_t control_hz);

}  // namespace qrterm
