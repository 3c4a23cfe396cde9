// The robustness sweep's draws: inside their documented ranges, the same for the same seed,
// different for another, and spread over the ranges rather than stuck at one end.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>

#include <qr/sim_runner/sweep.hpp>

namespace {

double drawn(const qrsim::VehicleDraw& d, size_t i) {
  const double values[] = {d.mass, d.inertia, d.motor_tau, d.vibration, d.noise};
  return values[i];
}

TEST(Sweep, DrawsLieInTheirRangesAndFollowTheSeed) {
  static_assert(std::size(qrsim::kSweepRanges) == 5, "one range per VehicleDraw member");
  double low[5], high[5];
  for (size_t i = 0; i < 5; ++i) low[i] = high[i] = drawn(qrsim::draw_vehicle(1), i);
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    const qrsim::VehicleDraw d = qrsim::draw_vehicle(seed);
    for (size_t i = 0; i < 5; ++i) {
      const qrsim::SweepRange& r = qrsim::kSweepRanges[i];
      EXPECT_GE(drawn(d, i), r.low) << r.what << " seed " << seed;
      EXPECT_LT(drawn(d, i), r.high) << r.what << " seed " << seed;
      EXPECT_EQ(drawn(d, i), drawn(qrsim::draw_vehicle(seed), i)) << "same seed, same draw";
      low[i] = std::min(low[i], drawn(d, i));
      high[i] = std::max(high[i], drawn(d, i));
    }
  }
  for (size_t i = 0; i < 5; ++i) {
    const qrsim::SweepRange& r = qrsim::kSweepRanges[i];
    const double span = r.high - r.low;
    EXPECT_LT(low[i], r.low + 0.05 * span) << r.what << ": 200 draws reach near the bottom";
    EXPECT_GT(high[i], r.high - 0.05 * span) << r.what << ": and near the top";
  }
  EXPECT_NE(qrsim::draw_vehicle(1).mass, qrsim::draw_vehicle(2).mass);
}

}  // namespace
