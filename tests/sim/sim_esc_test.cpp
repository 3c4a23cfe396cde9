// The simulator's DShot ESC (qr/boards/sim/sim_esc.hpp): it reads frames as an ESC firmware does
// and answers with its motor's period.
#include <gtest/gtest.h>

#include <cmath>

#include <common/drivers/dshot.hpp>
#include <common/drivers/erpm.hpp>
#include <qr/boards/sim/sim_esc.hpp>

namespace {

using drivers::DshotLine;

TEST(SimEsc, ABadCheckIsDroppedAndTheLastGoodValueKept) {
  qrsim::SimEsc esc;
  EXPECT_EQ(esc.receive(drivers::dshot_frame(drivers::dshot_throttle(600), false, DshotLine::bidirectional)), 600u);
  const uint16_t good = drivers::dshot_frame(drivers::dshot_throttle(900), false, DshotLine::bidirectional);
  EXPECT_EQ(esc.receive(static_cast<uint16_t>(good ^ 0x0400u)), 600u);
  // The check of a unidirectional frame is the wrong one for a bidirectional ESC.
  EXPECT_EQ(esc.receive(drivers::dshot_frame(drivers::dshot_throttle(900), false, DshotLine::unidirectional)), 600u);
  EXPECT_EQ(esc.rejected(), 2u);
  EXPECT_EQ(esc.receive(good), 900u);
  EXPECT_EQ(esc.receive(drivers::dshot_frame(0, false, DshotLine::bidirectional)), 0u);
}

TEST(SimEsc, ACommandLeavesTheMotorAsItIs) {
  qrsim::SimEsc esc;
  esc.receive(drivers::dshot_frame(0, false, DshotLine::bidirectional));
  EXPECT_EQ(esc.receive(drivers::dshot_frame(21, true, DshotLine::bidirectional)), 0u);
}

// 600 rad/s on 7 pole pairs: 5730 RPM, 40 107 eRPM, a period of 1496 us (code: shift 2, 374).
TEST(SimEsc, TheAnswerIsTheRotorsPeriod) {
  const drivers::ErpmReading r = drivers::decode_erpm_answer(qrsim::SimEsc::answer(600.0, 7));
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.period_us, 1496u);
  const double rpm = 600.0 * 60.0 / (2.0 * M_PI);
  EXPECT_NEAR(static_cast<double>(drivers::rpm_of_period(r.period_us, 7)), rpm, 0.005 * rpm);
  EXPECT_EQ(drivers::decode_erpm_answer(qrsim::SimEsc::answer(0.0, 7)).period_us, 0u);  // stopped
}

}  // namespace
