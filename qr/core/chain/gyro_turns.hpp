// The gyro's scale, measured by turning the vehicle (parameter gyro_turns): after a calibration's
// rest average, a person turns the vehicle N whole turns about one of its body axes and sets it
// down still. The angle that axis' gyro summed, against the 2 pi N it was turned, is its scale:
// the MPU-6050 allows +-3 % per axis, and a mismatch between axes tilts the attitude estimate of
// a vehicle that yaws while banked (docs/signal-chain.md, "The gyro's scale").
//
// Integers only: each sample adds its raw count minus the rest offset, both with the offset's 9
// fractional bits, to a 64-bit sum per axis. The turn is over once the vehicle, after moving, has
// been still for half a second; it has to be over within a minute.
#pragma once

#include <stdint.h>

#include <qr/core/board.hpp>
#include <qr/core/sensor_scale.hpp>

namespace qr::chain {

// The measured turns may differ from N by at most this (the datasheet's 3 % and a margin); one
// turn more or less than N is at least 10 % off for N <= 10, so a miscounted turn is refused.
inline constexpr int32_t kGyroTurnsTolerancePpm = 80000;
// The other two axes may sum at most this share of the turned one: the turn's axis within 3 deg
// of the body axis, whose cosine then misses the angle by 0.14 % at most.
inline constexpr int32_t kGyroTurnsCrossPpm = 50000;

struct GyroTurnsResult {
  bool found = false;  // a turn of the expected count about one axis
  uint8_t axis = 0;    // 0 x, 1 y, 2 z
  int32_t ppm = 0;     // how much more than nominal that axis read
};

template <uint32_t SampleHz>
class GyroTurns {
 public:
  static constexpr int kFrac = 9;  // the rest offsets' fractional bits (sensor_calibration.hpp)
  // Still: every axis within 1 deg/s of its offset; moving: one beyond 10 deg/s.
  static constexpr int64_t kStill = static_cast<int64_t>(sensor::kGyroCountsPerDegPerSec * (1 << kFrac));
  static constexpr int64_t kMoving = 10 * kStill;
  static constexpr int32_t kStillSamples = static_cast<int32_t>(SampleHz / 2);
  static constexpr int32_t kTimeoutSamples = static_cast<int32_t>(60 * SampleHz);
  // One turn as the sum counts it at the nominal scale: 2 pi rad x counts per rad/s x samples per
  // second, with the offsets' fractional bits (1.2e10 at 1 kHz).
  static constexpr int64_t kTurn = static_cast<int64_t>(
      2 * fx::kPi * sensor::kGyroCountsPerRadPerSec * SampleHz * (1 << kFrac) + 0.5);

  // Starts a measurement of `turns` turns (1 up to the parameter's maximum) against the rest
  // offsets, raw counts with kFrac fractional bits.
  void start(int32_t turns, const int32_t (&offsets)[3]) {
    turns_ = turns;
    for (int i = 0; i < 3; ++i) {
      offset_[i] = offsets[i];
      sum_[i] = 0;
    }
    samples_ = still_ = 0;
    moved_ = false;
    running_ = true;
    result_ = {};
  }
  void cancel() { running_ = false; }
  bool running() const { return running_; }

  // One raw sample; true when the measurement ends, found or not (result()).
  bool add(const SensorSample& s) {
    if (!running_) return false;
    bool still = true;
    for (int i = 0; i < 3; ++i) {
      const int64_t rate = (int64_t{s.gyro[i]} << kFrac) - offset_[i];
      sum_[i] += rate;
      if (rate > kMoving || rate < -kMoving) moved_ = true;
      if (rate > kStill || rate < -kStill) still = false;
    }
    still_ = still ? still_ + 1 : 0;
    ++samples_;
    if (moved_ && still_ >= kStillSamples) {
      finish();
      return true;
    }
    if (samples_ >= kTimeoutSamples) {
      running_ = false;
      return true;
    }
    return false;
  }

  const GyroTurnsResult& result() const { return result_; }

 private:
  // A sample adds less than 2^16 counts (raw minus offset), and a measurement ends within
  // kTimeoutSamples: finish() can scale any sum by 1e6 in 64 bits (2.0e18 at 1 kHz).
  static_assert(int64_t{kTimeoutSamples} * (int64_t{1} << (16 + kFrac)) <= INT64_MAX / 1000000,
                "finish() scales the sums by 1e6 in 64 bits");
  static constexpr int64_t magnitude(int64_t x) { return x < 0 ? -x : x; }

  void finish() {
    running_ = false;
    uint8_t axis = 0;
    for (uint8_t i = 1; i < 3; ++i) {
      if (magnitude(sum_[i]) > magnitude(sum_[axis])) axis = i;
    }
    const int64_t turned = magnitude(sum_[axis]);
    const int64_t expected = kTurn * turns_;
    const int64_t ppm = (turned * 1000000 + expected / 2) / expected - 1000000;
    if (ppm > kGyroTurnsTolerancePpm || ppm < -kGyroTurnsTolerancePpm) return;
    for (uint8_t i = 0; i < 3; ++i) {
      if (i != axis && magnitude(sum_[i]) * 1000000 > turned * kGyroTurnsCrossPpm) return;
    }
    result_ = {true, axis, static_cast<int32_t>(ppm)};
  }

  int64_t sum_[3] = {0, 0, 0};
  int32_t offset_[3] = {0, 0, 0};
  int32_t turns_ = 0;
  int32_t samples_ = 0;
  int32_t still_ = 0;
  bool moved_ = false;
  bool running_ = false;
  GyroTurnsResult result_{};
};

}  // namespace qr::chain
