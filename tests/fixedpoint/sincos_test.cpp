// fx::sin and fx::cos against long double. The documented bound (fixedpoint/README.md,
// sincos.hpp) is the maximum measured over 5e7 samples (DISABLED_LongSweep), rounded up to two
// digits; here it is asserted over every int16 angle of one format, a dense stride through a
// Q<28> range of [-8, 8) rad, the neighbourhoods of every quadrant boundary there, and random
// angles of Q<0>, Q<16> and Q<31> (up to 2^31 rad).
#include <gtest/gtest.h>
#include <fixedpoint/sincos.hpp>

#include <cmath>
#include <numbers>

#include "max_error.hpp"
#include "reference.hpp"

namespace {

constexpr long double kMaxError = 5.6e-9L;  // with the default Q<30> result

struct SinCosErrors {
  fxtest::MaxError sin, cos;
  explicit SinCosErrors(const std::string& name) : sin(name + " sin"), cos(name + " cos") {}
  void check(long double bound) {
    sin.print(bound);
    cos.print(bound);
    EXPECT_LE(sin.max(), bound) << "at " << static_cast<double>(sin.at());
    EXPECT_LE(cos.max(), bound) << "at " << static_cast<double>(cos.at());
  }
};

template <typename Out, typename Q>
void measure(Q angle, SinCosErrors& e) {
  const long double x = fxtest::value(angle);
  e.sin.add(fabsl(fxtest::value(fx::sin<Out>(angle)) - sinl(x)), x);
  e.cos.add(fabsl(fxtest::value(fx::cos<Out>(angle)) - cosl(x)), x);
}

TEST(SinCos, EveryInt16Angle) {
  using Angle = fx::Q<13, int16_t>;  // [-4, 4) rad
  SinCosErrors q30("Q<13, int16_t> -> Q<30>");
  SinCosErrors q14("Q<13, int16_t> -> Q<14, int16_t>");
  for (int32_t raw = INT16_MIN; raw <= INT16_MAX; ++raw) {
    measure<fx::Q<30>>(Angle::from_raw(static_cast<int16_t>(raw)), q30);
    measure<fx::Q<14, int16_t>>(Angle::from_raw(static_cast<int16_t>(raw)), q14);
  }
  q30.check(kMaxError);
  q14.check(kMaxError + 0x1p-15L);  // plus half an lsb of the coarser result
}

TEST(SinCos, DenseOverEightRadiansEitherSide) {
  using Angle = fx::Q<28>;
  SinCosErrors e("Q<28> -> Q<30>");
  for (int64_t raw = INT32_MIN; raw <= INT32_MAX; raw += 4099)
    measure<fx::Q<30>>(Angle::from_raw(static_cast<int32_t>(raw)), e);
  for (int k = -5; k <= 5; ++k) {
    const auto boundary = static_cast<int64_t>(std::llround(k * std::numbers::pi / 2 * 0x1p28));
    for (int64_t d = -3000; d <= 3000; ++d) {
      const int64_t raw = boundary + d;
      if (raw >= INT32_MIN && raw <= INT32_MAX) measure<fx::Q<30>>(Angle::from_raw(static_cast<int32_t>(raw)), e);
    }
  }
  e.check(kMaxError);
}

template <typename Angle>
void random_angles(const char* name, uint64_t seed, int samples) {
  SinCosErrors e(name);
  fxtest::RawSource<int32_t> source(seed);
  for (int i = 0; i < samples; ++i) measure<fx::Q<30>>(Angle::from_raw(source.next()), e);
  e.check(kMaxError);
}

TEST(SinCos, RandomAnglesOfAnySize) {
  random_angles<fx::Q<0>>("Q<0> -> Q<30>", 1, 150000);
  random_angles<fx::Q<16>>("Q<16> -> Q<30>", 2, 150000);
  random_angles<fx::Q<31>>("Q<31> -> Q<30>", 3, 150000);
}

// The sweep behind the documented bound (5e7 samples, minutes under the sanitizers). Run with
// --gtest_also_run_disabled_tests --gtest_filter='*LongSweep*'.
TEST(SinCos, DISABLED_LongSweep) {
  random_angles<fx::Q<16>>("Q<16> -> Q<30>", 11, 20000000);
  random_angles<fx::Q<28>>("Q<28> -> Q<30>", 12, 20000000);
  random_angles<fx::Q<0>>("Q<0> -> Q<30>", 13, 5000000);
  random_angles<fx::Q<31>>("Q<31> -> Q<30>", 14, 5000000);
}

TEST(SinCos, KnownValues) {
  EXPECT_EQ(fx::sin(fx::Q<16>()), fx::Q<30>());
  // Not 1 but 1 - 3 lsb: the published polynomial's own error at pi/2 (A&S 4.3.97 is not
  // constrained to hit 1 there), within the bound like every other value.
  EXPECT_EQ(fx::cos(fx::Q<16>()).raw(), (1 << 30) - 3);
  EXPECT_NEAR(fx::sin(fx::Q<28>(std::numbers::pi / 6)).to_double(), 0.5, 5.6e-9);
  EXPECT_NEAR(fx::cos(fx::Q<28>(-std::numbers::pi / 3)).to_double(), 0.5, 5.6e-9);
  EXPECT_NEAR(fx::sin(fx::Q<16>(-1000.0)).to_double(), std::sin(-1000.0), 5.6e-9);
  using Unit16 = fx::Q<14, int16_t>;
  EXPECT_EQ(fx::sin<Unit16>(fx::Q<16>(std::numbers::pi / 2)), Unit16(1.0));
}

}  // namespace
