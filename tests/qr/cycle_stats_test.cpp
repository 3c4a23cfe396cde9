// The cycle statistics' cheap usual case must give the figures a plain count, min, max, sum and
// budget check give, whatever order the measurements come in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <qr/core/cycle_stats.hpp>

namespace qr {
namespace {

struct Plain {
  uint32_t count = 0, min = 0, max = 0, overruns = 0;
  uint64_t sum = 0;
  void add(uint32_t c, uint32_t budget) {
    min = count == 0 ? c : std::min(min, c);
    max = std::max(max, c);
    overruns += c > budget ? 1 : 0;
    sum += c;
    ++count;
  }
};

void expect_same(const CycleStats& s, const Plain& p) {
  EXPECT_EQ(s.count, p.count);
  EXPECT_EQ(s.min, p.min);
  EXPECT_EQ(s.max, p.max);
  EXPECT_EQ(s.overruns, p.overruns);
  EXPECT_EQ(s.sum(), p.sum);
}

TEST(CycleStats, AgreesWithPlainFiguresOnRandomRuns) {
  std::mt19937 random(7);
  for (const uint32_t budget : {0u, 1u, 500u, 1000u, CycleStats::kNoBudget}) {
    CycleStats stats;
    Plain plain;
    std::uniform_int_distribution<uint32_t> usual(400, 600), rare(0, 5000);
    for (int i = 0; i < 20000; ++i) {
      const uint32_t c = i % 97 == 0 ? rare(random) : usual(random);
      stats.add(c, budget);
      plain.add(c, budget);
    }
    expect_same(stats, plain);
  }
}

TEST(CycleStats, EveryRunOverABudgetBelowTheMinimumIsAnOverrun) {
  CycleStats stats;
  for (int i = 0; i < 10; ++i) stats.add(300, 200);
  EXPECT_EQ(stats.overruns, 10u);
  EXPECT_EQ(stats.count, 10u);
}

TEST(CycleStats, RunsInsideTheRangeSeenButOverTheBudgetAreOverruns) {
  CycleStats stats;
  stats.add(100, 500);
  stats.add(900, 500);  // an overrun that widens the range
  stats.add(700, 500);  // inside [100, 900], still over the budget
  EXPECT_EQ(stats.overruns, 2u);
  EXPECT_EQ(stats.min, 100u);
  EXPECT_EQ(stats.max, 900u);
}

TEST(CycleStats, TheSumCarriesPastThirtyTwoBits) {
  CycleStats stats;
  for (int i = 0; i < 3; ++i) stats.add(0xF0000000u);
  EXPECT_EQ(stats.sum(), 3ull * 0xF0000000u);
  EXPECT_EQ(stats.mean(), 0xF0000000u);
}

TEST(CycleStats, TheMeanIsTheSameBelowAndAboveThirtyTwoBits) {
  CycleStats below;
  for (const uint32_t c : {7u, 8u, 8u}) below.add(c);
  EXPECT_EQ(below.sum_high, 0u);
  EXPECT_EQ(below.mean(), 7u);  // 23 / 3, rounded down as the 64-bit division rounds
  CycleStats above;
  for (const uint32_t c : {0xFFFFFFF0u, 0x20u, 0x10u}) above.add(c);
  EXPECT_EQ(above.sum_high, 1u);
  EXPECT_EQ(above.mean(), static_cast<uint32_t>(0x100000020ull / 3));
}

TEST(CycleStats, AnExtremeRangeStaysCorrect) {
  CycleStats stats;
  Plain plain;
  for (const uint32_t c : {0u, 0xFFFFFFFFu, 5u, 0xFFFFFFFFu, 0u}) {
    stats.add(c);
    plain.add(c, CycleStats::kNoBudget);
  }
  expect_same(stats, plain);
}

}  // namespace
}  // namespace qr
