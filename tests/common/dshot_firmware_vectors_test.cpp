// DShot frames and bidirectional answers from a flight firmware's own test suite, taken as facts:
// ESP-FC's ESC driver test, test/test_esc/test_esc.cpp (github.com/rtlopez/esp-fc, read at commit
// 082c52b2718965127f5d555abf7abc97fc2b3461). The numbers that test asserts are quoted as data; the
// code here is ours. (The worked example of docs/drivers.md comes from the DShot Handbook.)
#include <gtest/gtest.h>

#include <common/drivers/dshot.hpp>
#include <common/drivers/erpm.hpp>

namespace {

// test_esc_dshot_encode and test_esc_dshot_encode_inverted: the 16-bit frame of a value with no
// telemetry request, with the check as is and inverted (bidirectional).
TEST(DshotFirmwareVectors, EspFcsFramesAndChecks) {
  const struct {
    uint16_t value, frame, bidirectional;
  } cases[] = {{0, 0, 15},           {1, 34, 45},          {2, 68, 75},
               {47, 1515, 1508},     {1000, 32010, 32005}, {1001, 32040, 32039},
               {1023, 32742, 32745}, {1024, 32776, 32775}, {2047, 65518, 65505}};
  for (const auto& c : cases) {
    EXPECT_EQ(drivers::dshot_frame(c.value, false, drivers::DshotLine::unidirectional), c.frame) << c.value;
    EXPECT_EQ(drivers::dshot_frame(c.value, false, drivers::DshotLine::bidirectional), c.bidirectional) << c.value;
    // An ESC reads each back (our decoder, as the simulator's ESC uses it).
    const drivers::DshotDecoded d = drivers::dshot_decode(c.frame, drivers::DshotLine::unidirectional);
    EXPECT_TRUE(d.valid) << c.value;
    EXPECT_EQ(d.value, c.value);
  }
}

// test_esc_gcr_to_raw_value, test_esc_gcr_convert_to_value: six answers as the 21 line bits and
// the period each stands for, in us (ESP-FC's 12-bit code 1942 is shift 3, mantissa 406: 3248 us).
TEST(DshotFirmwareVectors, EspFcsAnswersDecodeToTheirPeriods) {
  const struct {
    uint32_t line;
    uint32_t period_us;
  } cases[] = {{0b011010011101101100101, 3248}, {0b011010011101001110001, 3264}, {0b011010011100110110011, 3288},
               {0b011010011101010001001, 3296}, {0b011010011100100101011, 3304}, {0b011010011100101110101, 3312}};
  for (const auto& c : cases) {
    const drivers::ErpmReading r = drivers::decode_erpm_answer(c.line);
    EXPECT_TRUE(r.valid) << std::hex << c.line;
    EXPECT_EQ(r.period_us, c.period_us) << std::hex << c.line;
  }
}

// test_esc_extract_telemetry_dshot300_idle / _sample / _running: answers captured from an ESC on
// DShot300, as the 21 line bits the test extracts: a stopped motor (code 0xFFF), a
// period of 0x13A0 = 5024 us and one of 0x8D0 = 2256 us. ESP-FC gives eRPM in hundreds, rounded
// (119 and 266) and, for 14 poles, 1700 and 3800 RPM from those hundreds; ours is exact, so it
// lies within half a hundred of theirs.
TEST(DshotFirmwareVectors, EspFcsCapturedAnswers) {
  const drivers::ErpmReading idle = drivers::decode_erpm_answer(0x52951);
  EXPECT_TRUE(idle.valid);
  EXPECT_EQ(idle.period_us, 0u) << "stopped";
  EXPECT_EQ(drivers::erpm_of_period(idle.period_us), 0u);

  const struct { uint32_t line, period_us, erpm_hundreds; } cases[] = {{0x77675, 0x13A0, 119}, {0xD499D, 0x08D0, 266}};
  for (const auto& c : cases) {
    const drivers::ErpmReading r = drivers::decode_erpm_answer(c.line);
    ASSERT_TRUE(r.valid) << std::hex << c.line;
    EXPECT_EQ(r.period_us, c.period_us) << std::hex << c.line;
    const uint32_t erpm = drivers::erpm_of_period(r.period_us);
    EXPECT_LE(erpm, c.erpm_hundreds * 100 + 50) << erpm;
    EXPECT_GE(erpm, c.erpm_hundreds * 100 - 50) << erpm;
  }
}

// test_esc_gcr_convert_to_erpm: period in us -> eRPM in hundreds (60, 120, 300, 600, 1200, 3000,
// 6000 for 10 000 .. 100 us; each exact, so ours is a hundred times theirs).
TEST(DshotFirmwareVectors, EspFcsPeriodsToErpm) {
  const struct {
    uint32_t period_us, erpm_hundreds;
  } cases[] = {{10000, 60}, {5000, 120}, {2000, 300}, {1000, 600}, {500, 1200}, {200, 3000}, {100, 6000}};
  for (const auto& c : cases) EXPECT_EQ(drivers::erpm_of_period(c.period_us), c.erpm_hundreds * 100) << c.period_us;
}

}  // namespace
