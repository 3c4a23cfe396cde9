// The vertical loops (vertical_controller.hpp): height hold's and a landing's thrust, and the
// landing's touchdown, on the flight's Q formats and on double.
#include <gtest/gtest.h>

#include <type_traits>

#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/vertical_controller.hpp>
#include <qr/host/real_numbers.hpp>

namespace qr::chain {
namespace {

constexpr uint32_t kRunHz = 250;      // the height task's rate
constexpr uint32_t kSampleHz = 1000;  // the control rate
constexpr double kG0 = 9.80665;

template <class N>
struct Types {
  using Height = typename N::Height;
  using Climb = typename N::Climb;
  using Thrust = typename N::Thrust;
  using Accel = typename N::Accel;
};

template <class X>
double real(X x) {
  if constexpr (std::is_floating_point_v<X>) {
    return x;
  } else {
    return x.to_double();
  }
}

// Each check is a template run on the flight's Q formats and on double by a plain test (the
// static analysis does not read gtest's typed tests).

template <class N>
void OnItsHeightAtRestTheThrustIsTheHoversThatFlew() {
  using T = Types<N>;
  VerticalController<N, kRunHz> loop;
  loop.start(typename T::Thrust(282.0), typename T::Height(1.5));
  const auto want = loop.climb_to_hold(typename T::Height(1.5));
  EXPECT_NEAR(real(loop.update(want, typename T::Climb(0.0), true)), 282.0, 1e-3);
}

// The thrust is T0 (1 + u / g0): a climb error of -0.5 m/s asks Kv x -0.5 = -2 m/s² at once.
template <class N>
void AClimbErrorAsksForItsAccelerationAsAShareOfTheWeight() {
  using T = Types<N>;
  VerticalController<N, kRunHz> loop;
  loop.start(typename T::Thrust(282.0), typename T::Height(0.0));
  const double thrust = real(loop.update(typename T::Climb(-0.5), typename T::Climb(0.0), false));
  EXPECT_NEAR(thrust, 282.0 * (1 - 2.0 / kG0), 0.01);
  // What a live plot shows of that run: the set-point, the P term that is all of u, no integral.
  EXPECT_NEAR(real(loop.climb_setpoint()), -0.5, 1e-6);
  EXPECT_NEAR(real(loop.p_term()), -2.0, 1e-5);
  EXPECT_NEAR(real(loop.integral()), 0.0, 1e-9);
  // Held for a second, the integral adds Ki x -0.5 x 1 s = -2 m/s² more.
  for (uint32_t i = 0; i < kRunHz; ++i) loop.update(typename T::Climb(-0.5), typename T::Climb(0.0), true);
  EXPECT_NEAR(real(loop.thrust()), 282.0 * (1 - 4.0 / kG0), 0.05);
  // and never more than half a g either way.
  for (uint32_t i = 0; i < 10 * kRunHz; ++i) loop.update(typename T::Climb(-0.5), typename T::Climb(0.0), true);
  EXPECT_GE(real(loop.thrust()), 282.0 * (1 - 4.9 / kG0) - 0.01);
}

// Height hold: 0.3 m below the held height asks for a climb of Kh x 0.3 m; far off, at most 0.5 m/s.
template <class N>
void HeightHoldAsksForAClimbBackBoundedAtHalfAMetreASecond() {
  using T = Types<N>;
  VerticalController<N, kRunHz> loop;
  loop.start(typename T::Thrust(282.0), typename T::Height(2.0));
  EXPECT_NEAR(real(loop.climb_to_hold(typename T::Height(1.7))), 0.3, 1e-4);
  EXPECT_NEAR(real(loop.climb_to_hold(typename T::Height(5.0))), -0.5, 1e-6);
}

// The stop: a steady descent never touches down; once the estimate stops descending, 0.2 s later.
template <class N>
void TouchdownWhenTheDescentStopsForAFifthOfASecond() {
  using T = Types<N>;
  TouchdownDetector<N, kRunHz, kSampleHz> touchdown;
  touchdown.set_descent(500);
  touchdown.start();
  for (uint32_t i = 0; i < 10 * kRunHz; ++i) ASSERT_FALSE(touchdown.update(typename T::Climb(-0.48)));
  for (uint32_t i = 1; i < kRunHz / 5; ++i) ASSERT_FALSE(touchdown.update(typename T::Climb(-0.1))) << i;
  EXPECT_TRUE(touchdown.update(typename T::Climb(-0.1)));
}

// A panic that starts while climbing brakes first: no touchdown before the descent is seen (or 2 s).
template <class N>
void NoTouchdownBeforeTheDescentHasBegun() {
  using T = Types<N>;
  TouchdownDetector<N, kRunHz, kSampleHz> touchdown;
  touchdown.set_descent(500);
  touchdown.start();
  for (uint32_t i = 0; i < 2 * kRunHz - 1; ++i) ASSERT_FALSE(touchdown.update(typename T::Climb(0.0))) << i;
  for (uint32_t i = 0; i < 100; ++i) ASSERT_FALSE(touchdown.impact(typename T::Accel(-2.0)));
  // Two seconds without descending: on the ground (a panic that began there); 0.2 s of stillness.
  bool down = false;
  for (uint32_t i = 0; i <= kRunHz / 5 && !down; ++i) down = touchdown.update(typename T::Climb(0.0));
  EXPECT_TRUE(down);
}

// The impact: beyond 1.3 g along body z for 5 ms, once descending.
template <class N>
void TouchdownOnTheImpactAfterFiveMilliseconds() {
  using T = Types<N>;
  TouchdownDetector<N, kRunHz, kSampleHz> touchdown;
  touchdown.set_descent(500);
  touchdown.start();
  ASSERT_FALSE(touchdown.update(typename T::Climb(-0.5)));
  for (int i = 0; i < 1000; ++i) ASSERT_FALSE(touchdown.impact(typename T::Accel(-1.25))) << "a firm brake";
  for (int i = 0; i < 4; ++i) ASSERT_FALSE(touchdown.impact(typename T::Accel(-1.5)));
  ASSERT_FALSE(touchdown.impact(typename T::Accel(-1.0))) << "a spike shorter than 5 ms";
  for (int i = 0; i < 4; ++i) ASSERT_FALSE(touchdown.impact(typename T::Accel(-1.5)));
  EXPECT_TRUE(touchdown.impact(typename T::Accel(-1.5)));
}

TEST(Vertical, OnItsHeightAtRestTheThrustIsTheHoversThatFlew) {
  OnItsHeightAtRestTheThrustIsTheHoversThatFlew<FixedNumbers>();
  OnItsHeightAtRestTheThrustIsTheHoversThatFlew<DoubleNumbers>();
}

TEST(Vertical, AClimbErrorAsksForItsAccelerationAsAShareOfTheWeight) {
  AClimbErrorAsksForItsAccelerationAsAShareOfTheWeight<FixedNumbers>();
  AClimbErrorAsksForItsAccelerationAsAShareOfTheWeight<DoubleNumbers>();
}

TEST(Vertical, HeightHoldAsksForAClimbBackBoundedAtHalfAMetreASecond) {
  HeightHoldAsksForAClimbBackBoundedAtHalfAMetreASecond<FixedNumbers>();
  HeightHoldAsksForAClimbBackBoundedAtHalfAMetreASecond<DoubleNumbers>();
}

TEST(Vertical, TouchdownWhenTheDescentStopsForAFifthOfASecond) {
  TouchdownWhenTheDescentStopsForAFifthOfASecond<FixedNumbers>();
  TouchdownWhenTheDescentStopsForAFifthOfASecond<DoubleNumbers>();
}

TEST(Vertical, NoTouchdownBeforeTheDescentHasBegun) {
  NoTouchdownBeforeTheDescentHasBegun<FixedNumbers>();
  NoTouchdownBeforeTheDescentHasBegun<DoubleNumbers>();
}

TEST(Vertical, TouchdownOnTheImpactAfterFiveMilliseconds) {
  TouchdownOnTheImpactAfterFiveMilliseconds<FixedNumbers>();
  TouchdownOnTheImpactAfterFiveMilliseconds<DoubleNumbers>();
}

}  // namespace
}  // namespace qr::chain
