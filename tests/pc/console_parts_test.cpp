// The console's parts alone (issue 31), without the fake QR: what each decides from its inputs.
// The Console.* suites fly them together; these pin down the rules each part owns.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <pc/core/descent_warning.hpp>
#include <pc/core/exit_handshake.hpp>
#include <pc/core/pilot_input.hpp>
#include <pc/core/qr_reports.hpp>
#include <pc/core/radio_pilot.hpp>
#include <pc/core/simulator_controls.hpp>

namespace {

using namespace qrterm;

// Collects what a part tells the pilot.
struct Said {
  std::vector<Notice> lines;
  std::function<void(Severity, const std::string&)> hook() {
    return [this](Severity severity, const std::string& text) { lines.push_back({severity, text}); };
  }
};

TelemetryModel radio_flying(bool radio) {
  TelemetryModel telemetry;
  telemetry.radio = wire::TelemetryRadio{};
  telemetry.radio->flags = static_cast<uint8_t>(wire::kRadioLinkUp | (radio ? wire::kRadioPilot : 0));
  return telemetry;
}

TEST(RadioPilot, OnlyTheSimulatorsRadioTakesTheSwitchsModesAndArmsOnlyFromSafe) {
  const TelemetryModel radio = radio_flying(true), pc = radio_flying(false);
  for (uint8_t position = 0; position < wire::kModeSwitchPositions; ++position) {
    const wire::Mode mode = wire::mode_at_switch(position);
    EXPECT_EQ(radio_arming(mode, true, true, radio), RadioArming::arm) << wire::mode_name(mode);
    EXPECT_EQ(radio_arming(mode, false, true, radio), RadioArming::refused) << wire::mode_name(mode);
    EXPECT_EQ(radio_arming(mode, true, false, radio), RadioArming::console) << "a real radio's switches";
    EXPECT_EQ(radio_arming(mode, true, true, pc), RadioArming::console) << "the PC flies";
  }
  for (const wire::Mode mode :
       {wire::Mode::safe, wire::Mode::panic, wire::Mode::calibration, wire::Mode::height_hold, wire::Mode::acro}) {
    EXPECT_FALSE(wire::armed_by_the_radio(mode)) << wire::mode_name(mode);
    EXPECT_EQ(radio_arming(mode, true, true, radio), RadioArming::console) << wire::mode_name(mode);
  }
  EXPECT_FALSE(radio_flies(TelemetryModel{})) << "no telemetry_radio yet: the PC flies";
}

TEST(SimulatorControls, WithoutASimulatorEachKeySaysSoAndSendsNothing) {
  Said said;
  SimulatorControls simulator(false, said.hook());
  for (const Action action : {Action::sim_push, Action::sim_reset, Action::sim_turn, Action::sim_radio_off}) {
    EXPECT_TRUE(simulator.act(action));
  }
  EXPECT_FALSE(simulator.act(Action::lift_up)) << "not the simulator's key";
  ASSERT_EQ(said.lines.size(), 4u);
  for (const Notice& line : said.lines) {
    EXPECT_EQ(line.severity, Severity::warning);
    EXPECT_EQ(line.text.rfind("no simulator: ", 0), 0u) << line.text;
  }
  EXPECT_TRUE(simulator.take_commands().empty());
  EXPECT_FALSE(simulator.take_mode_request(wire::Mode::manual, true, radio_flying(true)));
}

TEST(SimulatorControls, TheTurnKeyTakesTheAxesInTheCalibrationsOrder) {
  Said said;
  SimulatorControls simulator(true, said.hook());
  for (int i = 0; i < 4; ++i) simulator.act(Action::sim_turn);
  EXPECT_EQ(simulator.take_commands(),
            (std::vector<std::string>{"turn z 2 4\n", "turn x 2 4\n", "turn y 2 4\n", "turn z 2 4\n"}));
  EXPECT_TRUE(simulator.take_commands().empty()) << "taken once";
}

// The orientation check's hand: one tilt a step, the positive way about x, y, z; without a
// simulator nothing is sent and the check asks the pilot's hand instead.
TEST(SimulatorControls, TheOrientationChecksHandTiltsAboutEachBodyAxis) {
  Said said;
  SimulatorControls simulator(true, said.hook());
  for (size_t axis = 0; axis < 3; ++axis) EXPECT_TRUE(simulator.hand_tilt(axis));
  EXPECT_EQ(simulator.take_commands(), (std::vector<std::string>{"tilt x 45 1\n", "tilt y 45 1\n", "tilt z 45 1\n"}));
  EXPECT_EQ(said.lines.back().text, "sim: the hand tilts the QR nose right 45 deg, holds it and sets it down");
  SimulatorControls none(false, said.hook());
  EXPECT_FALSE(none.hand_tilt(0));
  EXPECT_TRUE(none.take_commands().empty());
}

TEST(SimulatorControls, ATruthLineIsKeptForTheScreenAndDrawnInRadians) {
  Said said;
  SimulatorControls simulator(true, said.hook());
  const auto truth = simulator.on_line("truth t=1.000 roll=10.0 pitch=-5.0 yaw=90.0 height=1.50 climb=0.20", 3000);
  ASSERT_TRUE(truth);
  EXPECT_EQ(simulator.truth(), "truth roll +10.0 pitch -5.0 yaw +90.0 height 1.50 m");
  EXPECT_NEAR(truth->roll, 10.0 * M_PI / 180, 1e-12);
  EXPECT_NEAR(truth->yaw, M_PI / 2, 1e-12);
  EXPECT_DOUBLE_EQ(truth->climb, 0.20);
  EXPECT_EQ(simulator.clock_offset_ms(), 2000);
  // The offset is the line that waited least: a later, slower line does not move it.
  simulator.on_line("truth t=2.000 roll=0 pitch=0 yaw=0 height=0", 4050);
  EXPECT_EQ(simulator.clock_offset_ms(), 2000);
  EXPECT_TRUE(std::isnan(simulator.on_line("truth t=3 roll=0 pitch=0 yaw=0 height=0", 5000)->climb))
      << "an older simulator's line has no climb";
  EXPECT_FALSE(simulator.on_line("ok push", 5000));
  EXPECT_FALSE(simulator.on_line("error: engines running", 5000));
  ASSERT_EQ(said.lines.size(), 1u);
  EXPECT_EQ(said.lines[0].text, "sim: error: engines running");
}

TEST(ExitHandshake, AsksOnceAndEndsOnceWhateverEndsTheWait) {
  Said said;
  ExitHandshake unanswered(said.hook());
  EXPECT_TRUE(unanswered.request(true, 100));
  unanswered.tick(100 + kExitWaitMs - 1);
  EXPECT_FALSE(unanswered.done());
  unanswered.tick(100 + kExitWaitMs);
  EXPECT_TRUE(unanswered.done());
  EXPECT_FALSE(unanswered.confirmed());
  EXPECT_FALSE(unanswered.request(true, 5000)) << "done: nothing more to ask";

  ExitHandshake confirmed(said.hook());
  EXPECT_TRUE(confirmed.request(true, 0));
  confirmed.on_answer(wire::NackReason::none);
  EXPECT_TRUE(confirmed.done() && confirmed.confirmed());

  ExitHandshake impatient(said.hook());
  EXPECT_TRUE(impatient.request(true, 0));
  EXPECT_FALSE(impatient.request(true, 10)) << "a second request does not ask again";
  EXPECT_TRUE(impatient.done());

  ExitHandshake alone(said.hook());
  EXPECT_FALSE(alone.request(false, 0)) << "no QR to tell";
  EXPECT_TRUE(alone.done());
  EXPECT_EQ(said.lines.back().text, "exit: no QR to tell");
}

TEST(DescentWatch, RisesWithOneLineHoldsWithoutAnotherAndLandingEndsIt) {
  TelemetryModel telemetry;
  telemetry.attitude = wire::TelemetryAttitude{};
  telemetry.attitude->mode = wire::Mode::manual;
  telemetry.attitude->flags = wire::kFlagFlying;
  const wire::TelemetryHeight falling{7000, -5700, wire::kHeightValid, 529};
  const wire::TelemetryHeight stopped{3000, 0, wire::kHeightValid, 529};
  DescentWatch watch;
  const std::string line = watch.on_height(falling, telemetry, true, 1000);
  EXPECT_EQ(line.rfind("SINKING 5.7 m/s at 7.0 m", 0), 0u) << line;
  EXPECT_NE(line.find("lift now (PgUp)"), std::string::npos) << line;
  EXPECT_EQ(watch.on_height(falling, telemetry, true, 1120), "") << "one line while it stands";
  EXPECT_EQ(watch.on_height(stopped, telemetry, true, 1120 + kSinkingHoldMs - 1), "");
  EXPECT_EQ(watch.speed_m_s(), 0.0) << "held, at the speed now";
  watch.on_height(stopped, telemetry, true, 1120 + kSinkingHoldMs);
  EXPECT_FALSE(watch.speed_m_s());

  watch.on_height(falling, telemetry, true, 5000);
  telemetry.attitude->flags = 0;  // landed
  watch.on_height(stopped, telemetry, true, 5001);
  EXPECT_FALSE(watch.speed_m_s()) << "landed ends it at once";
}

TEST(PilotInput, ASecondEscapeInARowExitsAndAnyOtherKeyBreaksThePair) {
  PilotInput input(false);
  EXPECT_FALSE(input.cockpit_key(kKeyEscape).second_escape);
  EXPECT_TRUE(input.cockpit_key(kKeyEscape).second_escape);
  EXPECT_FALSE(input.cockpit_key(kKeyEscape).second_escape) << "a third starts a new pair";
  input.screen_key();
  EXPECT_FALSE(input.cockpit_key(kKeyEscape).second_escape) << "a screen's key broke the pair";
  input.cockpit_key('a');
  EXPECT_FALSE(input.cockpit_key(kKeyEscape).second_escape) << "a cockpit key broke the pair";
}

TEST(PilotInput, AJoystickThatIsNotThereOrNotReadKeepsTheQrInSafe) {
  PilotInput keyboard(false);
  EXPECT_EQ(keyboard.refuses_flight(), "");
  EXPECT_FALSE(keyboard.joystick_lost()) << "no joystick to lose";

  PilotInput input(true);
  EXPECT_NE(input.refuses_flight(), "") << "position not reported yet";
  input.joystick_moved(true);
  EXPECT_EQ(input.refuses_flight(), "");
  EXPECT_TRUE(input.joystick_lost());
  EXPECT_EQ(input.joystick(), JoystickState::lost);
  EXPECT_NE(input.refuses_flight().find("gone"), std::string::npos);
  EXPECT_TRUE(input.joystick_back());
  EXPECT_NE(input.refuses_flight(), "") << "back, but its position not reported again yet";
}

TEST(QrReports, AChangeIsToldOnceNotAtEveryReport) {
  wire::TelemetryAttitude before{};
  wire::TelemetryAttitude now{};
  now.mode = wire::Mode::panic;
  now.flags = wire::kFlagCalibrated | wire::kFlagBatteryWarning;
  const std::vector<Notice> told = attitude_notices(before, now);
  ASSERT_EQ(told.size(), 3u);
  EXPECT_EQ(told[0].text, "QR mode: panic");
  EXPECT_EQ(told[0].severity, Severity::warning);
  EXPECT_EQ(told[1].text, "QR calibrated");
  EXPECT_EQ(told[2].text, "QR battery low");
  EXPECT_TRUE(attitude_notices(now, now).empty());
  EXPECT_EQ(attitude_notices(std::nullopt, before).size(), 1u) << "the first report says the mode";
  EXPECT_EQ(attitude_notices(before, now, "the pilot (key 0, safe from flight goes through panic)")[0].text,
            "QR mode: panic: asked by the pilot (key 0, safe from flight goes through panic)");

  wire::LogStatus full{};
  full.flags = wire::kLogStatusFull;
  full.capacity_lines = 1820;
  full.sensor_lines = 1820;
  const std::vector<Notice> logs = log_status_notices(std::nullopt, full, 10, 1000);
  ASSERT_FALSE(logs.empty());
  EXPECT_EQ(logs.back().text, "QR log full (1820 lines): it keeps its first lines");
  EXPECT_TRUE(log_status_notices(full, full, 10, 1000).empty());
}

}  // namespace
