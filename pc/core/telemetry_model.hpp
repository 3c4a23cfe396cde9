// The QR as the console last heard it: the latest of each telemetry group, what it says about
// lost telemetry, and when each group last arrived. The screen draws from it; the telemetry CSV
// writes it out.
#pragma once

#include <stdint.h>

#include <map>
#include <optional>

#include <common/log_records.hpp>
#include <common/telemetry.hpp>

namespace qrterm {

struct TelemetryModel {
  std::optional<wire::TelemetryAttitude> attitude;
  std::optional<wire::TelemetryRates> rates;
  std::optional<wire::TelemetryEngines> engines;
  std::optional<wire::TelemetrySetpoints> setpoints;
  std::optional<wire::TelemetrySystem> system;
  std::optional<wire::TelemetryLink> qr_link;    // the QR's receive counters: the uplink's health
  std::map<uint8_t, wire::TelemetryTask> tasks;  // cycle figures by task number, one task per telemetry period
  std::optional<wire::LogStatus> log_status;     // the QR's logs: on or off, lines, room
  std::optional<wire::TelemetryHeight> height;   // the height estimate
  std::optional<wire::TelemetryRadio> radio;     // the radio receiver's link and who flies
  std::optional<wire::TelemetryRpm> rpm;         // the engines' speeds, from bidirectional DShot ESCs

  uint32_t attitude_frames = 0;
  uint32_t attitude_lost = 0;  // from gaps in the attitude tick

  void on(const wire::TelemetryAttitude& message);
  void on(const wire::TelemetryRates& message) { rates = message; }
  void on(const wire::TelemetryEngines& message) { engines = message; }
  void on(const wire::TelemetrySetpoints& message) { setpoints = message; }
  void on(const wire::TelemetrySystem& message) { system = message; }
  void on(const wire::TelemetryLink& message) { qr_link = message; }
  void on(const wire::TelemetryTask& message) { tasks[message.task] = message; }
  void on(const wire::LogStatus& message) { log_status = message; }
  void on(const wire::TelemetryHeight& message) { height = message; }
  void on(const wire::TelemetryRadio& message) { radio = message; }
  void on(const wire::TelemetryRpm& message) { rpm = message; }

  bool flag(uint8_t bit) const { return attitude && (attitude->flags & bit) != 0; }
};

}  // namespace qrterm
