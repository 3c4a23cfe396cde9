// A few seconds of a tilting vehicle as the sensors would see it, computed with integers only
// (fixed-point sin/cos) so the same samples come out on the host and on the RV32 devboard. It
// feeds the host/devboard checksum (chain_devboard.cpp, chain_checksum_test.cpp) and, written out
// by make_recording, the replay's sample recording in tests/data.
//
// Script: first level and still with lift 0 for 512 samples (the calibration window) plus 0.1 s,
// then, with t in seconds from the end of that:
//   t >= 0    roll swings 0.25 sin(2 pi 0.8 t) rad; lift 450; roll stick follows at 80 %
//   t >= 0.4  an extra roll-gyro drift of +8 counts (2.1e-3 rad/s) for the bias estimate to find
//   t >= 0.6  pitch ramps to 0.15 rad over 0.5 s; pitch stick 600 (0.21 rad)
//   t >= 1.2  yaw turns at 0.5 rad/s; yaw stick 250 (0.5 rad/s at the default max_yaw_rate)
// until t = 1.9 (2512 samples at 1 kHz, 1462 at 500 Hz).
// Sensors: body rates from the Euler rates (p = phi' - psi' sin theta, ...) plus a gyro offset
// (x +40, y -25, z +15 counts); specific force g (sin theta, -sin phi cos theta, -cos phi cos theta) plus an
// accelerometer offset (x +60, y -35, z +90 counts); triangular-ish noise (sum of four uniform
// draws) of +-12 gyro counts and +-80 accelerometer counts.
// Barometer: a reading every 20 ms, held in between: 101325 Pa while still, then falling 6 Pa/s
// (about 0.5 m/s of climb; the accelerometer knows nothing of it, so the height estimate has two
// sensors that disagree, which is all a checksum needs) with +-2 Pa of noise from its own stream,
// so the gyro and accelerometer samples are those of the flight before the barometer.
#pragma once

#include <stdint.h>

#include <fixedpoint/fixedpoint.hpp>
#include <qr/core/board.hpp>
#include <qr/core/flight_types.hpp>

namespace qr::chain::synthetic {

// The QR clock at the first tick of the script (a recording of it starts at 1 s of uptime).
inline constexpr uint32_t kStartUs = 1000000u;

using Angle = fx::Q<28>;
using Unit = fx::Q<30>;  // sin, cos

struct Truth {
  Angle roll, pitch, yaw;  // rad
  Angle p, q, r;           // rad/s (Q<28> holds them)
};

struct Tick {
  SensorSample sample;
  ControlInput sticks;
  Truth truth;
};

// xorshift32: small, fast, and the same sequence everywhere.
class Noise {
 public:
  explicit Noise(uint32_t seed = 2463534242u) : state_(seed) {}
  int32_t next(int32_t half_width) {  // sum of four draws in [-w/4, w/4]
    int32_t sum = 0;
    for (int i = 0; i < 4; ++i) {
      state_ ^= state_ << 13;
      state_ ^= state_ >> 17;
      state_ ^= state_ << 5;
      const uint32_t span = static_cast<uint32_t>(half_width / 2 + 1);
      sum += static_cast<int32_t>(state_ % span) - half_width / 4;
    }
    return sum;
  }

 private:
  uint32_t state_;
};

inline int16_t saturate16(int32_t v) { return static_cast<int16_t>(v > 32767 ? 32767 : v < -32768 ? -32768 : v); }

template <uint32_t SampleHz>
class Flight {
 public:
  static constexpr uint32_t kStill = 512 + SampleHz / 10;
  static constexpr uint32_t kTicks = kStill + SampleHz * 19 / 10;

