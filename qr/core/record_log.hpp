// A log of fixed-size records in a byte area the board provides, each kept in its wire form
// (common/log_records.hpp), so a download sends the stored bytes as they are.
//
// Policy when full: the log stops (keeps its first lines) and says so; a new start clears it.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/log_records.hpp>
#include <common/payload_codec.hpp>

namespace qr {

template <wire::LogRecord Record>
class RecordLog {
 public:
  static constexpr size_t kRecordBytes = wire::wire_size<Record>();

  void attach(uint8_t* area, size_t bytes) {
    area_ = area;
    const size_t capacity = area == nullptr ? 0 : bytes / kRecordBytes;
    capacity_ = static_cast<uint16_t>(capacity > kMaxLines ? kMaxLines : capacity);
    lines_ = 0;
  }
  void clear() { lines_ = 0; }

  // False when full (or without storage): the line is not kept.
  bool append(const Record& record) {
    if (lines_ >= capacity_) return false;
    wire::write_fields(record, area_ + size_t{lines_} * kRecordBytes, kRecordBytes);
    ++lines_;
    return true;
  }

  // Part `part` of line `line`, as it goes on the wire.
  wire::LogPart<Record> part(uint16_t line, uint8_t part) const {
    wire::LogPart<Record> out;
    out.line = line;
    out.part = part;
    const uint8_t* bytes = area_ + size_t{line} * kRecordBytes + size_t{part} * wire::kLogPartDataBytes;
    for (size_t i = 0; i < wire::kLogPartDataBytes; ++i) out.data[i] = bytes[i];
    return out;
  }

  uint16_t lines() const { return lines_; }
  uint16_t capacity() const { return capacity_; }
  bool full() const { return capacity_ != 0 && lines_ >= capacity_; }

 private:
  static constexpr size_t kMaxLines = 0xFFFF;  // line numbers are u16 on the wire

  uint8_t* area_ = nullptr;
  uint16_t capacity_ = 0;
  uint16_t lines_ = 0;
};

}  // namespace qr
