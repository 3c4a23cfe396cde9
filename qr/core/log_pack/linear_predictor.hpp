// A backward-adaptive linear predictor of one sensor axis for the log's packing: the next sample
// from the last kOrder, with coefficients fitted (Levinson-Durbin on the autocorrelation) to the
// block of kBlockLines samples before. Fitted on what was already coded, the coefficients need not
// be stored: the decoder fits the same ones from the same samples, in the same integers.
//
// Why this and not a difference: the motors' vibration (harmonics of each rotor's speed) dominates
// the accelerometer and the gyro in flight. A hover's six raw axes took 68 bits a line as first or
// second differences and 47 with order 16 fitted on the block before (512 samples; order 8: 53).
// Integers only, wrapping where a damaged area could make them overflow: the encoder and the
// decoder compute the same wrapped values, so a bad prediction costs bits, never a wrong sample.
#pragma once

#include <stdint.h>

namespace qr::log_pack {

class LinearPredictor {
 public:
  static constexpr int kOrder = 16;
  static constexpr uint16_t kBlockLines = 512;
  static constexpr int kCoefficientBits = 12;  // coefficients in Q12, within +-8

  // The prediction of the next sample: the fitted sum once kOrder samples are known, the last
  // sample before that (after a restart).
  [[gnu::noinline]] int32_t predict() const {
    if (known_ < kOrder) return known_ == 0 ? 0 : history_[0];
    uint32_t sum = 1u << (kCoefficientBits - 1);
    for (int j = 0; j < kOrder; ++j) sum += static_cast<uint32_t>(coefficient_[j]) * static_cast<uint32_t>(history_[j]);
    return static_cast<int32_t>(sum) >> kCoefficientBits;
  }

  // The sample that came; at a block's end the coefficients are fitted again.
  [[gnu::noinline]] void push(int16_t x) {
    // A history not yet known is zeros (restart()): it adds nothing to the sums.
    autocorrelation_[0] += int32_t{x} * x;
    // Not unrolled: 16 64-bit sums unrolled took 1.1 kB of the QR's flash for a few cycles.
#pragma GCC unroll 1
    for (int l = 1; l <= kOrder; ++l) autocorrelation_[l] += int32_t{x} * history_[l - 1];
    for (int j = kOrder - 1; j > 0; --j) history_[j] = history_[j - 1];
    history_[0] = x;
    if (known_ < kOrder) ++known_;
    if (++in_block_ == kBlockLines) fit();
  }

  // At a keyframe (where a decoder may start): the history forgotten and a new block begun; the
  // coefficients, all a keyframe keeps of the predictor, stay.
  void restart() {
    known_ = 0;
    for (int16_t& h : history_) h = 0;
    in_block_ = 0;
    for (int64_t& a : autocorrelation_) a = 0;
  }
  using Coefficients = int16_t[kOrder];
  const Coefficients& coefficients() const { return coefficient_; }
  void load(const Coefficients& c) {
    for (int j = 0; j < kOrder; ++j) coefficient_[j] = c[j];
  }

 private:
  // Once a block: cold, so the QR keeps it small rather than fast (a few thousand instructions
  // in 512 lines).
  // Levinson-Durbin in Q20 on the autocorrelation scaled to within 2^24 (the products stay within
  // 2^62). A reflection coefficient at 1 or beyond, or a non-positive error, ends the fit at the
  // order reached; an empty block keeps the coefficients.
  [[gnu::cold, gnu::noinline]] void fit() {
    constexpr int kQ = 20;
    constexpr int64_t kOne = int64_t{1} << kQ;
    int64_t r[kOrder + 1];
    int64_t r0 = autocorrelation_[0] + (autocorrelation_[0] >> 10);  // a floor: noise the fit cannot model
    int shift = 0;
    while ((r0 >> shift) >= (int64_t{1} << 24)) ++shift;
    for (int l = 0; l <= kOrder; ++l) r[l] = (l == 0 ? r0 : autocorrelation_[l]) >> shift;
    for (int64_t& a : autocorrelation_) a = 0;
    in_block_ = 0;
    if (r[0] <= 0) return;

    int64_t a[kOrder + 1] = {};
    int64_t error = r[0];
    for (int i = 1; i <= kOrder; ++i) {
      int64_t acc = r[i] * kOne;
      for (int j = 1; j < i; ++j) acc -= a[j] * r[i - j];
      const int64_t k = acc / error;
      if (k >= kOne || k <= -kOne) break;
      int64_t next[kOrder + 1];
      for (int j = 1; j < i; ++j) next[j] = a[j] - (k * a[i - j]) / kOne;
      next[i] = k;
      for (int j = 1; j <= i; ++j) a[j] = next[j];
      error -= ((error * k) / kOne) * k / kOne;
      if (error <= 0) break;
    }
    constexpr int kDrop = kQ - kCoefficientBits;
    for (int j = 0; j < kOrder; ++j) {
      const int64_t c = (a[j + 1] + (int64_t{1} << (kDrop - 1))) >> kDrop;
      coefficient_[j] = static_cast<int16_t>(c > INT16_MAX ? INT16_MAX : c < INT16_MIN ? INT16_MIN : c);
    }
  }

  int16_t coefficient_[kOrder] = {};
  int16_t history_[kOrder] = {};
  int64_t autocorrelation_[kOrder + 1] = {};
  uint8_t known_ = 0;
  uint16_t in_block_ = 0;
};

}  // namespace qr::log_pack
