// The autotune's identification flight (docs/signal-chain.md, "Autotune"): while the loops hover
// the vehicle in full control, a pseudo-random binary sequence (PRBS) is added to one axis' moment
// at a time, roll, then pitch, then yaw. What the mixer was asked for and the rate the loops saw,
// at the control rate, are what the fit on the host (tune/) reads: the roll_moment and p
// observables, pitch_moment and q, yaw_moment and r.
//
// Why a PRBS: its power is spread evenly up to about a third of its bit rate (here 50 bits/s:
// flat to about 17 Hz, where the motors' lag and the delays that limit the loops show), it is two
// levels only, so its amplitude bounds the moment it adds and the angle it can move the vehicle
// (the loops answer it, so the vehicle stays within a few degrees), and it is made by a shift
// register: no multiplication, no table, the same sequence every flight. A chirp sweeps one
// frequency at a time (a long flight for the same information); a relay finds one point of the
// loop's response (the crossover), not the motors' lag and the delay apart.
#pragma once

#include <stdint.h>

namespace qr::chain {

template <class Thrust, uint32_t SampleHz>
class IdentificationSequence {
 public:
  static constexpr uint8_t kAxes = 3;                    // roll, pitch, yaw
  static constexpr uint32_t kQuietTicks = SampleHz / 2;  // 0.5 s before each axis: the loops settle
  static constexpr uint32_t kBitTicks = SampleHz / 50;   // 20 ms a bit
  static constexpr uint32_t kBits = 127;                 // a 7-bit register's whole period: 2.54 s
  static constexpr uint32_t kAxisTicks = kQuietTicks + kBits * kBitTicks;
  static constexpr uint32_t kTicks = kAxes * kAxisTicks;  // 9.1 s in all

  // The moment added on each axis: `tilt` to roll and pitch, `yaw` to yaw (thrust units).
  constexpr IdentificationSequence(Thrust tilt, Thrust yaw) : amplitude_{tilt, tilt, yaw} {}

  void start() {
    tick_ = 0;
    register_ = kSeed;
  }
  // The axis excited now (0 roll, 1 pitch, 2 yaw); kAxes once the sequence is over.
  uint8_t axis() const { return static_cast<uint8_t>(tick_ / kAxisTicks); }
  bool done() const { return tick_ >= kTicks; }

  // One tick: the moment to add to axis() (zero while quiet and once done). Each axis starts the
  // register from the same seed, so each sees the same sequence.
  Thrust step() {
    if (done()) return Thrust{};
    const uint32_t in_axis = tick_ % kAxisTicks;
    const uint8_t a = axis();
    ++tick_;
    if (in_axis < kQuietTicks) {
      register_ = kSeed;
      return Thrust{};
    }
    const uint32_t into = in_axis - kQuietTicks;
    if (into != 0 && into % kBitTicks == 0) advance();
    return (register_ & 1u) != 0 ? amplitude_[a] : -amplitude_[a];
  }

 private:
  // x^7 + x^6 + 1, a maximal-length Fibonacci register (period 2^7 - 1 = 127).
  static constexpr uint8_t kSeed = 0x5B;
  void advance() {
    const uint32_t r = register_;
    const uint32_t bit = ((r >> 6) ^ (r >> 5)) & 1u;
    register_ = static_cast<uint8_t>(((r << 1) | bit) & 0x7Fu);
  }

  Thrust amplitude_[kAxes];
  uint32_t tick_ = kTicks;    // not started: done
  uint8_t register_ = kSeed;  // 7 bits
};

}  // namespace qr::chain