  // The sample and sticks of tick n (n = 0, 1, 2, ... in order: the noise is a stream).
  Tick next() {
    const uint32_t n = n_++;
    Tick t;
    Truth& v = t.truth;

    // Roll: 0.25 sin(w (t - 0.6)), w = 2 pi 0.8, phase by samples modulo the period.
    Angle roll_rate_of_phi{};
    if (n >= kRollStart) {
      const uint32_t k = (n - kRollStart) % kRollPeriod;
      const Angle phase = kRollPhaseStep * static_cast<int32_t>(k);
      v.roll = fx::narrow<Angle>(fx::mul_wide(kRollAmplitude, fx::sin(phase)));
      roll_rate_of_phi = fx::narrow<Angle>(fx::mul_wide(kRollRateAmplitude, fx::cos(phase)));
    }
    // Pitch: ramp of 0.3 rad/s for 0.5 s from t = 1.2.
    Angle pitch_rate{};
    if (n >= kPitchStart) {
      const uint32_t k = n - kPitchStart;
      if (k < kPitchRamp) {
        v.pitch = kPitchStep * static_cast<int32_t>(k);
        pitch_rate = kPitchRate;
      } else {
        v.pitch = kPitchStep * static_cast<int32_t>(kPitchRamp);
      }
    }
    // Yaw: 0.5 rad/s from t = 1.8.
    Angle yaw_rate{};
    if (n >= kYawStart) {
      yaw_rate = kYawRate;
      yaw_ = yaw_ + kYawStep;
      if (!(yaw_ < kPi)) yaw_ = yaw_ - kTwoPi;
    }
    v.yaw = yaw_;

    const Unit sr = fx::sin(v.roll), cr = fx::cos(v.roll), sp = fx::sin(v.pitch), cp = fx::cos(v.pitch);
    // Body rates from Euler rates (Z-Y-X).
    v.p = roll_rate_of_phi - fx::narrow<Angle>(fx::mul_wide(yaw_rate, sp));
    v.q = fx::narrow<Angle>(fx::mul_wide(pitch_rate, cr) +
                            fx::mul_wide(fx::narrow<Angle>(fx::mul_wide(yaw_rate, sr)), cp));
    v.r = fx::narrow<Angle>(fx::mul_wide(fx::narrow<Angle>(fx::mul_wide(yaw_rate, cr)), cp) -
                            fx::mul_wide(pitch_rate, sr));

    const int32_t drift = n >= kDriftStart ? 8 : 0;
    t.sample.gyro[0] = saturate16(gyro_counts(v.p) + 40 + drift + noise_.next(12));
    t.sample.gyro[1] = saturate16(gyro_counts(v.q) - 25 + noise_.next(12));
    t.sample.gyro[2] = saturate16(gyro_counts(v.r) + 15 + noise_.next(12));
    // Specific force g (sin theta, -sin phi cos theta, -cos phi cos theta).
    t.sample.accel[0] = saturate16(g_counts(sp) + 60 + noise_.next(80));
    t.sample.accel[1] = saturate16(-g_counts(fx::narrow<Unit>(fx::mul_wide(sr, cp))) - 35 + noise_.next(80));
    t.sample.accel[2] = saturate16(-g_counts(fx::narrow<Unit>(fx::mul_wide(cr, cp))) + 90 + noise_.next(80));
    t.sample.battery_mv = static_cast<uint16_t>(11800 - n / 100);
    if (n % kBaroDivider == 0) {
      const int32_t climbing = n >= kRollStart ? static_cast<int32_t>(n - kRollStart) : 0;
      pressure_pa_ = 101325 - climbing * 6 / static_cast<int32_t>(SampleHz) + baro_noise_.next(4);
    }
    t.sample.pressure_pa = pressure_pa_;

    if (n >= kRollStart) {
      t.sticks.lift = 450;
      // The vehicle's roll as a stick, 2286 per rad (80 % of it when full stick was 0.35 rad; at the
      // 0.524 rad max_tilt_mrad default the set-point is 1.2 times the roll). The script is fixed.
      t.sticks.roll = saturate16(fx::narrow<fx::Q<0>>(fx::mul_wide(v.roll, kRollStickPerRad)).raw());
    }
    if (n >= kPitchStart) t.sticks.pitch = 600;
    if (n >= kYawStart) t.sticks.yaw = 250;
    return t;
  }

 private:
  static constexpr double kPiD = 3.14159265358979323846;
  static constexpr uint32_t kRollStart = kStill;
  static constexpr uint32_t kRollPeriod = SampleHz * 5 / 4;  // 0.8 Hz
  static constexpr uint32_t kDriftStart = kStill + SampleHz * 2 / 5;
  static constexpr uint32_t kPitchStart = kStill + SampleHz * 3 / 5;
  static constexpr uint32_t kPitchRamp = SampleHz / 2;
  static constexpr uint32_t kYawStart = kStill + SampleHz * 6 / 5;
  static constexpr uint32_t kBaroDivider = SampleHz / 50;  // a reading every 20 ms

  static constexpr Angle kRollPhaseStep = Angle(2 * kPiD / kRollPeriod);
  static constexpr Angle kRollAmplitude = Angle(0.25);
  static constexpr Angle kRollRateAmplitude = Angle(0.25 * 2 * kPiD * 0.8);
  static constexpr Angle kPitchRate = Angle(0.3);
  static constexpr Angle kPitchStep = Angle(0.3 / SampleHz);
  static constexpr Angle kYawRate = Angle(0.5);
  static constexpr Angle kYawStep = Angle(0.5 / SampleHz);
  static constexpr Angle kPi = Angle(kPiD);
  static constexpr Angle kTwoPi = Angle(2 * kPiD);
  static constexpr fx::Q<19> kGyroCountsPerRad = fx::Q<19>(65.5 * 180.0 / kPiD);
  static constexpr fx::Q<0> kCountsPerG = fx::Q<0>(8192.0);
  static constexpr fx::Q<16> kRollStickPerRad = fx::Q<16>(0.8 * 1000.0 / 0.35);

  static int32_t gyro_counts(Angle rate) { return fx::narrow<fx::Q<0>>(fx::mul_wide(rate, kGyroCountsPerRad)).raw(); }
  static int32_t g_counts(Unit u) { return fx::narrow<fx::Q<0>>(fx::mul_wide(u, kCountsPerG)).raw(); }

  uint32_t n_ = 0;
  Angle yaw_{};
  Noise noise_;
  Noise baro_noise_{123456789u};
  int32_t pressure_pa_ = 0;
};

}  // namespace qr::chain::synthetic
