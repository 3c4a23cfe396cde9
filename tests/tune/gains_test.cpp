// Gains to the parameter table's raw integers (tune/gains.hpp): rounded to the row's Q format,
// clamped to its range, and written so that --param reads back the very same raw value.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <qr/host/parameter_text.hpp>
#include <tune/gains.hpp>

namespace tune {
namespace {

TEST(TuneGains, DefaultsAreTheTables) {
  const RollPitchGains rp = default_roll_pitch_gains();
  EXPECT_EQ(rp.p1, 5.5);    // 1408 / 2^8
  EXPECT_EQ(rp.p2, 220.0);  // 3520 / 2^4
  EXPECT_EQ(rp.i, 80.0);
  EXPECT_EQ(rp.d, 8.0);
  const YawGains yaw = default_yaw_gains();
  EXPECT_EQ(yaw.p, 300.0);
  EXPECT_EQ(yaw.i, 300.0);
  const auto raw = raw_parameters(rp);
  EXPECT_STREQ(raw[0].name(), "roll_pitch_p1");
  EXPECT_STREQ(raw[3].name(), "roll_pitch_d");
  EXPECT_EQ(raw[0].raw, 1408);
  EXPECT_EQ(raw[1].raw, 3520);
  EXPECT_EQ(raw[2].raw, 1280);
  EXPECT_EQ(raw[3].raw, 2048);
  EXPECT_STREQ(raw_parameters(yaw)[1].name(), "yaw_i");
}

TEST(TuneGains, RoundToTheParameterFormats) {
  // P1 in Q<8>: 1/256 steps; P2 and I in Q<4>: 1/16; D in Q<8>.
  auto raw = raw_parameters(RollPitchGains{5.5 + 0.6 / 256, 220.03, 80.49, 8.001});
  EXPECT_EQ(raw[0].raw, 1409);
  EXPECT_EQ(raw[1].raw, 3520);  // 3520.48
  EXPECT_EQ(raw[2].raw, 1288);  // 1287.84
  EXPECT_EQ(raw[3].raw, 2048);  // 2048.256
  raw = raw_parameters(RollPitchGains{5.5 + 0.4 / 256, 220.04, 0, 0});
  EXPECT_EQ(raw[0].raw, 1408);
  EXPECT_EQ(raw[1].raw, 3521);  // 3520.64
  for (const RawParameter& p : raw) EXPECT_FALSE(p.clamped) << p.name();
  // What is flown is what the raw values say.
  const RollPitchGains g = flown(RollPitchGains{5.5 + 0.6 / 256, 220.04, 0, 0});
  EXPECT_EQ(g.p1, 1409 / 256.0);
  EXPECT_EQ(g.p2, 3521 / 16.0);
}

TEST(TuneGains, ClampToTheParameterRanges) {
  const auto raw = raw_parameters(RollPitchGains{25, -3, 2000, std::numeric_limits<double>::quiet_NaN()});
  EXPECT_EQ(raw[0].raw, 5120);  // P1 at most 20 /s
  EXPECT_TRUE(raw[0].clamped);
  EXPECT_EQ(raw[1].raw, 0);
  EXPECT_TRUE(raw[1].clamped);
  EXPECT_EQ(raw[2].raw, 16000);  // I at most 1000
  EXPECT_TRUE(raw[2].clamped);
  EXPECT_EQ(raw[3].raw, 0);  // not a number: the bottom of the range, and said
  EXPECT_TRUE(raw[3].clamped);
  const auto yaw = raw_parameters(YawGains{1000.02, 1000});
  EXPECT_EQ(yaw[0].raw, 16000);  // rounds to the top: in range
  EXPECT_FALSE(yaw[0].clamped);
  EXPECT_EQ(raw_parameters(YawGains{1000.04, 0})[0].raw, 16000);
  EXPECT_TRUE(raw_parameters(YawGains{1000.04, 0})[0].clamped);
  EXPECT_EQ(flown(YawGains{5000, 0}).p, 1000.0);
}

// The text is the value in its unit, exactly: qrsim --param NAME=TEXT uploads the same raw.
TEST(TuneGains, TextIsWhatParamReadsBack) {
  const auto raw = raw_parameters(RollPitchGains{5.5 + 0.6 / 256, 220.0625, 80, 7.05078125});
  EXPECT_EQ(raw[0].text(), "5.50390625");
  EXPECT_EQ(raw[1].text(), "220.0625");
  EXPECT_EQ(raw[2].text(), "80");
  EXPECT_EQ(raw[3].text(), "7.05078125");
  for (double p1 = 0; p1 <= 20; p1 += 0.37) {
    for (double p2 : {0.0, 0.0625, 17.3, 999.9}) {
      for (const RawParameter& p : raw_parameters(RollPitchGains{p1, p2, p2, p1})) {
        wire::ParamId id{};
        int32_t back = -1;
        const std::string problem = qr::host::parameter_from_text(p.name(), p.text(), id, back);
        ASSERT_TRUE(problem.empty()) << problem;
        EXPECT_EQ(id, p.id);
        EXPECT_EQ(back, p.raw) << p.name() << "=" << p.text();
      }
    }
  }
}

}  // namespace
}  // namespace tune
