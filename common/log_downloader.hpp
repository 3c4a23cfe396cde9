// The console's side of a log download: asks for the lines the QR has, collects their parts, asks
// again for the parts that did not come while the stream goes on, and hands each line on exactly
// once.
//
//   downloader.begin(status.sensor_lines);                       // from log_status
//   each pass:  if (downloader.next_download(now_ms, first, count)) queue LogDownload{first, count}
//               if (log_resend not pending && downloader.next_resend(now_ms, resend)) queue resend
//               for each sensor_log_part:  downloader.on_part(part, now_ms, store_line)
//   until downloader.done()
//
// The QR streams the log once (log_download). A line behind the newest one seen that is not
// whole has lost parts on the way: they are asked for again at once, by part (log_resend), and
// the QR sends them before the stream's next parts. Parts of a line that is not whole are kept
// (kPartialLines of them), so a line lost one part needs one part again, not the whole line. When
// the line is quiet (kQuietMs: the stream has ended, or a request or its parts were lost),
// whatever is still missing is asked for again from the first missing line on.
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
#include <common/payload_codec.hpp>
#include <common/requests.hpp>

namespace wire {

template <LogRecord Record, size_t MaxLines = 65536>
class LogDownloader {
 public:
  // Parts stop for this long: the QR has sent what it was asked for (or a request was lost).
  static constexpr uint32_t kQuietMs = 250;
  // Lines not whole whose parts are kept, a slot each by line number: over a line that damages
  // most parts nearly every line is partial for many passes (the soak's 5 % of bytes lost: 64
  // slots, the oldest evicted, never finished its hour's log in an hour; 512 finish it in 17 min).
  static constexpr size_t kPartialLines = 512;
  // Whole lines one log_resend covers: its mask holds their parts.
  static constexpr uint16_t kResendLines = kLogResendMaskBytes * 8 / Record::kParts;
  static constexpr LogKind kLog = Record::kPartType == MessageType::sensor_log_part ? LogKind::sensor
                                                                                    : LogKind::telemetry;

