// A serial line with faults, for the fault-injection test: it loses, duplicates and corrupts
// frames and throws in bursts of garbage, all from a seeded generator. It also keeps every frame
// it was given, so the receiving side can be checked: was each accepted frame one that was really
// sent (not a corrupted or made-up one), and which sent frames never arrived.
#pragma once

#include <stdint.h>

#include <array>
#include <deque>
#include <map>
#include <random>
#include <vector>

#include <common/frame.hpp>

namespace wire_test {

struct ChannelFaults {
  double bit_error_rate = 0;  // each bit on the line flips with this probability
  double frame_loss = 0;      // a frame vanishes whole
  double duplicate = 0;       // a frame arrives twice
  double garbage = 0;         // a burst of garbage comes before a frame: random bytes or a cut-off frame
  uint32_t garbage_max_bytes = 64;
};

class SimChannel {
 public:
  SimChannel(const ChannelFaults& faults, uint64_t seed);

  // The sender puts a frame on the line.
  void send(const wire::FrameBytes& frame);

  // Bytes that reached the far end since the last call.
  std::vector<uint8_t> deliver();

  // The receiver reports each frame its parser accepted, in order.
  void accepted(const wire::Frame& frame);

  // Settles the books once the line is quiet: frames never matched are lost.
  void finish();

  uint64_t frames_sent() const { return frames_sent_; }
  uint64_t frames_corrupted() const { return frames_corrupted_; }  // had at least one bit flipped
  uint64_t frames_dropped() const { return frames_dropped_; }
  uint64_t frames_lost() const { return frames_lost_; }  // sent (not dropped) but never accepted
  uint64_t accepted_ok() const { return accepted_ok_; }
  uint64_t accepted_false() const { return accepted_false_; }  // accepted but never sent like that
  uint64_t garbage_bursts() const { return garbage_bursts_; }
  // The most frames lost after one garbage burst, before the next one.
  uint32_t most_lost_after_a_burst() const;

 private:
  struct Sent {
    std::array<uint8_t, wire::kMaxFrameBytes> bytes{};
    uint8_t size = 0;
    uint64_t burst = 0;  // the last garbage burst before this frame (0: none yet)
    bool matched = false;
  };

  void corrupt(std::vector<uint8_t>& bytes, size_t from);
  void settle_front();

  ChannelFaults faults_;
  std::mt19937_64 rng_;
  std::geometric_distribution<uint64_t> bits_to_next_error_;
  uint64_t bits_left_ = 0;
  std::vector<uint8_t> line_;
  std::deque<Sent> window_;  // frames sent and not yet settled, oldest first
  size_t next_ = 0;          // index in window_ after the last matched frame
  std::map<uint64_t, uint32_t> lost_after_burst_;

  uint64_t frames_sent_ = 0, frames_corrupted_ = 0, frames_dropped_ = 0, frames_lost_ = 0;
  uint64_t accepted_ok_ = 0, accepted_false_ = 0, garbage_bursts_ = 0;
};

}  // namespace wire_test
