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

// The spin direction, as BLHeli_32, Bluejay and AM32 take it: at the 6th frame in a row with the
// motor stopped, and kept by a save likewise; fewer in a row, or a throttle frame between, count
// for nothing.
TEST(SimEsc, ASpinDirectionTakesEffectAtItsSixthFrameInARowAndASaveKeepsIt) {
  qrsim::SimEsc esc;
  const auto command = [&](drivers::DshotCommand c) {
    esc.receive(drivers::dshot_frame(static_cast<uint16_t>(c), true, DshotLine::bidirectional));
  };
  esc.receive(drivers::dshot_frame(0, false, DshotLine::bidirectional));
  for (int i = 0; i < 5; ++i) command(drivers::DshotCommand::spin_direction_2);
  EXPECT_FALSE(esc.reversed()) << "five in a row";
  esc.receive(drivers::dshot_frame(0, false, DshotLine::bidirectional));  // a stop frame between
  command(drivers::DshotCommand::spin_direction_2);
  EXPECT_FALSE(esc.reversed()) << "the count starts again";
  for (int i = 0; i < 5; ++i) command(drivers::DshotCommand::spin_direction_2);
  EXPECT_TRUE(esc.reversed()) << "six in a row";
  EXPECT_FALSE(esc.saved_reversed());
  for (int i = 0; i < 6; ++i) command(drivers::DshotCommand::save_settings);
  EXPECT_TRUE(esc.saved_reversed());
  // Under throttle it ignores them.
  esc.receive(drivers::dshot_frame(drivers::dshot_throttle(100), false, DshotLine::bidirectional));
  for (int i = 0; i < 6; ++i) command(drivers::DshotCommand::spin_direction_1);
  EXPECT_TRUE(esc.reversed());
  EXPECT_EQ(esc.commands_while_turning(), 6u);
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
