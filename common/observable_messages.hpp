// The messages of observable streams (docs/protocol.md section 13): the PC asks for the table
// (observable_get) and for streams (stream_request); the QR describes each observable
// (observable_info, observable_text) and sends samples (observable_samples).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/message_table.hpp>
#include <common/observable_table.hpp>
#include <common/stream_budget.hpp>

namespace wire {

// Asks for the observable table: one row (id), or every row (kAllObservables). Acked; the QR then
// sends observable_info and observable_text frames for each row asked for.
struct ObservableGet {
  static constexpr MessageType kType = MessageType::observable_get;
  uint8_t seq = 0;
  uint8_t id = kAllObservables;

  constexpr bool operator==(const ObservableGet&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.id);
  }
  // An id the QR does not know is its business (nack bad_value), not the decoder's: a console may
  // ask a firmware with a shorter table.
  constexpr bool valid() const { return true; }
};

// Starts (divider > 0) or stops (divider 0) one stream: up to four observables sampled every
// `divider` control periods. Places after the last observable hold kNoObservable.
struct StreamRequest {
  static constexpr MessageType kType = MessageType::stream_request;
  uint8_t seq = 0;
  uint8_t stream = 0;    // 0..kStreamCount-1
  uint16_t divider = 0;  // control periods between samples; 0: stop
  uint8_t id[kStreamObservablesMax] = {kNoObservable, kNoObservable, kNoObservable, kNoObservable};

  constexpr bool operator==(const StreamRequest&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.stream);
    v(m.divider);
    // One by one: GCC 13 at -O3 misjudges the array visitor's bounds here (stringop-overflow).
    v(m.id[0]);
    v(m.id[1]);
    v(m.id[2]);
    v(m.id[3]);
  }
  static_assert(kStreamObservablesMax == 4, "fields() visits four ids");
  // Observables first, then only empty places: one encoding per selection.
  constexpr uint8_t count() const {
    uint8_t n = 0;
    while (n < kStreamObservablesMax && id[n] != kNoObservable) ++n;
    return n;
  }
  constexpr bool valid() const {
    if (stream >= kStreamCount) return false;
    const uint8_t n = count();
    for (uint8_t i = n; i < kStreamObservablesMax; ++i) {
      if (id[i] != kNoObservable) return false;
    }
    return divider == 0 ? n == 0 : n > 0;
  }
};

// One row of the QR's observable table, and how many rows there are and the control rate the
// stream dividers divide: each frame is enough to use the row.
struct ObservableInfo {
  static constexpr MessageType kType = MessageType::observable_info;
  uint8_t id = 0;
  uint8_t count = 1;  // rows in the table: ids 0..count-1
  ObservableType type = ObservableType::i16;
  int8_t scale = 0;            // value in the unit = raw x 10^scale
  uint16_t control_hz = 1000;  // the QR's control rate

  constexpr bool operator==(const ObservableInfo&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.id);
    v(m.count);
    v(m.type);
    v(m.scale);
    v(m.control_hz);
  }
  constexpr bool valid() const {
    return id < count && (type == ObservableType::i16 || type == ObservableType::u16) && control_hz > 0;
  }
};

inline constexpr size_t kObservableTextPartChars = 7;
inline constexpr uint8_t kObservableTextParts = kObservableTextChars / kObservableTextPartChars;

// Seven characters of an observable's "name unit" text, NUL-padded; part k holds characters 7k..7k+6.
struct ObservableText {
  static constexpr MessageType kType = MessageType::observable_text;
  uint8_t id = 0;
  uint8_t part = 0;  // 0..3
  char text[kObservableTextPartChars] = {};

  constexpr bool operator==(const ObservableText&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.id);
    v(m.part);
    v(m.text);
  }
  constexpr bool valid() const {
    if (part >= kObservableTextParts || id == kNoObservable) return false;
    bool ended = false;  // NUL only as padding at the end
    for (char c : text) {
      if (c == '\0') ended = true;
      else if (ended) return false;
    }
    return true;
  }
};

// Samples of one stream: the header's top two bits name the stream, its low six count the
// stream's frames (wrapping), so the PC sees lost frames; then four 16-bit values, sample after
// sample (samples_per_frame of them), each sample's observables in the request's order, zero after
// the last. A u16 observable travels as the same 16 bits.
struct ObservableSamples {
  static constexpr MessageType kType = MessageType::observable_samples;
  uint8_t header = 0;
  int16_t value[kSampleValuesPerFrame] = {0, 0, 0, 0};

  constexpr bool operator==(const ObservableSamples&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.header);
    v(m.value);
  }
  constexpr uint8_t stream() const { return static_cast<uint8_t>(header >> 6); }
  constexpr uint8_t sequence() const { return static_cast<uint8_t>(header & 0x3F); }
  constexpr bool valid() const { return true; }
};

inline constexpr uint8_t kSampleSequenceModulo = 64;

constexpr uint8_t sample_header(uint8_t stream, uint8_t sequence) {
  return static_cast<uint8_t>((stream << 6) | (sequence & 0x3F));
}

}  // namespace wire
