// What a gyro axis missed while it read full scale. A push that spins the vehicle past the
// gyro's range (±500 deg/s, 8.7 rad/s) clips the samples at ±32767 counts: the angle the
// estimator integrates falls short of the truth by the area above full scale, and only the
// accelerometer can bring it back, through the free-flight drag lag of seconds (a 3 N m, 0.05 s
// roll push left 4.4 deg that took 8 s to go; issue 29).
//
// A clipped sample is known for what it is: the true rate is beyond full scale. While the run
// of clipped samples lasts nothing more is known, but once it has ended the rate's slope going
// in and coming out are, and a rate that rises at s_in until it turns and falls at s_out (a push,
// then the controller's answer) makes a triangle above full scale of n samples, whose peak is
// n s_in s_out / (s_in + s_out) and area half that times n. ClipBridge measures the slopes over
// kSlopeSamples samples each side and returns the area, in counts x samples, kSlopeSamples
// samples after the run ends; the chain adds it to the angle (FlightChain::estimate()).
//
// A model, not a measurement: the controller's answer comes through the motors' lag, so the
// rate falls ever faster and the slope measured coming out overstates the fall before it. In the
// simulator it takes roll pushes' missed 3-9 deg down to within 0.6-1.8 deg (docs/signal-chain.md);
// a finer model (where each line crosses full scale between samples) did worse there, as the
// shape is further from a triangle than that detail is from the samples.
//
// Bounds: a run longer than kMaxRun samples (0.1 s at 1 kHz) is a spin, not a push, and no
// triangle: the bridge adds nothing for it (a capped triangle over such runs left the tilt-push
// landings on drawn vehicles no better, 19 of 30 upright against 21 without the bridge). The
// peak is taken at most one full scale above full scale. A slope that does not point the way
// the clip does (noise, a run too short to measure) gives no area: the bridge adds nothing it
// cannot see. Integers only, the peak formed first (at most 32767) and the area from it: one
// division per run, none per sample.
#pragma once

#include <stdint.h>

namespace qr::chain {

class ClipBridge {
 public:
  static constexpr int32_t kSlopeSamples = 4;  // a power of two: the history is a ring
  static constexpr int32_t kMaxRun = 100;
  static constexpr int32_t kFullScale = 32767;

  // One raw sample; the missed area (counts x samples, the clip's sign) when a run has just been
  // measured, else 0.
  int32_t update(int16_t counts) {
    const int32_t c = counts;
    const int32_t oldest = history_[next_];  // kSlopeSamples samples before this one
    history_[next_] = c;
    next_ = (next_ + 1) & (kSlopeSamples - 1);
    if (c >= kFullScale || c <= -kFullScale) {
      if (run_ == 0) {
        sign_ = c > 0 ? 1 : -1;
        rise_ = sign_ * (c - oldest);  // over kSlopeSamples samples, towards the clip
      }
      if (run_ <= kMaxRun) ++run_;
      after_ = 0;
      return 0;
    }
    if (run_ == 0 || ++after_ < kSlopeSamples) return 0;
    const int32_t fall = sign_ * (sign_ * kFullScale - c);  // over kSlopeSamples samples, away from it
    const int32_t area = run_ > kMaxRun ? 0 : sign_ * triangle(run_, rise_, fall);
    run_ = 0;
    after_ = 0;
    return area;
  }

 private:
  // Area above full scale of n samples rising by `rise` and falling by `fall` per kSlopeSamples.
  static int32_t triangle(int32_t n, int32_t rise, int32_t fall) {
    if (rise <= 0 || fall <= 0) return 0;
    const uint32_t in = static_cast<uint32_t>(rise < kFullScale ? rise : kFullScale);
    const uint32_t out = static_cast<uint32_t>(fall < kFullScale ? fall : kFullScale);
    const uint32_t harmonic = in * out / (in + out);  // < 2^30 / 2^1: fits
    const uint32_t peak = static_cast<uint32_t>(n) * harmonic / kSlopeSamples;
    const uint32_t capped = peak < static_cast<uint32_t>(kFullScale) ? peak : static_cast<uint32_t>(kFullScale);
    return static_cast<int32_t>(static_cast<uint32_t>(n) * capped / 2);  // < 2^7 x 2^15
  }
  int32_t history_[kSlopeSamples] = {};  // the last samples, a ring
  int32_t next_ = 0;                     // where the next goes (the oldest is there)
  int32_t run_ = 0;                      // clipped samples in this run
  int32_t after_ = 0;                    // unclipped samples since it ended
  int32_t rise_ = 0;
  int32_t sign_ = 0;
};

}  // namespace qr::chain
