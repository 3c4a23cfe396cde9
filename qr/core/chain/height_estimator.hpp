// Height and vertical speed from the barometer and the accelerometer: a third-order
// complementary filter (the baro-inertial loop), with the accelerometer's vertical bias as its
// third state. Per run, at kHeightHz:
//
//   a     = -(f_down + 1 g) g0                vertical acceleration, up, m/s²: the calibrated
//                                             specific force turned to the earth frame by the
//                                             attitude estimate, minus gravity
//   e     = h_baro - h                        the barometer's height against the estimate
//   b     = b - k3 e dt                       an accelerometer reading high makes h run ahead: e < 0, b up
//   v     = v + (a - b + k2 e) dt
//   h     = h + (v + k1 e) dt
//
// The error dynamics are s³ + k1 s² + k2 s + k3; with k1 = 3/τ, k2 = 3/τ², k3 = 1/τ³ all three
// poles sit at -1/τ (critically damped, one number to choose). Above 1/τ the height and speed are
// the integrated accelerometer, below it the barometer; a constant accelerometer error is taken
// out by b, with no steady height error. docs/signal-chain.md has why this and not a Kalman filter,
// and the figures that chose τ.
//
// Heights are relative to the pressure at calibration (zero_reference()): the barometer's height
// is (p_ref - p) times the standard atmosphere's metres per pascal at p_ref (isa_table.hpp),
// formed once, so a run only multiplies and adds. A pressure of 0 means no barometer
// (board.hpp): with no reading at calibration there is no reference and the estimate stays 0
// (has_reference() false); a 0 in flight skips the correction for that run (the estimate coasts
// on the accelerometer).
//
// Fixed point: the height and speed are kept as exact sums of their increments (Wide<48> for
// FixedNumbers, +-32768 m and m/s), so a small speed still moves the height; the bias rounds to
// its Q<24> (6e-8 m/s²) each run, far below what the loop resolves.
#pragma once

#include <stdint.h>

#include <qr/core/chain/isa_table.hpp>
#include <qr/core/chain/numeric.hpp>
#include <qr/core/chain/sensor_calibration.hpp>

namespace qr::chain {

// The filter's time constant, ms: docs/signal-chain.md has the measurements that chose it.
inline constexpr uint32_t kHeightTauMs = 1000;

template <class N, uint32_t RunHz, uint32_t TauMs = kHeightTauMs>
class HeightEstimator {
 public:
  using Accel = typename N::Accel;
  using Angle = typename N::Angle;
  using Height = typename N::Height;
  using Climb = typename N::Climb;
  using VerticalAccel = typename N::VerticalAccel;
  using Pressure = typename N::Pressure;

  // Beyond this the bias is clamped: the accelerometer's offsets are calibrated and its scale is
  // within 3 %, so 2 m/s² is a broken sensor or a crash, not a bias to learn.
  static constexpr VerticalAccel kMaxBias = VerticalAccel(2.0);

  // ---- calibration: the reference pressure ----
  void restart_calibration() {
    pressure_sum_ = 0;
    count_ = 0;
    absent_ = false;
  }
  // One raw reading; the first kCalibrationSamples count (as SensorCalibration's).
  void add_calibration(int32_t pressure_pa) {
    if (count_ >= kCalibrationSamples) return;
    if (pressure_pa <= 0) absent_ = true;
    pressure_sum_ += clamp_pressure(pressure_pa);
    ++count_;
  }
  // The calibration run has finished: its average pressure is height 0, the speed and bias start
  // at 0. Without a barometer in every sample there is no reference.
  void zero_reference() {
    has_reference_ = !absent_ && count_ == kCalibrationSamples;
    height_sum_ = {};
    climb_sum_ = {};
    height_ = {};
    climb_ = {};
    bias_ = {};
    baro_height_ = {};
    if (!has_reference_) return;
    // The average in Pressure's format: sum / 2^9 = sum x 2^(14 - 9) raw (fits: < 2^31 for
    // pressures below 2^17 Pa, clamp_pressure).
    reference_ = N::template fixed<kPressureFrac>(pressure_sum_ * (int32_t{1} << (kPressureFrac - kCalibrationShift)));
    metres_per_pa_ = gradient_at(pressure_sum_ >> kCalibrationShift);
  }

  // ---- one run ----
  // accel: calibrated, filtered specific force (g), body x y z; roll, pitch: the attitude
  // estimate; pressure_pa: the board's latest reading (0: none).
  void update(const Accel (&accel)[3], Angle roll, Angle pitch, int32_t pressure_pa) {
    if (!has_reference_) return;
    const VerticalAccel up = vertical_acceleration(accel, roll, pitch);
    Height e{};
    if (pressure_pa > 0) {
      baro_height_ = N::template convert<Height>(fx::mul_wide(
          reference_ - N::template fixed<kPressureFrac>(clamp_pressure(pressure_pa) << kPressureFrac), metres_per_pa_));
      e = baro_height_ - height_;
    }
    bias_ = clamp(bias_ - N::template convert<VerticalAccel>(fx::mul_wide(e, kK3Dt)), -kMaxBias, kMaxBias);
    climb_sum_ += fx::mul_wide(up - bias_ + N::template convert<VerticalAccel>(fx::mul_wide(e, kK2)), kDt);
    climb_ = N::template convert<Climb>(climb_sum_);
    height_sum_ += fx::mul_wide(climb_ + N::template convert<Climb>(fx::mul_wide(e, kK1)), kDt);
    height_ = N::template convert<Height>(height_sum_);
    accel_up_ = up;
  }

