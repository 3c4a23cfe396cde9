// The console's side of a log download: asks for the lines the QR has, collects their parts, asks
// again for the lines that did not come whole, and hands each line on exactly once.
//
//   downloader.begin(status.sensor_lines);             // from log_status
//   each pass:  if (downloader.next_request(now_ms, first, count)) queue LogDownload{first, count}
//               for each sensor_log_part:  downloader.on_part(part, now_ms, store_line)
//   until downloader.done()
//
// One request is out at a time: a new log_download replaces the QR's current one. After the
// parts stop coming (kQuietMs), the missing lines are asked for again (next_request).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/log_records.hpp>

namespace wire {

template <LogRecord Record, size_t MaxLines = 65536>
class LogDownloader {
 public:
  // Parts stop for this long: the QR has sent what it was asked for (or the request was lost).
  static constexpr uint32_t kQuietMs = 250;
  // The widest span one re-request covers.
  static constexpr uint16_t kMaxRerequestLines = 512;

  void begin(uint16_t lines) {
    lines_ = lines;
    received_ = 0;
    requests_ = 0;
    asked_ = false;
    for (uint8_t& b : have_) b = 0;
  }

  // A part from the QR; on_line(const Record&) is called the first time its line is whole.
  template <class OnLine>
  void on_part(const LogPart<Record>& part, uint32_t now_ms, OnLine&& on_line) {
    last_activity_ms_ = now_ms;
    Record record;
    if (assembler_.add(part, record) != LogLineAssembler<Record>::Result::complete) return;
    if (record.line >= lines_ || have(record.line)) return;
    have_[record.line / 8] = static_cast<uint8_t>(have_[record.line / 8] | (1u << (record.line % 8)));
    ++received_;
    on_line(static_cast<const Record&>(record));
  }

  // The request to make now, if one is due: everything at first, then, each time the line has
  // been quiet for kQuietMs, the span from the first missing line to the last missing line within
  // kMaxRerequestLines of it. Losses are scattered, so a span brings back every gap in it in one
  // pass, at the price of re-sending the lines between them that did arrive.
  bool next_request(uint32_t now_ms, uint16_t& first, uint16_t& count) {
    if (done()) return false;
    if (asked_ && now_ms - last_activity_ms_ < kQuietMs) return false;
    uint32_t line = 0;
    while (line < lines_ && have(static_cast<uint16_t>(line))) ++line;
    uint32_t last = line;
    for (uint32_t l = line; l < lines_ && l - line < kMaxRerequestLines; ++l) {
      if (!have(static_cast<uint16_t>(l))) last = l;
    }
    first = static_cast<uint16_t>(line);
    count = asked_ ? static_cast<uint16_t>(last - line + 1) : 0;  // the first request: to the end
    asked_ = true;
    last_activity_ms_ = now_ms;
    ++requests_;
    return true;
  }

  bool done() const { return received_ == lines_; }
  uint16_t lines() const { return lines_; }
  uint16_t received() const { return received_; }
  uint32_t requests() const { return requests_; }
  uint32_t rerequests() const { return requests_ == 0 ? 0 : requests_ - 1; }

 private:
  static_assert(MaxLines <= 65536, "line numbers are u16");
  bool have(uint16_t line) const { return (have_[line / 8] >> (line % 8) & 1u) != 0; }

  LogLineAssembler<Record> assembler_;
  uint8_t have_[MaxLines / 8] = {};
  uint16_t lines_ = 0;
  uint16_t received_ = 0;
  uint32_t requests_ = 0;
  bool asked_ = false;
  uint32_t last_activity_ms_ = 0;
};

}  // namespace wire
