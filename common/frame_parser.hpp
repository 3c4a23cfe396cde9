// Byte-at-a-time frame parser. It never blocks, keeps only the bytes of the frame it is looking at
// (at most kMaxFrameBytes), and after a failed check starts looking again at the byte after the
// 'M' it had taken for a start, so a real frame beginning inside a damaged one is still found.
//
// Work per byte: every step of the loop in advance() either waits for more bytes or throws away
// at least one buffered byte, so one push() does at most kMaxFrameBytes + 1 steps of at most one
// check over kMaxPayloadBytes + 1 bytes and one shift of the buffer; averaged over a stream it is
// at most one such step per byte received (each byte is thrown away or delivered once).
#pragma once

#include <stdint.h>

#include <common/frame.hpp>
#include <common/message_table.hpp>

namespace wire {

struct LinkCounters {
  uint32_t bytes_received = 0;
  uint32_t frames_ok = 0;
  uint32_t check_failures = 0;  // a candidate frame whose check byte did not match
  uint32_t unknown_types = 0;   // 'M' followed by a byte that is no type this receiver listens to
  uint32_t bytes_skipped = 0;   // bytes that ended up in no accepted frame
};

class FrameParser {
 public:
  explicit constexpr FrameParser(Listen listen) : listen_(listen) {}

  // Feeds one received byte; calls on_frame(const Frame&) for each frame it completes (usually
  // none or one; after a failed check, re-scanning the kept bytes can complete more than one).
  template <class OnFrame>
  void push(uint8_t byte, OnFrame&& on_frame) {
    // advance() returns false only with fewer than kMaxFrameBytes bytes kept, so this fits.
    buffer_[length_++] = byte;
    ++counters_.bytes_received;
    while (advance()) on_frame(static_cast<const Frame&>(frame_));
  }

  // The line has been silent for a long time (recommended: 50 ms or more; a frame's bytes follow
  // each other within a millisecond, but USB serial adapters deliver in chunks a few ms apart).
  // Kept bytes then belong to a frame whose sender stopped part-way, e.g. a restarted console;
  // dropping them means the next frame is not read as the rest of it. Optional: without it the
  // check catches the mix-up all but 1 time in 256.
  void line_idle() { discard(length_, true); }

  const LinkCounters& counters() const { return counters_; }

  // Bytes kept for a frame not yet complete.
  uint8_t buffered() const { return length_; }

 private:
  bool advance();
  bool guard_holds(const MessageSpec& spec) const;
  void discard(uint8_t count, bool skipped);

  Listen listen_;
  uint8_t buffer_[kMaxFrameBytes] = {};
  uint8_t length_ = 0;
  Frame frame_;
  LinkCounters counters_;
};

}  // namespace wire
