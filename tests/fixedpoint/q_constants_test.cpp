// What a Q is made of and how constants get in: compile-time construction from a double
// (rounded half up, rejected when it does not fit: see compile_fail/), raw access, integers in
// and out, and the value as a double for tests.
#include <gtest/gtest.h>
#include <fixedpoint/q.hpp>

#include <type_traits>

namespace {

using fx::Q;
using Q8s = Q<8, int16_t>;  // int16 formats by name, so that macros see one argument

static_assert(sizeof(Q8s) == 2 && sizeof(Q<16>) == 4);
static_assert(std::is_trivially_copyable_v<Q<16>>);
static_assert(Q<16>::int_bits == 15 && Q<15, int16_t>::int_bits == 0);

TEST(QConstants, ComeFromDoublesAtCompileTimeRoundedHalfUp) {
  constexpr Q<16> one_and_a_half(1.5);
  static_assert(one_and_a_half.raw() == 3 << 15);
  static_assert(Q<1, int16_t>(0.25).raw() == 1);    // 0.5 lsb -> up
  static_assert(Q<1, int16_t>(-0.25).raw() == 0);   // -0.5 lsb -> up, to 0
  static_assert(Q<1, int16_t>(-0.75).raw() == -1);  // -1.5 lsb -> -1
  static_assert(Q<1, int16_t>(0.2).raw() == 0 && Q<1, int16_t>(0.3).raw() == 1);
  static_assert(Q<15, int16_t>(-1.0) == Q<15, int16_t>::min());
  static_assert(Q<15, int16_t>(1.0 - 1.0 / 32768) == Q<15, int16_t>::max());
  static_assert(Q<0>(2147483647.0) == Q<0>::max() && Q<0>(-2147483648.0) == Q<0>::min());
  static_assert(Q<30>(1.9999999990686774) == Q<30>::max());  // 2 - 2^-30
  static_assert(Q<31>(-1.0).raw() == INT32_MIN);
  EXPECT_EQ(Q<16>().raw(), 0);
}

TEST(QConstants, ToDoubleIsExact) {
  EXPECT_EQ(Q<16>::from_raw(-98304).to_double(), -1.5);
  EXPECT_EQ(Q<31>::min().to_double(), -1.0);
  EXPECT_EQ(Q<31>::from_raw(1).to_double(), 0x1p-31);
  EXPECT_EQ(Q<0>::max().to_double(), 2147483647.0);
  EXPECT_EQ(Q8s::min().to_double(), -128.0);
}

TEST(QConstants, IntegersInSaturateAndOutRoundHalfUp) {
  EXPECT_EQ(Q<16>::from_int(-3), Q<16>(-3.0));
  EXPECT_EQ(Q<16>::from_int(40000), Q<16>::max());
  EXPECT_EQ(Q<16>::from_int(-40000), Q<16>::min());
  EXPECT_EQ(Q<16>::from_int(-32768), Q<16>::min());
  EXPECT_EQ(Q8s::from_int(127), Q8s(127.0));
  EXPECT_EQ(Q8s::from_int(128), Q8s::max());
  EXPECT_EQ(Q<16>(2.5).to_int(), 3);
  EXPECT_EQ(Q<16>(-2.5).to_int(), -2);
  EXPECT_EQ(Q<16>(-2.5000153).to_int(), -3);
  EXPECT_EQ(Q<31>(-1.0).to_int(), -1);
  EXPECT_EQ(Q<31>::max().to_int(), 1);
  EXPECT_EQ(Q<16>::max().to_int(), 32768);  // the rounded value, one past max: an int32 holds it
}

TEST(QConstants, FormatsAreDistinctTypes) {
  static_assert(!std::is_same_v<Q<16>, Q<17>>);
  static_assert(!std::is_same_v<Q<15>, Q<15, int16_t>>);
  static_assert(fx::is_q<Q<3, int16_t>>);
  static_assert(!fx::is_q<int>);
}

}  // namespace
