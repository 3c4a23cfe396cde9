#include "sim_channel.hpp"

#include <algorithm>

namespace wire_test {

namespace {
// How far ahead of the last matched frame an accepted frame is looked for. Frames are delivered
// in order within a millisecond tick, so only a handful are ever in flight.
constexpr size_t kMatchWindow = 64;
}  // namespace

SimChannel::SimChannel(const ChannelFaults& faults, uint64_t seed)
    : faults_(faults), rng_(seed), bits_to_next_error_(faults.bit_error_rate > 0 ? faults.bit_error_rate : 0.5) {
  bits_left_ = faults_.bit_error_rate > 0 ? bits_to_next_error_(rng_) : UINT64_MAX;
}

void SimChannel::corrupt(std::vector<uint8_t>& bytes, size_t from) {
  if (faults_.bit_error_rate <= 0) return;
  // Bit errors as a stream over everything on the line: draw the gap to the next error instead
  // of a coin per bit.
  uint64_t bits = (bytes.size() - from) * 8;
  uint64_t at = 0;
  while (bits_left_ < bits - at) {
    at += bits_left_;
    bytes[from + at / 8] = static_cast<uint8_t>(bytes[from + at / 8] ^ (0x80u >> (at % 8)));
    at += 1;
    bits_left_ = bits_to_next_error_(rng_);
  }
  bits_left_ -= bits - at;
}

void SimChannel::send(const wire::FrameBytes& frame) {
  std::uniform_real_distribution<double> chance(0.0, 1.0);
  const int copies = chance(rng_) < faults_.duplicate ? 2 : 1;
  for (int copy = 0; copy < copies; ++copy) {
    if (faults_.garbage > 0 && chance(rng_) < faults_.garbage) {
      if (chance(rng_) < 0.5) {
        // Line noise: random bytes.
        const uint32_t n = std::uniform_int_distribution<uint32_t>(1, faults_.garbage_max_bytes)(rng_);
        for (uint32_t i = 0; i < n; ++i) line_.push_back(static_cast<uint8_t>(rng_()));
      } else {
        // A frame cut off part-way (the sender restarted): a real start and type, whose expected
        // length runs into the frames after it.
        const unsigned n = std::uniform_int_distribution<unsigned>(2, frame.size - 1u)(rng_);
        line_.insert(line_.end(), frame.bytes, frame.bytes + n);
      }
      ++garbage_bursts_;
    }
    Sent sent;
    std::copy(frame.bytes, frame.bytes + frame.size, sent.bytes.begin());
    sent.size = frame.size;
    sent.burst = garbage_bursts_;
    ++frames_sent_;
    if (chance(rng_) < faults_.frame_loss) {
      ++frames_dropped_;
      continue;  // never on the line, so not in the books as "lost by the receiver" either
    }
    const size_t from = line_.size();
    line_.insert(line_.end(), frame.bytes, frame.bytes + frame.size);
    corrupt(line_, from);
    if (!std::equal(line_.begin() + static_cast<std::ptrdiff_t>(from), line_.end(), frame.bytes)) ++frames_corrupted_;
    window_.push_back(sent);
  }
}

std::vector<uint8_t> SimChannel::deliver() {
  std::vector<uint8_t> out;
  out.swap(line_);
  return out;
}

void SimChannel::accepted(const wire::Frame& frame) {
  const wire::FrameBytes bytes = wire::make_frame(frame.type, frame.payload, frame.length);
  const size_t end = std::min(window_.size(), next_ + kMatchWindow);
  for (size_t i = next_; i < end; ++i) {
    Sent& s = window_[i];
    if (s.size == bytes.size && std::equal(s.bytes.begin(), s.bytes.begin() + s.size, bytes.bytes)) {
      s.matched = true;
      next_ = i + 1;
      ++accepted_ok_;
      settle_front();
      return;
    }
  }
  ++accepted_false_;
}

// Frames the receiver has gone past without accepting are lost; forget them.
void SimChannel::settle_front() {
  while (next_ > 0) {
    const Sent& s = window_.front();
    if (!s.matched) {
      ++frames_lost_;
      if (s.burst > 0) ++lost_after_burst_[s.burst];
    }
    window_.pop_front();
    --next_;
  }
}

void SimChannel::finish() {
  next_ = window_.size();
  settle_front();
}

uint32_t SimChannel::most_lost_after_a_burst() const {
  uint32_t most = 0;
  for (const auto& [burst, lost] : lost_after_burst_) most = std::max(most, lost);
  return most;
}

}  // namespace wire_test
