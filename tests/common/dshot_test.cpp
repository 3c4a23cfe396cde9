// DShot frames against published vectors and the protocol's rules (common/drivers/dshot.hpp).
#include <gtest/gtest.h>

#include <common/drivers/dshot.hpp>
#include <common/drivers/dshot_commands.hpp>

namespace {

using drivers::DshotLine;

// "DSHOT - the missing Handbook" (brushlesswhoop.com), its worked example: throttle 1046, no
// telemetry request: 10000010110 0 0110.
TEST(Dshot, TheHandbooksWorkedExample) {
  EXPECT_EQ(drivers::dshot_checksum(1046u << 1), 0x6u);
  EXPECT_EQ(drivers::dshot_frame(1046, false, DshotLine::unidirectional), 0x82C6u);
}

// Bidirectional DShot sends the check inverted (Handbook, "Bidirectional DShot"): 1046 -> 0x82C9.
TEST(Dshot, BidirectionalInvertsTheCheck) {
  EXPECT_EQ(drivers::dshot_frame(1046, false, DshotLine::bidirectional), 0x82C9u);
  for (uint16_t v = 0; v <= drivers::kDshotValueMax; ++v) {
    for (bool t : {false, true}) {
      const uint16_t uni = drivers::dshot_frame(v, t, DshotLine::unidirectional);
      const uint16_t bi = drivers::dshot_frame(v, t, DshotLine::bidirectional);
      ASSERT_EQ(uni >> 4, bi >> 4);
      ASSERT_EQ((uni ^ bi) & 0xFu, 0xFu);
    }
  }
}

// The XOR of all four nibbles of a good frame is 0 (0xF bidirectional): the check an ESC makes.
TEST(Dshot, EveryFrameDecodesAndEveryBitFlipIsCaught) {
  for (DshotLine line : {DshotLine::unidirectional, DshotLine::bidirectional}) {
    for (uint16_t v = 0; v <= drivers::kDshotValueMax; ++v) {
      const uint16_t f = drivers::dshot_frame(v, (v & 1) != 0, line);
      const drivers::DshotDecoded d = drivers::dshot_decode(f, line);
      ASSERT_TRUE(d.valid);
      ASSERT_EQ(d.value, v);
      ASSERT_EQ(d.telemetry_request, (v & 1) != 0);
      for (int bit = 0; bit < 16; ++bit) {
        ASSERT_FALSE(drivers::dshot_decode(static_cast<uint16_t>(f ^ (1u << bit)), line).valid) << v << " bit " << bit;
      }
    }
  }
}

TEST(Dshot, TelemetryRequestIsBitFour) {
  EXPECT_EQ(drivers::dshot_frame(0, true, DshotLine::unidirectional), 0x0011u);  // 0 0...01 0001
  EXPECT_EQ(drivers::dshot_frame(0, false, DshotLine::unidirectional), 0x0000u);
}

TEST(Dshot, EngineZeroStopsTheMotorAndTheRangeIsThrottle) {
  EXPECT_EQ(drivers::dshot_throttle(0), 0u);
  EXPECT_EQ(drivers::dshot_throttle(1), 49u);
  EXPECT_EQ(drivers::dshot_throttle(1000), 2047u);
  EXPECT_EQ(drivers::dshot_throttle(4000), 2047u);  // beyond the scale: full, never a wrapped value
  for (uint16_t e = 1; e <= 1000; ++e) {
    const uint16_t t = drivers::dshot_throttle(e);
    ASSERT_GE(t, drivers::kDshotThrottleMin);  // never a command
    ASSERT_EQ(drivers::dshot_engine(t), e);    // the ESC's reading gives the engine value back
  }
  EXPECT_EQ(drivers::dshot_engine(0), 0u);
  EXPECT_EQ(drivers::dshot_engine(47), 0u);
  EXPECT_EQ(drivers::dshot_engine(48), 0u);
}

// The Handbook's table: DShot600 bit 1.67 us, T1H 1.25 us, T0H 0.625 us; 300 and 150 twice and
// four times as long.
TEST(Dshot, BitTimingIsTheHandbooks) {
  const drivers::DshotTiming& d600 = drivers::dshot_timing(drivers::DshotSpeed::dshot600);
  EXPECT_EQ(d600.bit_ns, 1667u);
  EXPECT_EQ(d600.t1h_ns, 1250u);
  EXPECT_EQ(d600.t0h_ns, 625u);
  const drivers::DshotTiming& d300 = drivers::dshot_timing(drivers::DshotSpeed::dshot300);
  EXPECT_EQ(d300.t1h_ns, 2 * d600.t1h_ns);
  EXPECT_EQ(d300.t0h_ns, 2 * d600.t0h_ns);
  const drivers::DshotTiming& d150 = drivers::dshot_timing(drivers::DshotSpeed::dshot150);
  EXPECT_EQ(d150.t1h_ns, 4 * d600.t1h_ns);
  EXPECT_EQ(d150.t0h_ns, 4 * d600.t0h_ns);
  EXPECT_EQ(d150.bit_ns, 6667u);
  // A 100 MHz timer: 167 ticks a bit, 125 high for a 1 (compile time only).
  static_assert(drivers::timer_ticks(1667, 100000000u) == 167u);
  static_assert(drivers::timer_ticks(1250, 100000000u) == 125u);
}

// BLHeli_32 "Dshotprog spec": commands 7-12 (and the later 13, 14, 20, 21, 32-35) need 6 in a row.
TEST(DshotCommands, SettingCommandsRepeatSixTimesOthersOnce) {
  for (uint8_t c = 1; c <= drivers::kDshotCommandMax; ++c) {
    const bool setting = (c >= 7 && c <= 14) || c == 20 || c == 21 || (c >= 32 && c <= 35);
    EXPECT_EQ(drivers::dshot_repeats(c), setting ? 6u : 1u) << int{c};
  }
}

TEST(DshotCommands, ACommandIsSentItsRepeatsWithTheRequestBitThenThrottle) {
  drivers::DshotCommandSequencer seq;
  ASSERT_TRUE(seq.request(static_cast<uint8_t>(drivers::DshotCommand::spin_direction_reversed), 0));
  for (int i = 0; i < 6; ++i) {
    const drivers::DshotDecoded d = drivers::dshot_decode(seq.next_frame(0, DshotLine::bidirectional, false),
                                                          DshotLine::bidirectional);
    ASSERT_TRUE(d.valid);
    EXPECT_EQ(d.value, 21u);
    EXPECT_TRUE(d.telemetry_request);
  }
  EXPECT_FALSE(seq.busy());
  EXPECT_EQ(drivers::dshot_decode(seq.next_frame(0, DshotLine::bidirectional, false), DshotLine::bidirectional).value,
            0u);
}

TEST(DshotCommands, CommandsOnlyWhenStopped) {
  drivers::DshotCommandSequencer seq;
  EXPECT_FALSE(seq.request(static_cast<uint8_t>(drivers::DshotCommand::beep1), 300));  // turning: refused
  EXPECT_FALSE(seq.request(0, 0));                                                     // not a command
  EXPECT_FALSE(seq.request(48, 0));                                                    // throttle, not a command
  ASSERT_TRUE(seq.request(static_cast<uint8_t>(drivers::DshotCommand::save_settings), 0));
  (void)seq.next_frame(0, DshotLine::unidirectional, false);
  // The engine starts before the repeats are out: throttle wins and the command is dropped.
  EXPECT_EQ(
      drivers::dshot_decode(seq.next_frame(500, DshotLine::unidirectional, false), DshotLine::unidirectional).value,
      drivers::dshot_throttle(500));
  EXPECT_FALSE(seq.busy());
  EXPECT_EQ(drivers::dshot_decode(seq.next_frame(0, DshotLine::unidirectional, false), DshotLine::unidirectional).value,
            0u);
}

}  // namespace