  void begin(uint16_t lines) {
    lines_ = lines;
    received_ = 0;
    requests_ = 0;
    resends_ = 0;
    asked_ = false;
    stream_over_ = false;
    newest_ = 0;
    cursor_ = 0;
    first_missing_ = 0;
    for (uint8_t& b : have_) b = 0;
    for (Partial& p : partial_) p.parts = 0;
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

  // The stream request, once: every line from the first on.
  bool next_download(uint32_t now_ms, uint16_t& first, uint16_t& count) {
    if (asked_ || done()) return false;
    asked_ = true;
    first = 0;
    count = 0;  // to the end
    last_activity_ms_ = now_ms;
    ++requests_;
    return true;
  }

  // Parts to ask for again now, if any: the missing parts of the next kResendLines lines behind
  // the stream from where the last request ended; once the line is quiet, from the first line
  // still missing. The caller sends one at a time (a new log_resend replaces a pending one).
  bool next_resend(uint32_t now_ms, LogResend& out) {
    if (!asked_ || done()) return false;
    const bool quiet = now_ms - last_activity_ms_ >= kQuietMs;
    if (quiet) stream_over_ = true;
    // Lines the stream has passed; once it has been quiet, every line (the stream is over or lost).
    const uint32_t behind = stream_over_ ? lines_ : (newest_ > 0 ? newest_ - 1 : 0);
    while (first_missing_ < lines_ && have(static_cast<uint16_t>(first_missing_))) ++first_missing_;
    // Quiet, and nothing asked for lately: what is still missing was lost again, or its request.
    if (quiet && now_ms - last_resend_ms_ >= kQuietMs) cursor_ = first_missing_;
    uint32_t line = cursor_ > first_missing_ ? cursor_ : first_missing_;
    while (line < behind && have(static_cast<uint16_t>(line))) ++line;
    if (line >= behind) return false;

    out = LogResend{0, kLog, static_cast<uint16_t>(line), {}};
    for (uint16_t n = 0; n < kResendLines && line + n < behind; ++n) {
      const uint16_t l = static_cast<uint16_t>(line + n);
      if (have(l)) continue;
      const uint8_t parts = parts_of(l);
      for (uint8_t k = 0; k < Record::kParts; ++k) {
        if ((parts >> k & 1u) == 0) out.want(size_t{n} * Record::kParts + k);
      }
    }
    // Lines the stream has not passed yet are looked at again when it has.
    cursor_ = line + kResendLines < behind ? line + kResendLines : behind;
    last_resend_ms_ = now_ms;
    ++resends_;
    return true;
  }

  bool done() const { return received_ == lines_; }
  uint16_t lines() const { return lines_; }
  uint16_t received() const { return received_; }
  uint32_t requests() const { return requests_ + resends_; }
  // Requests after the stream request: every log_resend.
  uint32_t rerequests() const { return resends_; }

 private:
  static_assert(MaxLines <= 65536, "line numbers are u16");
  static_assert(Record::kParts <= 8, "a line's parts are one byte of bits");
  static_assert(kResendLines >= 1, "a log_resend covers a whole line at least");
  static constexpr uint8_t kAllParts = static_cast<uint8_t>((1u << Record::kParts) - 1u);

  struct Partial {
    uint16_t line = 0;
    uint8_t parts = 0;  // 0: free
    uint8_t flat[size_t{Record::kParts} * kLogPartDataBytes] = {};
  };

  bool have(uint16_t line) const { return (have_[line / 8] >> (line % 8) & 1u) != 0; }

  // A part to keep: its line's slot gathers it; on_line gets the line the first time it is whole.
  template <class OnLine>
  void keep(const LogPart<Record>& part, OnLine& on_line) {
    if (part.line >= lines_ || part.part >= Record::kParts) return;
    if (uint32_t{part.line} + 1 > newest_) newest_ = uint32_t{part.line} + 1;
    if (have(part.line)) return;
    Partial& p = partial_for(part.line);
    for (size_t i = 0; i < kLogPartDataBytes; ++i) p.flat[size_t{part.part} * kLogPartDataBytes + i] = part.data[i];
    p.parts = static_cast<uint8_t>(p.parts | (1u << part.part));
    if (p.parts != kAllParts) return;
    p.parts = 0;  // the slot is free again, whatever the record says
    Record record;
    if (!read_fields(p.flat, sizeof p.flat, record)) return;  // a field out of range: asked again
    record.line = part.line;
    have_[part.line / 8] = static_cast<uint8_t>(have_[part.line / 8] | (1u << (part.line % 8)));
    ++received_;
    on_line(static_cast<const Record&>(record));
  }

  // The parts of `line` kept so far (0 when it has no slot).
  uint8_t parts_of(uint16_t line) const {
    const Partial& p = partial_[line % kPartialLines];
    return p.parts != 0 && p.line == line ? p.parts : 0;
  }

  // The line's slot, by line number modulo the slots: a stream or a re-stream's span never has
  // two lines in one slot; a slot's earlier line starts over (its parts are asked for again).
  Partial& partial_for(uint16_t line) {
    Partial& slot = partial_[line % kPartialLines];
    if (slot.parts == 0 || slot.line != line) {
      slot.line = line;
      slot.parts = 0;
    }
    return slot;
  }

  bool watching_ = false;  // the receiver reports its damage count
  uint32_t damage_ = 0;
  bool frame_clean_ = false;  // no damage between the frame before the last one and it
  bool pending_ = false;
  bool pending_clean_ = false;
  LogPart<Record> pending_part_;
  uint8_t have_[MaxLines / 8] = {};
  Partial partial_[kPartialLines] = {};
  uint16_t lines_ = 0;
  uint16_t received_ = 0;
  uint32_t requests_ = 0;
  uint32_t resends_ = 0;
  bool asked_ = false;
  bool stream_over_ = false;    // the line has been quiet since the stream request
  uint32_t newest_ = 0;         // one past the highest line a part came for
  uint32_t cursor_ = 0;         // where the next log_resend starts looking
  uint32_t first_missing_ = 0;  // no line before it is missing
  uint32_t last_activity_ms_ = 0;
  uint32_t last_resend_ms_ = 0;
};

}  // namespace wire
