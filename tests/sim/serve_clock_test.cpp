// Serve mode's pace (qr/sim_runner/serve_clock.hpp): the kicks on the wall clock, a late world
// caught up no faster than twice the wall clock, a world far behind paused rather than skipped.
// The wall clock is the test's, so nothing here sleeps.
#include <gtest/gtest.h>

#include <qr/sim_runner/serve_clock.hpp>

namespace {

constexpr uint64_t kPeriod = 1000;

TEST(ServeClock, KicksFollowTheWallClock) {
  qrsim::ServeClock clock(kPeriod);
  clock.start(5000000, 0);
  EXPECT_EQ(clock.due_us(1000), 5001000u);
  EXPECT_EQ(clock.begin(1000, 5001000), 0u);
  EXPECT_EQ(clock.due_us(2000), 5002000u);
  EXPECT_EQ(clock.timing().late_wakeups, 0u);
  EXPECT_EQ(clock.timing().pauses, 0u);
}

// Woken 20 ms late, the world catches up, but a kick comes no sooner than half a period after the
// last: simulated time runs at most twice as fast as the wall clock, so the console's frames read
// meanwhile are at most twice as close in the world as on the wall. Back on time after 40 ms.
TEST(ServeClock, ALateWorldCatchesUpAtMostTwiceAsFast) {
  qrsim::ServeClock clock(kPeriod);
  clock.start(0, 0);
  uint64_t kick = 1000;
  ASSERT_EQ(clock.begin(kick, 21000), 0u) << "20 ms behind: caught up, not a pause";
  EXPECT_EQ(clock.timing().late_wakeups, 1u);
  uint64_t wall = 21000;
  const uint64_t caught_up_from_wall = wall, caught_up_from_sim = kick;
  while (wall > kick) {  // started at 0 on both clocks: a kick is on time at its own time
    kick += kPeriod;
    const uint64_t due = clock.due_us(kick);
    ASSERT_GE(due, wall + kPeriod / 2) << "two kicks closer than half a period at " << kick;
    wall = due;
    ASSERT_EQ(clock.begin(kick, wall), 0u);
    ASSERT_LT(kick, 100000u) << "never caught up";
  }
  // 20 ms of lag made up at 0.5 ms per kick: 40 kicks in 20 ms of wall time.
  EXPECT_NEAR(static_cast<double>(wall - caught_up_from_wall), 20000.0, 1000.0);
  EXPECT_NEAR(static_cast<double>(kick - caught_up_from_sim), 40000.0, 2000.0);
  EXPECT_EQ(clock.due_us(kick + kPeriod), kick + kPeriod) << "on the wall clock again";
  EXPECT_EQ(clock.timing().late_wakeups, 1u) << "catching up is not the host being late";
  EXPECT_GE(clock.timing().behind_kicks, 19u);
  EXPECT_EQ(clock.timing().max_behind_us, 20000u);
  EXPECT_EQ(clock.timing().pauses, 0u);
}

// The catch-up's pace is counted from where the world fell behind, not kick by kick: a kick the
// host took late meanwhile (a sleep that overslept, a slow devboard round trip) is made up by the
// next ones at once, as far as twice the wall clock since the world fell behind allows.
TEST(ServeClock, AKickTakenLateWhileCatchingUpIsMadeUp) {
  qrsim::ServeClock clock(kPeriod);
  clock.start(0, 0);
  ASSERT_EQ(clock.begin(1000, 11000), 0u);  // 10 ms behind from here: 20 kicks in 10 ms to catch up
  EXPECT_EQ(clock.due_us(2000), 11500u);
  ASSERT_EQ(clock.begin(2000, 13000), 0u);  // 1.5 ms late
  EXPECT_EQ(clock.due_us(3000), 12000u) << "due already: taken at once";
  ASSERT_EQ(clock.begin(3000, 13000), 0u);
  EXPECT_EQ(clock.due_us(4000), 12500u);
  ASSERT_EQ(clock.begin(4000, 13000), 0u);
  EXPECT_EQ(clock.due_us(5000), 13000u);
  ASSERT_EQ(clock.begin(5000, 13000), 0u);
  EXPECT_EQ(clock.due_us(6000), 13500u) << "back on the line of twice the wall clock, and no further";
}

// Once on time again, a later lag is caught up at the same pace from where that one began (not
// from the first, long ago, which would let it run back to back).
TEST(ServeClock, EveryLagIsCaughtUpAtTheSamePace) {
  qrsim::ServeClock clock(kPeriod);
  clock.start(0, 0);
  ASSERT_EQ(clock.begin(1000, 11000), 0u);
  uint64_t kick = 1000;
  for (uint64_t wall = 11000; wall > kick;) {
    kick += kPeriod;
    wall = clock.due_us(kick);
    clock.begin(kick, wall);
  }
  for (int i = 0; i < 1000; ++i) {
    kick += kPeriod;
    ASSERT_EQ(clock.due_us(kick), kick);
    clock.begin(kick, kick);
  }
  kick += kPeriod;
  ASSERT_EQ(clock.begin(kick, kick + 10000), 0u);
  EXPECT_EQ(clock.due_us(kick + kPeriod), kick + 10000 + kPeriod / 2);
}

// Stopped for 2 s (SIGSTOP, a loaded host), the world does not run 2 s to catch up, nor skip them:
// it pauses, and takes its next kicks on the wall clock from where it stood.
TEST(ServeClock, AWorldFarBehindPausesAndResumesFromNow) {
  qrsim::ServeClock clock(kPeriod);
  clock.start(0, 0);
  for (uint64_t kick = 1000; kick <= 100000; kick += kPeriod) ASSERT_EQ(clock.begin(kick, kick), 0u);
  EXPECT_EQ(clock.begin(101000, 2101000), 2000000u);
  EXPECT_EQ(clock.due_us(102000), 2102000u) << "the next period on time, from the pause on";
  EXPECT_EQ(clock.begin(102000, 2102000), 0u);
  EXPECT_EQ(clock.timing().pauses, 1u);
  EXPECT_EQ(clock.timing().paused_us, 2000000u);
  EXPECT_EQ(clock.timing().longest_pause_us, 2000000u);
  EXPECT_EQ(clock.timing().max_behind_us, 0u) << "a pause is not caught up";
}

TEST(ServeClock, TheBoundBetweenCatchingUpAndPausing) {
  qrsim::ServeClock clock(kPeriod);
  clock.start(0, 0);
  EXPECT_EQ(clock.begin(1000, 1000 + qrsim::ServeClock::kMaxBehindUs), 0u);
  qrsim::ServeClock other(kPeriod);
  other.start(0, 0);
  EXPECT_EQ(other.begin(1000, 1000 + qrsim::ServeClock::kMaxBehindUs + 1), qrsim::ServeClock::kMaxBehindUs + 1);
  // The catch-up's pace keeps the console's frames inside the QR's link watchdog (link_timeout_ms,
  // 50 ms at the least): caught up at twice the wall clock, a frame 20 ms after the last on the
  // wall is at most 40 ms after it in the world.
  static_assert(qrsim::ServeClock::kCatchUpFactor * 20000 < 50000);
}

}  // namespace
