// The engine mapping: signs of each moment on the "+" layout, the inverse of the quadratic rotor
// model round-tripping, the idle floor, and saturation that keeps the moments' balance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <qr/core/chain/engine_mixer.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/host/real_numbers.hpp>

#include "chain_test_support.hpp"

namespace qr::chain {
namespace {

using F = FixedNumbers;
using D = DoubleNumbers;

template <class N>
EngineMixer<N> mixer(int32_t idle = 180) {
  EngineMixer<N> m;
  m.set_idle(idle);
  return m;
}

template <class N>
Moments<typename N::Thrust> moments(double roll, double pitch, double yaw) {
  if constexpr (fx::is_q<typename N::Thrust>) {
    using T = typename N::Thrust;
    return {test::quantise<T>(roll), test::quantise<T>(pitch), test::quantise<T>(yaw)};
  } else {
    return {roll, pitch, yaw};
  }
}

// The forward model (docs/conventions.md) in thrust units: w_i = ae_i^2 / 1000.
struct Forces {
  double lift, roll, pitch, yaw;
};
Forces forces_of(const EngineCommand& e) {
  double w[4];
  for (int i = 0; i < 4; ++i) w[i] = e.value[i] * double(e.value[i]) / 1000;
  return {w[0] + w[1] + w[2] + w[3], w[3] - w[1], w[0] - w[2], w[1] + w[3] - w[0] - w[2]};
}

TEST(EngineMixer, NoMomentsGiveEveryEngineTheLift) {
  auto m = mixer<F>();
  for (const uint16_t lift :
       {uint16_t{180}, uint16_t{181}, uint16_t{300}, uint16_t{500}, uint16_t{999}, uint16_t{1000}}) {
    const EngineCommand e = m.mix(lift, moments<F>(0, 0, 0));
    for (const uint16_t v : e.value) EXPECT_EQ(v, lift);
  }
}

TEST(EngineMixer, LiftZeroStopsTheEnginesWhateverTheMoments) {
  auto m = mixer<F>();
  EXPECT_TRUE(m.mix(0, moments<F>(300, -200, 100)).all_zero());
}

// Engine order 0 front, 1 right, 2 back, 3 left.
TEST(EngineMixer, PositiveRollMomentRaisesLeftAndLowersRight) {
  auto m = mixer<F>();
  const EngineCommand e = m.mix(500, moments<F>(50, 0, 0));
  EXPECT_GT(e.value[3], 500);
  EXPECT_LT(e.value[1], 500);
  EXPECT_EQ(e.value[0], 500);
  EXPECT_EQ(e.value[2], 500);
}

TEST(EngineMixer, PositivePitchMomentRaisesFrontAndLowersBack) {
  auto m = mixer<F>();
  const EngineCommand e = m.mix(500, moments<F>(0, 50, 0));
  EXPECT_GT(e.value[0], 500);
  EXPECT_LT(e.value[2], 500);
  EXPECT_EQ(e.value[1], 500);
  EXPECT_EQ(e.value[3], 500);
}

TEST(EngineMixer, PositiveYawMomentSpeedsUpTheCounterClockwisePair) {
  auto m = mixer<F>();
  const EngineCommand e = m.mix(500, moments<F>(0, 0, 50));
  EXPECT_GT(e.value[1], 500);
  EXPECT_GT(e.value[3], 500);
  EXPECT_LT(e.value[0], 500);
  EXPECT_LT(e.value[2], 500);
  EXPECT_EQ(e.value[1], e.value[3]);
  EXPECT_EQ(e.value[0], e.value[2]);
}

// Engines -> lift and moments (forward model) -> engines (the mixer) gives the engines back: the
// mixer is the model's inverse. Exactly, in Q too: the rounding of the moments and the root stays
// far below the half unit that would change a whole engine value.
template <class N>
int round_trip_worst(int32_t idle) {
  auto m = mixer<N>(idle);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> engine(idle, 1000);
  int worst = 0;
  for (int i = 0; i < 100000; ++i) {
    EngineCommand e;
    for (uint16_t& v : e.value) v = static_cast<uint16_t>(engine(rng));
    const Forces f = forces_of(e);
    typename N::Thrust per_engine;
    if constexpr (fx::is_q<typename N::Thrust>) {
      per_engine = test::quantise<typename N::Thrust>(f.lift / 4);
    } else {
      per_engine = f.lift / 4;
    }
    const EngineCommand back = m.mix_thrust(per_engine, moments<N>(f.roll, f.pitch, f.yaw));
    for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(back.value[k] - e.value[k]));
  }
  return worst;
}

TEST(EngineMixer, InverseOfTheQuadraticModelRoundTrips) {
  const int fixed = round_trip_worst<F>(180), fixed_no_idle = round_trip_worst<F>(0);
  const int reference = round_trip_worst<D>(180);
  std::printf("  engines -> forces -> engines, worst difference: Q %d (idle 180), %d (idle 0); double %d\n", fixed,
              fixed_no_idle, reference);
  EXPECT_EQ(fixed, 0);
  EXPECT_EQ(fixed_no_idle, 0);
  EXPECT_EQ(reference, 0);
}

TEST(EngineMixer, NoEngineBelowIdleWhileLiftIsAboveZero) {
  for (const int32_t idle : {0, 180, 350, 500}) {
    auto m = mixer<F>(idle);
    std::mt19937_64 rng(static_cast<uint64_t>(idle));
    std::uniform_int_distribution<int> lift(1, 1000);
    std::uniform_real_distribution<double> moment(-1000, 1000);
    for (int i = 0; i < 50000; ++i) {
      const EngineCommand e = m.mix(static_cast<uint16_t>(lift(rng)),
                                    moments<F>(moment(rng), moment(rng), moment(rng)));
      for (const uint16_t v : e.value) {
        ASSERT_GE(v, idle);
        ASSERT_LE(v, 1000);
      }
    }
  }
}

// Moments too large for the engines: what is realised has the ratios asked for (all three scaled
// by one factor), and the engines' forward model shows the realised moments.
TEST(EngineMixer, SaturationKeepsTheMomentsBalance) {
  auto m = mixer<F>();
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> lift(150, 1000);
  std::uniform_real_distribution<double> moment(-1000, 1000);
  int scaled = 0;
  double worst_ratio = 0, worst_forces = 0;
  for (int i = 0; i < 50000; ++i) {
    const double L = moment(rng), M = moment(rng) / 2, N = moment(rng) / 4;
    const auto wanted = moments<F>(L, M, N);
    const EngineCommand e = m.mix(static_cast<uint16_t>(lift(rng)), wanted);
    const auto& applied = m.applied();
    // The common factor, from the largest moment asked for (L here: |L| is up to 1000, |M| 500).
    const double s = applied.roll.to_double() / wanted.roll.to_double();
    if (std::fabs(L) < 100) continue;
    ASSERT_GE(s, 0.0);
    ASSERT_LE(s, 1 + 1e-6);
    if (s < 0.999) ++scaled;
    // Same factor on every axis, to the rounding of the scaled moments and of s itself.
    worst_ratio = std::max(worst_ratio, std::fabs(applied.pitch.to_double() - s * wanted.pitch.to_double()));
    worst_ratio = std::max(worst_ratio, std::fabs(applied.yaw.to_double() - s * wanted.yaw.to_double()));
    // The engines, rounded to whole units, realise the applied moments: d(w)/d(ae) = 2 ae / 1000
    // is at most 2 per engine unit, and each moment involves two or four engines.
    const Forces f = forces_of(e);
    worst_forces = std::max(worst_forces, std::fabs(f.roll - applied.roll.to_double()));
    worst_forces = std::max(worst_forces, std::fabs(f.pitch - applied.pitch.to_double()));
    worst_forces = std::max(worst_forces, std::fabs(f.yaw - applied.yaw.to_double()) / 2);
  }
  std::printf(
      "  %d of 50000 mixes scaled; moments off the common factor by %.2e; engines realise the applied "
      "moments within %.3f thrust units\n",
      scaled, worst_ratio, worst_forces);
  EXPECT_GT(scaled, 10000);
  EXPECT_LE(worst_ratio, 1e-4);
  EXPECT_LE(worst_forces, 2.0);
}

// Near full throttle the lift gives way and the moment is realised in full.
TEST(EngineMixer, AtTheTopLiftGivesWayToTheMoments) {
  auto m = mixer<F>();
  const EngineCommand e = m.mix(990, moments<F>(100, 0, 0));
  EXPECT_NEAR(m.applied().roll.to_double(), 100.0, 1e-3);
  EXPECT_EQ(e.value[3], 1000);
  const Forces f = forces_of(e);
  EXPECT_LT(f.lift, 4 * 990.0 * 990.0 / 1000);  // less lift than asked
  EXPECT_NEAR(f.roll, 100.0, 2.0);
}

// Near idle the lift is kept and the moments are scaled down to what fits above idle.
TEST(EngineMixer, AtTheBottomMomentsGiveWayToTheLift) {
  auto m = mixer<F>(180);
  const EngineCommand e = m.mix(250, moments<F>(100, 0, 0));  // 62.5 per engine, idle is 32.4
  const double s = m.applied().roll.to_double() / 100.0;
  EXPECT_NEAR(s, (62.5 - 32.4) / 50.0, 1e-3);
  EXPECT_EQ(e.value[1], 180);  // the low side sits on idle
  EXPECT_NEAR(forces_of(e).lift, 4 * 62.5, 4.0);
  // At idle lift there is no room below: the engines just idle.
  const EngineCommand idle = m.mix(100, moments<F>(100, -50, 20));
  for (const uint16_t v : idle.value) EXPECT_EQ(v, 180);
}

TEST(EngineMixer, FixedFollowsDouble) {
  auto mf = mixer<F>();
  auto md = mixer<D>();
  std::mt19937_64 rng(21);
  std::uniform_int_distribution<int> lift(0, 1000);
  std::uniform_real_distribution<double> moment(-600, 600);
  int worst = 0, differ = 0;
  for (int i = 0; i < 100000; ++i) {
    const auto wanted = moments<F>(moment(rng), moment(rng), moment(rng));
    const uint16_t l = static_cast<uint16_t>(lift(rng));
    const EngineCommand ef = mf.mix(l, wanted);
    const EngineCommand ed = md.mix(l, {wanted.roll.to_double(), wanted.pitch.to_double(), wanted.yaw.to_double()});
    for (int k = 0; k < 4; ++k) {
      const int d = std::abs(ef.value[k] - ed.value[k]);
      worst = std::max(worst, d);
      differ += d != 0;
    }
  }
  std::printf("  Q vs double engines: worst %d unit, %d of 400000 values differ\n", worst, differ);
  EXPECT_LE(worst, 1);
}

// The square root of the flight build (32-bit, engine_of_thrust) is the exact rounding of
// sqrt(1000 w) for a Q<16> thrust w: k = round(sqrt(x)) means (2k - 1)^2 <= 4x < (2k + 1)^2,
// here in integers, 4x = 4000 raw / 2^16. Checked on both sides of every rounding boundary of
// every engine value 0..1000 and on a million random thrusts.
TEST(EngineMixer, EngineOfThrustIsTheRoundedRoot) {
  using T = F::Thrust;
  const auto exact = [](int64_t raw, int64_t k) {
    const int64_t four_x_scaled = 4000 * raw;  // 4x x 2^16
    const bool above_lower = k == 0 || (2 * k - 1) * (2 * k - 1) * 65536 <= four_x_scaled;
    return above_lower && four_x_scaled < (2 * k + 1) * (2 * k + 1) * 65536;
  };
  int checked = 0;
  for (int64_t k = 0; k <= 1000; ++k) {
    // The first raw value whose root rounds to k + 1: 4000 raw >= (2k + 1)^2 2^16.
    const int64_t boundary = ((2 * k + 1) * (2 * k + 1) * 65536 + 3999) / 4000;
    for (const int64_t raw : {boundary - 2, boundary - 1, boundary, boundary + 1}) {
      if (raw < 0 || raw > 1000 * 65536) continue;
      const int32_t ae = EngineMixer<F>::engine_of_thrust(T::from_raw(static_cast<int32_t>(raw)));
      ASSERT_TRUE(exact(raw, ae)) << "raw " << raw << " gave " << ae;
      ++checked;
    }
  }
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int32_t> thrust(0, 1000 * 65536);
  for (int i = 0; i < 1000000; ++i) {
    const int32_t raw = thrust(rng);
    const int32_t ae = EngineMixer<F>::engine_of_thrust(T::from_raw(raw));
    ASSERT_TRUE(exact(raw, ae)) << "raw " << raw << " gave " << ae;
    ++checked;
  }
  std::printf("  engine_of_thrust exact on %d thrusts (every rounding boundary, a million random)\n", checked);
  EXPECT_EQ(EngineMixer<F>::engine_of_thrust(T::from_raw(0)), 0);
  EXPECT_EQ(EngineMixer<F>::engine_of_thrust(T::from_raw(-5)), 0);
  EXPECT_EQ(EngineMixer<F>::engine_of_thrust(T(1000.0)), 1000);
}

// limited() tells the controllers' integrals when the moments asked for were not realised.
TEST(EngineMixer, LimitedSaysWhenTheMomentsWereScaled) {
  auto m = mixer<F>(180);
  m.mix(500, moments<F>(50, -30, 10));
  EXPECT_FALSE(m.limited());
  m.mix(250, moments<F>(100, 0, 0));  // bottom: scaled to what fits above idle
  EXPECT_TRUE(m.limited());
  m.mix(990, moments<F>(100, 0, 0));  // top: the lift gives way, the moment is realised
  EXPECT_FALSE(m.limited());
  m.mix(600, moments<F>(1000, 500, 0));  // more spread than the engines span
  EXPECT_TRUE(m.limited());
  m.mix(0, moments<F>(1000, 500, 0));  // engines stopped: nothing to limit
  EXPECT_FALSE(m.limited());
}

}  // namespace
}  // namespace qr::chain
