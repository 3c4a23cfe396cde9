// The gyro clip bridge (qr/core/chain/gyro_clip.hpp): the area a clipped run hid, from the
// slopes either side, as a triangle above full scale.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <qr/core/chain/gyro_clip.hpp>

namespace qr::chain {
namespace {

constexpr int32_t kFs = ClipBridge::kFullScale;

// A rate rising by `rise` counts a sample from 0, turning at `peak` counts and falling by `fall`
// a sample, as the gyro reads it (clipped at full scale), and the area above full scale the
// bridge should return (sign by `sign`).
struct Triangle {
  std::vector<int16_t> samples;
  double hidden = 0;  // counts x samples above full scale
};
Triangle triangle(int32_t rise, int32_t peak, int32_t fall, int32_t sign) {
  Triangle t;
  int32_t v = 0;
  for (; v < peak; v += rise) {
    t.samples.push_back(static_cast<int16_t>(sign * (v < kFs ? v : kFs)));
    if (v > kFs) t.hidden += v - kFs;
  }
  for (v = peak; v > 0; v -= fall) {
    t.samples.push_back(static_cast<int16_t>(sign * (v < kFs ? v : kFs)));
    if (v > kFs) t.hidden += v - kFs;
  }
  for (int i = 0; i < 20; ++i) t.samples.push_back(0);
  t.hidden *= sign;
  return t;
}

// What the bridge returns over a run of samples: the area once, 0 for every other sample.
std::vector<int32_t> areas(const std::vector<int16_t>& samples) {
  ClipBridge bridge;
  std::vector<int32_t> out;
  for (int16_t s : samples) {
    const int32_t a = bridge.update(s);
    if (a != 0) out.push_back(a);
  }
  return out;
}

TEST(GyroClip, ATriangleAboveFullScaleIsReturnedOnce) {
  for (int32_t sign : {1, -1}) {
    // 2000 counts a sample up to 40000 (the push), 800 down (the controller's answer).
    const Triangle t = triangle(2000, 40000, 800, sign);
    const std::vector<int32_t> got = areas(t.samples);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0] > 0, sign > 0);
    // Within 15 %: the samples' own steps at the crossings are a sample each side.
    EXPECT_NEAR(got[0], t.hidden, 0.15 * std::abs(t.hidden)) << "sign " << sign;
  }
}

TEST(GyroClip, NothingIsReturnedWithoutAClip) {
  const Triangle t = triangle(1000, 32000, 1000, 1);
  EXPECT_TRUE(areas(t.samples).empty());
}

// A clip one way and then the other: two runs, two areas of their own signs.
TEST(GyroClip, ClipsBothWaysAreTwoRuns) {
  std::vector<int16_t> s = triangle(2000, 40000, 800, 1).samples;
  const std::vector<int16_t> down = triangle(2000, 40000, 800, -1).samples;
  s.insert(s.end(), down.begin(), down.end());
  const std::vector<int32_t> got = areas(s);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_GT(got[0], 0);
  EXPECT_LT(got[1], 0);
  EXPECT_EQ(got[0], -got[1]);
}

// A spin that stays clipped longer than kMaxRun is no triangle: the bridge adds nothing for it,
// however long; a run of kMaxRun samples still counts.
TEST(GyroClip, ASpinAddsNothing) {
  auto run = [](int32_t clipped) {
    std::vector<int16_t> s;
    for (int i = 0; i < 8; ++i) s.push_back(static_cast<int16_t>(4000 * i));
    for (int i = 0; i < clipped; ++i) s.push_back(32767);
    for (int i = 0; i < 8; ++i) s.push_back(static_cast<int16_t>(28000 - 4000 * i));
    return areas(s);
  };
  EXPECT_TRUE(run(ClipBridge::kMaxRun + 1).empty());
  EXPECT_TRUE(run(5000).empty());
  const std::vector<int32_t> longest = run(ClipBridge::kMaxRun);
  ASSERT_EQ(longest.size(), 1u);
  EXPECT_GT(longest[0], 0);
  EXPECT_LE(longest[0], ClipBridge::kMaxRun * kFs / 2);
}

}  // namespace
}  // namespace qr::chain
