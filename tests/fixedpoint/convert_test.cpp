// Every kind of conversion between Q formats: fewer fractional bits (rounded half up), more
// (exact), narrower storage, wider storage, and both flavours (convert wraps, convert_sat
// clamps). int16 sources are swept exhaustively, int32 sources over edges and random raws.
#include <gtest/gtest.h>
#include <fixedpoint/convert.hpp>

#include <type_traits>

#include "reference.hpp"

namespace {

using fxtest::i128;

template <typename To, typename From>
void expect_conversion(From from) {
  const i128 exact = fxtest::round_half_up_shift(from.raw(), From::frac_bits - To::frac_bits);
  using Raw = typename To::raw_type;
  ASSERT_EQ(fx::convert<To>(from).raw(), fxtest::wrapped<Raw>(exact))
      << from.raw() << " from Q" << From::frac_bits << " to Q" << To::frac_bits;
  ASSERT_EQ(fx::convert_sat<To>(from).raw(), fxtest::saturated<Raw>(exact))
      << from.raw() << " from Q" << From::frac_bits << " to Q" << To::frac_bits;
}

template <typename From, typename... Tos>
void sweep_int16_source() {
  for (int32_t raw = INT16_MIN; raw <= INT16_MAX; ++raw) {
    const From from = From::from_raw(static_cast<int16_t>(raw));
    (expect_conversion<Tos>(from), ...);
  }
}

template <typename From, typename... Tos>
void sweep_int32_source(uint64_t seed) {
  for (int32_t raw : fxtest::edge_raws<int32_t>()) (expect_conversion<Tos>(From::from_raw(raw)), ...);
  fxtest::RawSource<int32_t> source(seed);
  for (int i = 0; i < 200000; ++i) (expect_conversion<Tos>(From::from_raw(source.next())), ...);
}

using fx::Q;
using Q8s = Q<8, int16_t>;  // int16 formats by name, so that macros see one argument

TEST(Convert, FromInt16FormatsExhaustively) {
  sweep_int16_source<Q8s, Q<4, int16_t>, Q<0, int16_t>, Q<12, int16_t>, Q<15, int16_t>, Q8s, Q<0>, Q<16>, Q<24>,
                     Q<31>>();
  sweep_int16_source<Q<15, int16_t>, Q<14, int16_t>, Q<1, int16_t>, Q<30>, Q<2>>();
}

TEST(Convert, FromInt32Formats) {
  sweep_int32_source<Q<16>, Q<0>, Q<8>, Q<15>, Q<16>, Q<17>, Q<30>, Q<31>, Q<0, int16_t>, Q8s, Q<15, int16_t>>(1);
  sweep_int32_source<Q<30>, Q<29>, Q<16>, Q<0>, Q<31>, Q<14, int16_t>, Q<15, int16_t>>(2);
  sweep_int32_source<Q<0>, Q<31>, Q<16>, Q<0, int16_t>, Q<15, int16_t>>(3);
}

TEST(Convert, RoundsHalfUpAtTheTies) {
  // -1.5, -0.5, 0.5, 1.5 lsb of the target go to -1, 0, 1, 2.
  EXPECT_EQ(fx::convert<Q<0>>(Q<1>::from_raw(-3)).raw(), -1);
  EXPECT_EQ(fx::convert<Q<0>>(Q<1>::from_raw(-1)).raw(), 0);
  EXPECT_EQ(fx::convert<Q<0>>(Q<1>::from_raw(1)).raw(), 1);
  EXPECT_EQ(fx::convert<Q<0>>(Q<1>::from_raw(3)).raw(), 2);
  // Just below a tie goes down, on either side of zero.
  EXPECT_EQ(fx::convert<Q<16>>(Q<30>::from_raw((1 << 13) - 1)).raw(), 0);
  EXPECT_EQ(fx::convert<Q<16>>(Q<30>::from_raw(-(1 << 13) - 1)).raw(), -1);
}

TEST(Convert, OutOfRangeWrapsOrSaturates) {
  const auto big = Q<16>(300.0);
  EXPECT_EQ(fx::convert_sat<Q8s>(big), Q8s::max());
  EXPECT_EQ(fx::convert<Q8s>(big).raw(), static_cast<int16_t>(300 * 256 - 65536));
  EXPECT_EQ(fx::convert_sat<Q8s>(-big), Q8s::min());
  EXPECT_EQ(fx::convert_sat<Q<30>>(Q<16>(2.0)), Q<30>::max());
  EXPECT_EQ(fx::convert_sat<Q<30>>(Q<16>(-2.0)), Q<30>(-2.0));
}

TEST(Convert, NothingConvertsImplicitly) {
  static_assert(!std::is_convertible_v<Q<16>, Q<17>>);
  static_assert(!std::is_convertible_v<Q<15>, Q<15, int16_t>>);
  static_assert(!std::is_convertible_v<Q<15, int16_t>, Q<15>>);
  static_assert(!std::is_convertible_v<int, Q<16>>);
  static_assert(!std::is_convertible_v<double, Q<16>>);
  static_assert(!std::is_convertible_v<Q<16>, int>);
  static_assert(!std::is_convertible_v<Q<16>, double>);
}

}  // namespace
