// Byte-at-a-time CRSF receiver parser (crsf.hpp for the format). It never blocks, keeps at most one
// frame's bytes, and computes the check as the bytes arrive, so a good frame costs one table
// lookup per byte. After a bad length or check it looks for the next sync byte among the bytes it
// kept (a real frame starting inside a damaged one is still found, and every whole frame after it);
// each such step drops at least one byte, so a push does at most kCrsfMaxFrameBytes of them.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/crc8.hpp>
#include <common/drivers/crsf.hpp>

namespace drivers {

struct CrsfCounters {
  uint32_t bytes = 0;
  uint32_t frames = 0;
  uint32_t check_failures = 0;  // a candidate frame whose check byte did not match
  uint32_t bad_lengths = 0;     // a sync byte followed by a length outside 2..62
  uint32_t bytes_skipped = 0;   // bytes in no good frame
};

class CrsfParser {
 public:
  // Calls on_frame(const CrsfFrame&) for each good frame the bytes complete. Inside a frame's
  // type and payload a byte is only kept and checked (the loop a frame spends its bytes in); the
  // sync, the length, the check byte and a resynchronisation take the general path.
  template <class OnFrame>
  void push(const uint8_t* data, size_t size, OnFrame&& on_frame) {
    counters_.bytes += static_cast<uint32_t>(size);
    size_t i = 0;
    while (i < size) {
      if (length_ >= 2 && length_ <= buffer_[1]) {
        // Up to the check byte's place (index length + 1), as far as the data goes. Pointers and
        // a count fixed up front: eight instructions a byte on RV32IM.
        const size_t want = static_cast<size_t>(buffer_[1] + 1 - length_);
        const size_t n = want < size - i ? want : size - i;
        const uint8_t* src = data + i;
        const uint8_t* const stop = src + n;
        uint8_t* dst = &buffer_[length_];
        uint8_t crc = crc_;
        while (src != stop) {
          const uint8_t b = *src++;
          *dst++ = b;
          crc = wire::kCrc8Table.entry[crc ^ b];
        }
        i += n;
        length_ = static_cast<uint8_t>(length_ + n);
        crc_ = crc;
        continue;
      }
      step(data[i++], on_frame);
    }
  }
  template <class OnFrame>
  void push(uint8_t byte, OnFrame&& on_frame) {
    const uint8_t one[1] = {byte};  // an array of one: cppcheck took &byte for an object indexed past itself
    push(one, 1, on_frame);
  }

  const CrsfCounters& counters() const { return counters_; }
  uint8_t buffered() const { return length_; }

 private:
  enum class Verdict : uint8_t { incomplete, complete, broken };

  // One byte by the general path: kept, then judged until the kept bytes are a frame's start.
  template <class OnFrame>
  void step(uint8_t byte, OnFrame& on_frame) {
    if (length_ == 0 && byte != kCrsfSync) {  // between frames: the common garbage case
      ++counters_.bytes_skipped;
      return;
    }
    take(byte);
    while (true) {
      const Verdict v = judge();
      if (v == Verdict::incomplete) return;
      if (v == Verdict::complete) {
        ++counters_.frames;
        const uint8_t size = static_cast<uint8_t>(buffer_[1] + 2);
        on_frame(CrsfFrame{buffer_[2], static_cast<uint8_t>(buffer_[1] - 2), &buffer_[3]});
        keep_from(size);  // bytes after the frame: only after a resync found it inside kept bytes
      } else {
        resync();
      }
    }
  }

  // Keeps a byte; type and payload (bytes 2 .. length) go into the running check.
  void take(uint8_t byte) {
    const uint8_t at = length_;
    buffer_[length_++] = byte;
    if (at >= 2 && at <= buffer_[1]) crc_ = wire::crc8_update(crc_, byte);
  }
  Verdict judge() {
    if (length_ < 2) return Verdict::incomplete;
    const uint8_t length = buffer_[1];
    if (length < kCrsfMinLength || length > kCrsfMaxLength) {
      ++counters_.bad_lengths;
      return Verdict::broken;
    }
    if (length_ < length + 2) return Verdict::incomplete;
    if (crc_ == buffer_[length + 1]) return Verdict::complete;
    ++counters_.check_failures;
    return Verdict::broken;
  }
  // The kept bytes are not a frame: drop the leading sync and keep from the next one.
  void resync() {
    uint8_t from = 1;
    while (from < length_ && buffer_[from] != kCrsfSync) ++from;
    counters_.bytes_skipped += from;
    keep_from(from);
  }
  // Keeps the bytes from `from` on, moved down, and recounts the running check over them.
  void keep_from(uint8_t from) {
    const uint8_t kept = static_cast<uint8_t>(length_ - from);
    length_ = 0;
    crc_ = 0;
    for (uint8_t i = 0; i < kept; ++i) take(buffer_[from + i]);  // moves down: never reads a byte it wrote
  }

  uint8_t buffer_[kCrsfMaxFrameBytes] = {};
  uint8_t length_ = 0;
  uint8_t crc_ = 0;
  CrsfCounters counters_;
};

}  // namespace drivers
