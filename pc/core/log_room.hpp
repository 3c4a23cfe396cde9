// How long the QR's logs last, and what a new start would drop. The boards' 256 KiB hold about
// 12,000 packed lines at the default log_divider of 10 (2 minutes; docs/protocol.md section 8). A
// newcomer found the log full without a word before it: the console says the room at the start and
// warns before it fills. A start empties the QR's log, so one that holds lines asks first.
#pragma once

#include <stdint.h>

#include <string>

#include <common/log_records.hpp>

namespace qrterm {

// The share of the room past which the console warns that the log is about to fill.
inline constexpr uint32_t kLogWarnPercent = 50;
// A flight worth logging: the divider that gives this long is offered when the room is shorter.
inline constexpr uint32_t kUsefulFlightS = 60;

// Seconds of logging `lines` take at a log line every `divider` control periods.
double log_seconds(uint32_t lines, uint32_t divider, uint32_t control_hz);

// "room for 1820 lines: 18 s at log_divider 10 (100 lines/s); log_divider 33 logs 60 s (parameter
// screen)"
std::string log_room_text(const wire::LogStatus& status, uint32_t divider, uint32_t control_hz);

// The warning to give when this status report crosses kLogWarnPercent (empty otherwise):
// "QR log 50 % full: about 9 s left at log_divider 10, ..."
std::string log_filling_warning(const wire::LogStatus& before, const wire::LogStatus& now, uint32_t divider,
                                uint32_t control_hz);

// A log start empties the QR's log: when it holds lines, s asks to be pressed again within this.
inline constexpr uint32_t kLogRestartConfirmMs = 3000;

// What a log start would drop (empty when the log holds no line): "the QR's log holds 2403 lines
// (24 s): s again within 3 s starts a new log without them (t stops, g downloads)"
std::string log_restart_warning(const wire::LogStatus& status, uint32_t divider, uint32_t control_hz);

}  // namespace qrterm
