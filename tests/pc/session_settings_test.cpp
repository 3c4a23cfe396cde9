// Settings that do not trap (issue 36): a saved `pilot = 1` made the next plain start unable to
// arm, with no word of why. At start each saved value this session cannot use is named with its
// fix; at exit each change saved is named with the line that undoes it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <pc/core/session_settings.hpp>

namespace qrterm {
namespace {

wire::ParameterValues with(wire::ParamId id, int32_t raw) {
  wire::ParameterValues values;
  EXPECT_EQ(values.set(static_cast<uint8_t>(id), raw), wire::NackReason::none);
  return values;
}

TEST(SessionSettings, ARadioPilotWithoutARadioIsNamedWithItsFix) {
  const wire::ParameterValues radio_pilot = with(wire::ParamId::pilot, 1);
  const std::vector<std::string> traps = settings_that_trap(radio_pilot, {.simulator = true, .simulator_radio = false});
  ASSERT_EQ(traps.size(), 1u);
  EXPECT_EQ(traps[0].rfind("pilot = 1 (the radio flies) but this simulator has no radio", 0), 0u) << traps[0];
  EXPECT_NE(traps[0].find("Set pilot 0 on the parameter screen"), std::string::npos) << "the fix";
  EXPECT_NE(traps[0].find("scripts/run --radio"), std::string::npos) << "or the other fix";

  EXPECT_TRUE(settings_that_trap(radio_pilot, {.simulator = true, .simulator_radio = true}).empty());
  EXPECT_TRUE(settings_that_trap(radio_pilot, {.simulator = false}).empty()) << "a real QR may well have its radio";
  EXPECT_TRUE(settings_that_trap(wire::ParameterValues{}, {.simulator = true}).empty()) << "the defaults trap nobody";
}

TEST(SessionSettings, ASavedGyroTurnsIsNamed) {
  const std::vector<std::string> traps = settings_that_trap(with(wire::ParamId::gyro_turns, 2), {});
  ASSERT_EQ(traps.size(), 1u);
  EXPECT_EQ(traps[0].rfind("gyro_turns = 2 from the parameter file: the next calibration (3) waits", 0), 0u)
      << traps[0];
}

TEST(SessionSettings, TheSimulatorsArgumentsSayWhetherItHasARadio) {
  EXPECT_TRUE(simulator_has_radio({"--rc", "crsf"}));
  EXPECT_FALSE(simulator_has_radio({"--devboard", "qr.elf"}));
  EXPECT_FALSE(simulator_has_radio({}));
}

TEST(SessionSettings, EachChangeIsNamedWithItsUndo) {
  wire::ParameterValues after = with(wire::ParamId::pilot, 1);
  ASSERT_EQ(after.set(static_cast<uint8_t>(wire::ParamId::roll_pitch_p1), 1472), wire::NackReason::none);  // 5.75
  const std::vector<std::string> lines = undo_lines(wire::ParameterValues{}, after);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "roll_pitch_p1 5.5 -> 5.75           undo: roll_pitch_p1 = 5.5");
  EXPECT_EQ(lines[1], "pilot 0 -> 1                        undo: pilot = 0");
}

}  // namespace
}  // namespace qrterm
