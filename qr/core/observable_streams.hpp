// The QR's side of observable streams (docs/protocol.md section 13): up to four streams, each a
// few observables sampled every `divider` ticks and packed into observable_samples frames, and the
// table rows owed to an observable_get. Run by the stream row of the task table every tick, after
// the safety machine: a sample is the tick's final values. A stream's rate is data (its request's
// divider), so it counts its own ticks; the row itself runs every tick.
#pragma once

#include <stdint.h>

#include <common/frame.hpp>
#include <common/nack_reason.hpp>
#include <common/observable_messages.hpp>
#include <common/payload_codec.hpp>
#include <common/sample_packing.hpp>
#include <common/stream_budget.hpp>
#include <qr/core/observable_readers.hpp>

// A board short of image can build without streams (QR_OBSERVABLE_STREAMS=0, about 4 KiB on
// RV32): it answers their requests not_supported. Every image of this project carries them.
#ifndef QR_OBSERVABLE_STREAMS
#define QR_OBSERVABLE_STREAMS 1
#endif

namespace qr {

inline constexpr bool kObservableStreams = QR_OBSERVABLE_STREAMS != 0;

using wire::NackReason;

template <class Flight>
class ObservableStreams {
 public:
  // A stream request: started (or replaced, or stopped) if the line can carry every stream then
  // running beside the telemetry at `telemetry_hz`; otherwise nothing changes.
  // Requests and the table are rare: compiled for size (cold), the image has little room.
  [[gnu::cold, gnu::noinline]] NackReason request(const wire::StreamRequest& r, uint32_t control_hz,
                                                  uint32_t telemetry_hz) {
    const uint8_t n = r.count();
    for (uint8_t i = 0; i < n; ++i) {
      if (r.id[i] >= wire::kObservableCount) return NackReason::bad_value;
    }
    uint32_t bytes = wire::stream_bytes_per_s(control_hz, r.divider, n);
    for (uint8_t s = 0; s < wire::kStreamCount; ++s) {
      if (s != r.stream) bytes += wire::stream_bytes_per_s(control_hz, slots_[s].divider, slots_[s].count);
    }
    if (bytes > wire::stream_room_bytes_per_s(telemetry_hz)) return NackReason::over_budget;
    Slot& slot = slots_[r.stream];
    slot.divider = r.divider;
    slot.countdown = 1;  // the first sample on the next run
    slot.count = n;
    for (uint8_t i = 0; i < wire::kStreamObservablesMax; ++i) slot.id[i] = r.id[i];
    slot.packer.start(r.stream, n);
    running_ = 0;
    for (const Slot& each : slots_) running_ = static_cast<uint8_t>(running_ + (each.divider != 0 ? 1 : 0));
    return NackReason::none;
  }

  [[gnu::cold, gnu::noinline]] NackReason request_table(uint8_t id) {
    if (id == wire::kAllObservables) {
      next_row_ = 0;
      next_part_ = 0;
      end_row_ = wire::kObservableCount;
    } else if (id < wire::kObservableCount) {
      next_row_ = id;
      next_part_ = 0;
      end_row_ = static_cast<uint8_t>(id + 1);
    } else {
      return NackReason::bad_value;
    }
    return NackReason::none;
  }

  bool streaming() const { return running_ != 0; }

  // No stream running and no table row owed: the tick has nothing to do. The row runs in every
  // tick of every mode, and a console that plots nothing should not pay for it: the caller asks
  // this first, before it makes what run() is handed.
  bool idle() const { return running_ == 0 && next_row_ >= end_row_; }

  // One tick: a sample of every stream that is due; then one owed table row if `room(bytes)` says
  // the line has that much to spare.
  template <class Send, class Room>
  [[gnu::always_inline]] inline void run(const Flight& f, uint32_t control_hz, Send&& send, Room&& room) {
    if (idle()) return;
    run_due(f, control_hz, send, room);
  }

 private:
  struct Slot;

  template <class Send, class Room>
  [[gnu::noinline]] void run_due(const Flight& f, uint32_t control_hz, Send& send, Room& room) {
    for (Slot& slot : slots_) {
      if (slot.divider == 0 || --slot.countdown != 0) continue;
      slot.countdown = slot.divider;
      wire::FrameBytes frame;
      if (sample(slot, f, frame)) send(frame);
    }
    if (next_row_ < end_row_ && room(wire::kMaxFrameBytes)) send_table_frame(control_hz, send);
  }

  // One sample of a stream into its packer; true when that filled a frame, encoded in `out`. Out
  // of line: one copy in the image.
  [[gnu::noinline]] static bool sample(Slot& slot, const Flight& f, wire::FrameBytes& out) {
    int16_t values[wire::kStreamObservablesMax];
    for (uint8_t i = 0; i < slot.count; ++i) {
      const uint8_t id = slot.id[i];
      values[i] = observable_bits(wire::kObservableWire[id].type, read_observable(f, id));
    }
    wire::ObservableSamples frame;
    if (!slot.packer.add(values, frame)) return false;
    out = wire::encode(frame);
    return true;
  }

  // One frame of the owed table rows a tick: a row's observable_info, then its observable_text
  // pieces ("name unit", seven characters each, NUL-padded, until a piece holds a NUL).
  template <class Send>
  [[gnu::cold, gnu::noinline]] void send_table_frame(uint32_t control_hz, Send& send) {
    const wire::ObservableWireRow& row = wire::kObservableWire[next_row_];
    if (next_part_ == 0) {
      send(wire::encode(wire::ObservableInfo{next_row_, wire::kObservableCount, row.type, row.scale,
                                             static_cast<uint16_t>(control_hz)}));
      next_part_ = 1;
      return;
    }
    const uint8_t part = static_cast<uint8_t>(next_part_ - 1);
    const char* c = row.text;
    for (size_t skip = 0; skip < size_t{part} * wire::kObservableTextPartChars; ++skip) ++c;
    wire::ObservableText piece;
    piece.id = next_row_;
    piece.part = part;
    size_t copied = 0;
    for (; copied < wire::kObservableTextPartChars && *c != '\0'; ++copied) piece.text[copied] = *c++;
    send(wire::encode(piece));
    next_part_ = static_cast<uint8_t>(next_part_ + 1);
    // The text ends with a NUL: a piece with room left. A text of 7k characters takes a last,
    // empty piece.
    if (copied < wire::kObservableTextPartChars) {
      next_part_ = 0;
      ++next_row_;
    }
  }

  struct Slot {
    uint16_t divider = 0;  // 0: stopped
    uint16_t countdown = 0;
    uint8_t count = 0;
    uint8_t id[wire::kStreamObservablesMax] = {};
    wire::SamplePacker packer;
  };
  Slot slots_[wire::kStreamCount];
  uint8_t running_ = 0;    // streams with a divider: the run's quick idle check
  uint8_t next_row_ = 0;   // table rows owed: [next_row_, end_row_)
  uint8_t next_part_ = 0;  // of the row next_row_: 0 its info, k its text piece k-1
  uint8_t end_row_ = 0;
};

}  // namespace qr
