// The QR's two logs (sensor and telemetry) packed together in the board's log memory
// (log_pack/packed_log.hpp): start, stop, writing a line, and a download that unpacks the stored
// lines and sends them as log parts while the link has room, so the wire and the console see the
// same flat lines as ever. How often a line is written is the logger task's row (its rate is the
// log_divider parameter); the telemetry record comes with the lines at most kTelemetryHz times a
// second (it is most of a packed line's bits, and 100 Hz is what a plot of a flight needs).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/log_records.hpp>
#include <common/messages.hpp>
#include <common/nack_reason.hpp>
#include <common/requests.hpp>
#include <qr/core/board.hpp>
#include <qr/core/log_filter_model.hpp>
#include <qr/core/log_pack/packed_log.hpp>
#include <qr/core/log_repairs.hpp>

namespace qr {

template <class Chain>
class FlightLog {
 public:
  using Model = ChainFilterModel<Chain>;
  // Lines unpacked at most per call of send_parts(): a seek to a part asked for again spreads over
  // ticks (about 1,500 RV32 instructions a line).
  static constexpr uint16_t kUnpackLinesPerCall = 8;
  // What the keyframes' index takes of the board's log area (log_pack/packed_log.hpp).
  static constexpr size_t kIndexBytes = log_pack::PackedLog<Model>::kIndexBytes;

  void attach(LogArea area) { packed_.attach(area.data, area.size); }

  static constexpr uint32_t kTelemetryHz = 100;

  // `lines_hz`: the rate the logger writes lines at (the control rate over log_divider).
  wire::NackReason start(uint8_t logs, uint32_t lines_hz) {
    if (packed_.bytes() == 0) return wire::NackReason::not_supported;  // no log memory
    downloading_ = false;
    repairs_.clear();
    stream_.forget();
    repair_.forget();
    const bool sensor = (logs & wire::kLogSensor) != 0;
    const uint32_t every = sensor && lines_hz > kTelemetryHz ? lines_hz / kTelemetryHz : 1u;
    packed_.clear({sensor, (logs & wire::kLogTelemetry) != 0, static_cast<uint16_t>(every)});
    logging_ = true;
    return wire::NackReason::none;
  }
  wire::NackReason stop() {
    logging_ = false;
    return wire::NackReason::none;
  }
  wire::NackReason download(const wire::LogDownload& d) {
    if (logging()) return wire::NackReason::busy;
    const uint16_t lines = lines_of(d.log);
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
    if (r.first_line >= lines_of(r.log)) return wire::NackReason::bad_value;
    return repairs_.add(r) ? wire::NackReason::none : wire::NackReason::busy;
  }

  bool logging() const { return logging_; }
  void write(const wire::SensorLogRecord& s, const wire::TelemetryLogRecord& t, const Chain& chain) {
    if (!logging_ || packed_.full()) return;
    packed_.append({s, t, false}, [&chain](Model& m) { m.take(chain); });
  }

  // Sends the next parts of a download while `send` accepts them (it returns false when the
  // link has no room), at most `max_parts` this call; a line still being unpacked waits.
  template <class Send>
  void send_parts(uint8_t max_parts, Send&& send) {
    uint8_t n = 0;
    LogRepairs::Part repair{};
    const auto lines_of_log = [this](wire::LogKind log) { return lines_of(log); };
    for (; n < max_parts && repairs_.next(parts_per_line, lines_of_log, repair); ++n) {
      if (!reach(repair_, repair.log, repair.line)) return;
      if (!send(part(repair_, repair.log, repair.line, repair.part))) return;
      repairs_.sent();
    }
    for (; n < max_parts && downloading_; ++n) {
      if (!reach(stream_, kind_, next_line_)) return;
      if (!send(part(stream_, kind_, next_line_, next_part_))) return;
      if (++next_part_ == parts_per_line(kind_)) {
        next_part_ = 0;
        if (++next_line_ >= end_line_) downloading_ = false;
      }
    }
  }

  [[gnu::noinline]] wire::LogStatus status() const {
    uint8_t flags = 0;
    if (logging_ && packed_.contents().sensor) flags |= wire::kLogStatusSensorOn;
    if (logging_ && packed_.contents().telemetry) flags |= wire::kLogStatusTelemetryOn;
    if (full()) flags |= wire::kLogStatusFull;
    return {flags, lines_of(wire::LogKind::sensor), lines_of(wire::LogKind::telemetry), packed_.capacity_estimate()};
  }
  bool full() const { return packed_.full(); }
  // Line `line` of a log, unpacked from its keyframe (for checks: a download unpacks as it goes).
  bool read_line(wire::LogKind log, uint16_t line, log_pack::LogLine& out) const {
    log_pack::LogCursor<Model> cursor;
    if (line >= lines_of(log) || !cursor.reach(packed_, index_of(log, line), log_pack::kKeyframeLines)) return false;
    out = cursor.line();
    return true;
  }
  // A part of a telemetry line as a download sends it: what a line that came whole must equal.
  wire::TelemetryLogPart telemetry_part(uint16_t line, uint8_t part) const {
    log_pack::LogLine l;
    if (!read_line(wire::LogKind::telemetry, line, l)) return {};
    l.telemetry.line = line;
    return wire::make_log_part(l.telemetry, part);
  }
  // A stream or parts asked for again are still to send.
  bool downloading() const { return downloading_ || !repairs_.empty(); }
  // The packing's figures: the area's bytes for lines and the bits they took.
  size_t packed_bytes() const { return packed_.bytes(); }
  size_t packed_bits_used() const { return packed_.bits_used(); }

 private:
  uint16_t lines_of(wire::LogKind log) const {
    const log_pack::Contents c = packed_.contents();
    if (log == wire::LogKind::sensor) return c.sensor ? packed_.lines() : 0;
    return c.telemetry ? packed_.telemetry_lines() : 0;
  }
  uint32_t index_of(wire::LogKind log, uint16_t line) const {
    return log_pack::LogCursor<Model>::index_of(packed_.contents(), log == wire::LogKind::telemetry, line);
  }
  bool reach(log_pack::LogCursor<Model>& cursor, wire::LogKind log, uint16_t line) {
    return cursor.reach(packed_, index_of(log, line), kUnpackLinesPerCall);
  }
  [[gnu::cold, gnu::noinline]] static wire::FrameBytes part(const log_pack::LogCursor<Model>& cursor, wire::LogKind log,
                                                            uint16_t line, uint8_t p) {
    log_pack::LogLine l = cursor.line();
    if (log == wire::LogKind::sensor) {
      l.sensor.line = line;
      return wire::encode(wire::make_log_part(l.sensor, p));
    }
    l.telemetry.line = line;
    return wire::encode(wire::make_log_part(l.telemetry, p));
  }
  static uint8_t parts_per_line(wire::LogKind log) {
    return log == wire::LogKind::sensor ? wire::SensorLogRecord::kParts : wire::TelemetryLogRecord::kParts;
  }

  log_pack::PackedLog<Model> packed_;
  log_pack::LogCursor<Model> stream_;
  log_pack::LogCursor<Model> repair_;
  bool logging_ = false;

  bool downloading_ = false;
  wire::LogKind kind_ = wire::LogKind::sensor;
  uint16_t next_line_ = 0;
  uint16_t end_line_ = 0;
  uint8_t next_part_ = 0;
  LogRepairs repairs_;
};

}  // namespace qr