  bool has_reference() const { return has_reference_; }
  Height height() const { return height_; }                   // m, up, from the calibration's height
  Climb climb() const { return climb_; }                      // m/s, up
  VerticalAccel accel_bias() const { return bias_; }          // m/s², what the accelerometer reads too high
  VerticalAccel vertical_accel() const { return accel_up_; }  // m/s², up, as measured (bias not removed)
  Height baro_height() const { return baro_height_; }         // m, the barometer's own
  Pressure reference() const { return reference_; }           // Pa

 private:
  using Unit = typename N::Coefficient;  // sin, cos: Q<30>
  using Gain = typename N::HeightGain;
  using Step = typename N::HeightStep;
  static constexpr int kPressureFrac = N::kPressureFrac;
  static constexpr int32_t kMaxPressurePa = (int32_t{1} << (31 - kPressureFrac)) - 1;

  // k1 = 3/tau, k2 = 3/tau², k3 dt = dt/tau³, with tau = TauMs / 1000 s (compile-time constants).
  static constexpr Gain kK1 = Gain(3.0e3 / TauMs);
  static constexpr Gain kK2 = Gain(3.0e6 / TauMs / TauMs);
  static constexpr typename N::Scale kK3Dt = typename N::Scale(1.0e9 / TauMs / TauMs / TauMs / RunHz);
  static constexpr Step kDt = Step(1.0 / RunHz);
  static constexpr Accel kOneG = Accel(1.0);
  static constexpr Accel kMinusG0 = Accel(-9.80665);  // standard gravity, m/s² per g
  static constexpr Unit kOne = Unit(1.0), kHalf = Unit(1.0 / 2), kSixth = Unit(1.0 / 6), kTwentyFourth = Unit(1.0 / 24);
  static constexpr isa::Gradient<Unit> kGradient = isa::gradient_table<Unit>();

  static int32_t clamp_pressure(int32_t pa) { return pa < 0 ? 0 : pa > kMaxPressurePa ? kMaxPressurePa : pa; }

  // |dh/dp| at `pa`, interpolated in the table (at calibration only: one division).
  static Unit gradient_at(int32_t pa) {
    const int32_t low = isa::kTableLowPa, last = isa::kTableLowPa + (isa::kTableSize - 1) * isa::kTableStepPa;
    const int32_t p = pa < low ? low : pa > last ? last : pa;
    int32_t i = (p - low) / isa::kTableStepPa;
    if (i > isa::kTableSize - 2) i = isa::kTableSize - 2;
    const auto fraction = N::template ratio<typename N::Scale>(p - low - i * isa::kTableStepPa, isa::kTableStepPa);
    const Unit a = kGradient.at[i], b = kGradient.at[i + 1];
    return a + product<Unit>(b - a, fraction);
  }

  // The earth frame's down component of the specific force (Z-Y-X Euler angles):
  // f_down = -sin(pitch) f_x + sin(roll) cos(pitch) f_y + cos(roll) cos(pitch) f_z, then the
  // acceleration up. sin and cos by their series (sin to x³, cos to x⁴) on angles clamped to
  // +-1 rad: at 20° the cosines are off by 2e-6, which is 2e-5 m/s² of acceleration. Past the
  // clamp the vehicle is falling, not flying.
  static VerticalAccel vertical_acceleration(const Accel (&f)[3], Angle roll, Angle pitch) {
    const Angle limit = Angle(1.0);
    const Unit r = N::template convert<Unit>(clamp(roll, -limit, limit));
    const Unit t = N::template convert<Unit>(clamp(pitch, -limit, limit));
    const Unit r2 = product<Unit>(r, r), t2 = product<Unit>(t, t);
    const Unit sin_r = product<Unit>(r, kOne - product<Unit>(r2, kSixth));
    const Unit sin_t = product<Unit>(t, kOne - product<Unit>(t2, kSixth));
    const Unit cos_r = kOne - product<Unit>(r2, kHalf - product<Unit>(r2, kTwentyFourth));
    const Unit cos_t = kOne - product<Unit>(t2, kHalf - product<Unit>(t2, kTwentyFourth));
    const Accel down = N::template convert<Accel>(fx::mul_wide(f[1], product<Unit>(sin_r, cos_t)) +
                                                  fx::mul_wide(f[2], product<Unit>(cos_r, cos_t)) -
                                                  fx::mul_wide(f[0], sin_t));
    return N::template convert<VerticalAccel>(fx::mul_wide(down + kOneG, kMinusG0));
  }

  using Sum = decltype(fx::mul_wide(Climb{}, Step{}));
  static_assert(fx::detail::is_same<Sum, decltype(fx::mul_wide(VerticalAccel{}, Step{}))>,
                "speed and height increments add in the same wide format");

  int32_t pressure_sum_ = 0;
  int32_t count_ = 0;
  bool absent_ = false;
  bool has_reference_ = false;
  Pressure reference_{};
  Unit metres_per_pa_{};
  Sum height_sum_{}, climb_sum_{};
  Height height_{}, baro_height_{};
  Climb climb_{};
  VerticalAccel bias_{}, accel_up_{};
};

}  // namespace qr::chain
