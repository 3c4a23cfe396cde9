// A backward-adaptive linear predictor of one sensor axis for the log's packing: the next sample
// from the last kOrder, with coefficients fitted (Levinson-Durbin on the autocorrelation) to the
// block of kBlockLines samples before (its first 416 to 496: the rest are the fit's, push()).
// Fitted on what was already coded, the coefficients need not be stored: the decoder fits the same
// ones from the same samples, in the same integers.
//
// Why this and not a difference: the motors' vibration (harmonics of each rotor's speed) dominates
// the accelerometer and the gyro in flight. A hover's six raw axes took 68 bits a line as first or
// second differences and 47 with order 16 fitted on the block before (a measurement in floating
// point on 512-sample blocks; order 8: 53).
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

  // `lane` (0..kLanes-1): which of the axes coded together this one is; each fits in turn.
  void set_lane(uint8_t lane) { fit_from_ = static_cast<uint16_t>(kBlockLines - (kLanes - lane) * kOrder); }

  // The sample that came. The block's samples before the fit make the autocorrelation; then
  // each of kOrder samples takes one order of the fit, the lanes one after the other, so a tick
  // does one order of one axis (six whole fits in one tick took 61,000 RV32 instructions: a 1 kHz
  // tick's deadline missed); the new coefficients predict from the next block on.
  [[gnu::noinline]] void push(int16_t x) {
    if (in_block_ < fit_from_) {
      // A history not yet known is zeros (restart()): it adds nothing to the sums.
      autocorrelation_[0] += static_cast<int32_t>(x) * x;
      // Not unrolled: 16 64-bit sums unrolled took 1.1 kB of the QR's flash for a few cycles.
#pragma GCC unroll 1
      for (int l = 1; l <= kOrder; ++l) autocorrelation_[l] += static_cast<int32_t>(x) * history_[l - 1];
    }
    for (int j = kOrder - 1; j > 0; --j) history_[j] = history_[j - 1];
    history_[0] = x;
    if (known_ < kOrder) ++known_;
    ++in_block_;
    if (in_block_ == fit_from_) begin_fit();
    if (in_block_ > fit_from_ && in_block_ <= fit_from_ + kOrder) fit_order(in_block_ - fit_from_);
    if (in_block_ == fit_from_ + kOrder) end_fit();
    if (in_block_ == kBlockLines) in_block_ = 0;
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
  static constexpr int kLanes = 6;
  static constexpr int kQ = 20;
  static constexpr int64_t kOne = int64_t{1} << kQ;

  // Levinson-Durbin in Q20 on the autocorrelation scaled to within 2^24 (the products stay within
  // 2^62), one order a sample. A reflection coefficient at 1 or beyond, or a non-positive error,
  // ends the fit at the order reached; an empty block keeps the coefficients.
  [[gnu::cold, gnu::noinline]] void begin_fit() {
    int64_t r0 = autocorrelation_[0] + (autocorrelation_[0] >> 10);  // a floor: noise the fit cannot model
    int shift = 0;
    while ((r0 >> shift) >= (int64_t{1} << 24)) ++shift;
    for (int l = 0; l <= kOrder; ++l) r_[l] = static_cast<int32_t>((l == 0 ? r0 : autocorrelation_[l]) >> shift);
    for (int64_t& a : a_) a = 0;
    error_ = r_[0];
    fitting_ = r_[0] > 0;
  }
  [[gnu::cold, gnu::noinline]] void fit_order(int i) {
    if (!fitting_) return;
    int64_t acc = r_[i] * kOne;
    for (int j = 1; j < i; ++j) acc -= a_[j] * r_[i - j];
    const int64_t k = acc / error_;
    if (k >= kOne || k <= -kOne) {
      fitting_ = false;
      return;
    }
    int64_t next[kOrder + 1];
    for (int j = 1; j < i; ++j) next[j] = a_[j] - (k * a_[i - j]) / kOne;
    next[i] = k;
    for (int j = 1; j <= i; ++j) a_[j] = next[j];
    error_ -= ((error_ * k) / kOne) * k / kOne;
    if (error_ <= 0) fitting_ = false;
  }
  [[gnu::cold, gnu::noinline]] void end_fit() {
    constexpr int kDrop = kQ - kCoefficientBits;
    if (r_[0] > 0) {
      for (int j = 0; j < kOrder; ++j) {
        const int64_t c = (a_[j + 1] + (int64_t{1} << (kDrop - 1))) >> kDrop;
        coefficient_[j] = static_cast<int16_t>(c > INT16_MAX ? INT16_MAX : c < INT16_MIN ? INT16_MIN : c);
      }
    }
    for (int64_t& a : autocorrelation_) a = 0;
  }

  uint16_t fit_from_ = kBlockLines - kLanes * kOrder;  // the line of the block where this lane's fit begins
  int16_t coefficient_[kOrder] = {};
  int16_t history_[kOrder] = {};
  int64_t autocorrelation_[kOrder + 1] = {};
  uint8_t known_ = 0;
  uint16_t in_block_ = 0;
  // The fit under way in the block's last samples.
  int32_t r_[kOrder + 1] = {};
  int64_t a_[kOrder + 1] = {};
  int64_t error_ = 0;
  bool fitting_ = false;
};

}  // namespace qr::log_pack
