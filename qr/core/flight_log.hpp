// The QR's two logs (sensor and telemetry) over the board's log memory: start, stop, writing a
// line, and a download that sends the stored lines as log parts while the link has room. How
// often a line is written is the logger task's row (its rate is the log_divider parameter).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/log_records.hpp>
#include <common/messages.hpp>
#include <common/nack_reason.hpp>
#include <common/requests.hpp>
#include <qr/core/board.hpp>
#include <qr/core/log_repairs.hpp>
#include <qr/core/record_log.hpp>

namespace qr {

class FlightLog {
 public:
  // Both logs get the same number of lines, so they cover the same stretch of flight.
  void attach(LogArea area) {
    constexpr size_t kLineBytes = RecordLog<wire::SensorLogRecord>::kRecordBytes +
                                  RecordLog<wire::TelemetryLogRecord>::kRecordBytes;
    const size_t lines = area.data == nullptr ? 0 : area.size / kLineBytes;
    const size_t sensor_bytes = lines * RecordLog<wire::SensorLogRecord>::kRecordBytes;
    sensor_.attach(area.data, sensor_bytes);
    telemetry_.attach(area.data == nullptr ? nullptr : area.data + sensor_bytes,
                      lines * RecordLog<wire::TelemetryLogRecord>::kRecordBytes);
  }

  wire::NackReason start(uint8_t logs) {
    if (sensor_.capacity() == 0) return wire::NackReason::not_supported;  // no log memory
    downloading_ = false;
    repairs_.clear();
    full_ = false;
    if ((logs & wire::kLogSensor) != 0) {
      sensor_.clear();
      sensor_on_ = true;
    }
    if ((logs & wire::kLogTelemetry) != 0) {
      telemetry_.clear();
      telemetry_on_ = true;
    }
    return wire::NackReason::none;
  }
  wire::NackReason stop() {
    sensor_on_ = telemetry_on_ = false;
    return wire::NackReason::none;
  }
  wire::NackReason download(const wire::LogDownload& d) {
    if (logging()) return wire::NackReason::busy;
    const uint16_t lines = d.log == wire::LogKind::sensor ? sensor_.lines() : telemetry_.lines();
    if (d.first_line >= lines) return wire::NackReason::bad_value;
    const uint32_t end = d.count == 0 ? lines : uint32_t{d.first_line} + d.count;
    kind_ = d.log;
    next_line_ = d.first_line;
    end_line_ = static_cast<uint16_t>(end < lines ? end : lines);
    next_part_ = 0;
    downloading_ = true;
    return wire::NackReason::none;
  }

  // Parts asked for again: sent before the stream's next parts (log_repairs.hpp).
  wire::NackReason resend(const wire::LogResend& r) {
    if (logging()) return wire::NackReason::busy;
    if (r.first_line >= lines(r.log)) return wire::NackReason::bad_value;
    return repairs_.add(r) ? wire::NackReason::none : wire::NackReason::busy;
  }

  bool logging() const { return sensor_on_ || telemetry_on_; }
  void write(const wire::SensorLogRecord& s, const wire::TelemetryLogRecord& t) {
    if (sensor_on_ && !sensor_.append(s)) full_ = true;
    if (telemetry_on_ && !telemetry_.append(t)) full_ = true;
  }

  // Sends the next parts of a download while `send` accepts them (it returns false when the
  // link has no room), at most `max_parts` this call.
  template <class Send>
  void send_parts(uint8_t max_parts, Send&& send) {
    uint8_t n = 0;
    LogRepairs::Part repair{};
    const auto lines_of = [this](wire::LogKind log) { return lines(log); };
    for (; n < max_parts && repairs_.next(parts_per_line, lines_of, repair); ++n) {
      const wire::FrameBytes frame = repair.log == wire::LogKind::sensor
                                         ? wire::encode(sensor_.part(repair.line, repair.part))
                                         : wire::encode(telemetry_.part(repair.line, repair.part));
      if (!send(frame)) return;
      repairs_.sent();
    }
    for (; n < max_parts && downloading_; ++n) {
      const bool sensor = kind_ == wire::LogKind::sensor;
      const uint8_t parts = sensor ? wire::SensorLogRecord::kParts : wire::TelemetryLogRecord::kParts;
      const wire::FrameBytes frame = sensor ? wire::encode(sensor_.part(next_line_, next_part_))
                                            : wire::encode(telemetry_.part(next_line_, next_part_));
      if (!send(frame)) return;
      if (++next_part_ == parts) {
        next_part_ = 0;
        if (++next_line_ >= end_line_) downloading_ = false;
      }
    }
  }

  wire::LogStatus status() const {
    uint8_t flags = 0;
    if (sensor_on_) flags |= wire::kLogStatusSensorOn;
    if (telemetry_on_) flags |= wire::kLogStatusTelemetryOn;
    if (full_) flags |= wire::kLogStatusFull;
    return {flags, sensor_.lines(), telemetry_.lines(), sensor_.capacity()};
  }
  bool full() const { return full_; }
  // A part of a telemetry line as a download sends it: what a line that came whole must equal.
  wire::TelemetryLogPart telemetry_part(uint16_t line, uint8_t part) const { return telemetry_.part(line, part); }
  // A stream or parts asked for again are still to send.
  bool downloading() const { return downloading_ || !repairs_.empty(); }

 private:
  uint16_t lines(wire::LogKind log) const {
    return log == wire::LogKind::sensor ? sensor_.lines() : telemetry_.lines();
  }
  static uint8_t parts_per_line(wire::LogKind log) {
    return log == wire::LogKind::sensor ? wire::SensorLogRecord::kParts : wire::TelemetryLogRecord::kParts;
  }

  RecordLog<wire::SensorLogRecord> sensor_;
  RecordLog<wire::TelemetryLogRecord> telemetry_;
  bool sensor_on_ = false;
  bool telemetry_on_ = false;
  bool full_ = false;

  bool downloading_ = false;
  wire::LogKind kind_ = wire::LogKind::sensor;
  uint16_t next_line_ = 0;
  uint16_t end_line_ = 0;
  uint8_t next_part_ = 0;
  LogRepairs repairs_;
};

}  // namespace qr
