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
//
// A line's parts are kept until it is whole, over as many passes as it takes (a line never
// changes once written): over a line losing 5 % of its bytes a 7-part line comes whole in one
// pass about once in 70, and the soak's download took 421 passes for 120 lines when a line had
// to come whole in one (docs/simulator.md section 9).
//
// Over a line that loses bytes, a receiver that says what its parser saw (frame_accepted, with
// every frame it accepts) gets only parts it can trust: a lost byte inside a part splices it
// with the next frame's first byte, and one time in 256 the 8-bit check passes, with the right
// line and part number and wrong data. The splice leaves the next frame broken, so a part is
// kept only when no damage (bytes skipped, checks failed) came between the frame before it and
// the frame after it. Without frame_accepted every part is kept as it comes.
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
    for (Partial& p : partial_) p = Partial{};
    pending_ = false;
  }

  // Every frame the receiver accepts, before it is handled (a part then goes to on_part), with
  // its parser's damage count so far (FrameParser::counters(): bytes_skipped + check_failures).
  template <class OnLine>
  void frame_accepted(uint32_t damage, OnLine&& on_line) {
    const bool clean = watching_ && damage == damage_;
    watching_ = true;
    damage_ = damage;
    if (pending_ && pending_clean_ && clean) keep(pending_part_, on_line);
    pending_ = false;
    frame_clean_ = clean;
  }

  // A part from the QR; on_line(const Record&) is called the first time its line is whole.
  template <class OnLine>
  void on_part(const LogPart<Record>& part, uint32_t now_ms, OnLine&& on_line) {
    last_activity_ms_ = now_ms;
    if (!watching_) {
      keep(part, on_line);
      return;
    }
    // Judged when the next frame shows whether this one was spliced.
    pending_ = true;
    pending_part_ = part;
    pending_clean_ = frame_clean_;
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

  template <class OnLine>
  void keep(const LogPart<Record>& part, OnLine& on_line) {
    if (part.part >= Record::kParts || part.line >= lines_ || have(part.line)) return;
    Partial& slot = partial_[part.line % kPartialLines];
    if (!slot.used || slot.line != part.line) {
      slot = Partial{};
      slot.used = true;
      slot.line = part.line;
    }
    for (size_t i = 0; i < kLogPartDataBytes; ++i) slot.data[size_t{part.part} * kLogPartDataBytes + i] = part.data[i];
    slot.parts = static_cast<uint8_t>(slot.parts | (1u << part.part));
    if (slot.parts != kAllParts) return;

    Record record;
    const bool valid = read_fields(slot.data, sizeof slot.data, record);
    slot = Partial{};
    if (!valid) return;  // a field out of range: the line is asked for again
    record.line = part.line;
    have_[record.line / 8] = static_cast<uint8_t>(have_[record.line / 8] | (1u << (record.line % 8)));
    ++received_;
    on_line(static_cast<const Record&>(record));
  }

  // Lines being collected, by line number modulo the widest re-request: one pass never has two
  // lines in one slot, except the first (then a slot's earlier line starts over).
  static constexpr uint16_t kPartialLines = kMaxRerequestLines;
  static_assert(Record::kParts <= 8, "the parts mask is one byte");
  static constexpr uint8_t kAllParts = static_cast<uint8_t>((1u << Record::kParts) - 1u);
  struct Partial {
    bool used = false;
    uint16_t line = 0;
    uint8_t parts = 0;  // one bit per part kept
    uint8_t data[size_t{Record::kParts} * kLogPartDataBytes] = {};
  };
  Partial partial_[kPartialLines];

  bool watching_ = false;  // the receiver reports its damage count
  uint32_t damage_ = 0;
  bool frame_clean_ = false;  // no damage between the frame before the last one and it
  bool pending_ = false;
  bool pending_clean_ = false;
  LogPart<Record> pending_part_;
  uint8_t have_[MaxLines / 8] = {};
  uint16_t lines_ = 0;
  uint16_t received_ = 0;
  uint32_t requests_ = 0;
  bool asked_ = false;
  uint32_t last_activity_ms_ = 0;
};

}  // namespace wire
