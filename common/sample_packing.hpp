// Samples into observable_samples frames and back (docs/protocol.md section 13.3). The QR packs
// each stream's samples, whole samples to a frame; the PC, knowing what it asked each stream for,
// unpacks them and counts the samples lost in frames that did not arrive.
#pragma once

#include <stdint.h>

#include <common/observable_messages.hpp>

namespace wire {

// One stream's packing on the QR: add() a sample at a time; when a frame is full it is handed out.
class SamplePacker {
 public:
  void start(uint8_t stream, uint8_t observables) {
    stream_ = stream;
    observables_ = observables;
    per_frame_ = samples_per_frame(observables);
    held_ = 0;
    sequence_ = 0;
  }
  // `values`: one sample, `observables` of them. True when `out` is a full frame to send.
  bool add(const int16_t* values, ObservableSamples& out) {
    if (per_frame_ == 0) return false;
    for (uint8_t i = 0; i < observables_; ++i) frame_.value[held_ * observables_ + i] = values[i];
    if (++held_ < per_frame_) return false;
    frame_.header = sample_header(stream_, sequence_);
    sequence_ = static_cast<uint8_t>((sequence_ + 1) % kSampleSequenceModulo);
    out = frame_;
    frame_ = ObservableSamples{};
    held_ = 0;
    return true;
  }

 private:
  ObservableSamples frame_{};
  uint8_t stream_ = 0;
  uint8_t observables_ = 0;
  uint8_t per_frame_ = 0;
  uint8_t held_ = 0;
  uint8_t sequence_ = 0;
};

// One stream's unpacking on the PC. `lost` counts samples in frames that never came (from the gaps
// in the frame sequence; a gap of 64 frames or more is indistinguishable from none).
class SampleUnpacker {
 public:
  void start(uint8_t observables) {
    observables_ = observables;
    per_frame_ = samples_per_frame(observables);
    expected_ = 0;
    started_ = false;
    lost_ = 0;
    received_ = 0;
  }
  uint8_t observables() const { return observables_; }
  uint8_t per_frame() const { return per_frame_; }
  uint32_t lost() const { return lost_; }
  uint32_t received() const { return received_; }

  // Calls sample(values) for each sample of the frame, `observables()` values each, in order.
  // Frames of a stream nobody started give nothing.
  template <class Sample>
  uint8_t unpack(const ObservableSamples& frame, Sample&& sample) {
    if (per_frame_ == 0) return 0;
    const uint8_t sequence = frame.sequence();
    if (started_) {
      const uint8_t gap = static_cast<uint8_t>((sequence - expected_ + kSampleSequenceModulo) % kSampleSequenceModulo);
      lost_ += static_cast<uint32_t>(gap) * per_frame_;
    }
    started_ = true;
    expected_ = static_cast<uint8_t>((sequence + 1) % kSampleSequenceModulo);
    for (uint8_t s = 0; s < per_frame_; ++s) sample(&frame.value[s * observables_]);
    received_ += per_frame_;
    return per_frame_;
  }

 private:
  uint8_t observables_ = 0;
  uint8_t per_frame_ = 0;
  uint8_t expected_ = 0;
  bool started_ = false;
  uint32_t lost_ = 0;
  uint32_t received_ = 0;
};

}  // namespace wire
