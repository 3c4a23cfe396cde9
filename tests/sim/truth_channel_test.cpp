// The serve mode side channel's command parser and truth line (qr/sim_runner/truth_channel.hpp).
#include <gtest/gtest.h>

#include <qr/sim_runner/truth_channel.hpp>
#include <sim/quaternion.hpp>

namespace {

TEST(TruthChannel, ParsesAPush) {
  qrsim::TruthCommand push;
  std::string error;
  ASSERT_TRUE(qrsim::parse_truth_command("push 0.3 -0.1 0 0.1", push, error)) << error;
  EXPECT_DOUBLE_EQ(push.torque.x, 0.3);
  EXPECT_DOUBLE_EQ(push.torque.y, -0.1);
  EXPECT_DOUBLE_EQ(push.torque.z, 0.0);
  EXPECT_DOUBLE_EQ(push.seconds, 0.1);
  ASSERT_TRUE(qrsim::parse_truth_command("  push\t1 2 3 0.5\r", push, error)) << error;
  EXPECT_DOUBLE_EQ(push.torque.z, 3.0);
}

TEST(TruthChannel, ParsesAReset) {
  qrsim::TruthCommand command;
  std::string error;
  ASSERT_TRUE(qrsim::parse_truth_command(" reset\r", command, error)) << error;
  EXPECT_EQ(command.kind, qrsim::TruthCommand::Kind::reset);
  EXPECT_FALSE(qrsim::parse_truth_command("reset 1", command, error));
  EXPECT_NE(error.find("reset takes nothing"), std::string::npos) << error;
  ASSERT_TRUE(qrsim::parse_truth_command("push 1 0 0 1", command, error)) << error;
  EXPECT_EQ(command.kind, qrsim::TruthCommand::Kind::push) << "a push after a reset is a push";
}

// A hand turn: axis, whole turns, seconds; the same limits as the scenario event.
TEST(TruthChannel, ParsesATurn) {
  qrsim::TruthCommand command;
  std::string error;
  ASSERT_TRUE(qrsim::parse_truth_command(" turn x -2 4\r", command, error)) << error;
  EXPECT_EQ(command.kind, qrsim::TruthCommand::Kind::turn);
  EXPECT_EQ(command.turn.axis, sim::BodyAxis::x);
  EXPECT_EQ(command.turn.turns, -2);
  EXPECT_EQ(command.turn.seconds, 4);
  const struct {
    const char* line;
    const char* error;
  } bad[] = {
      {"turn", "turn needs AXIS N SECONDS (AXIS x, y or z; N whole turns)"},
      {"turn z 1", "turn needs AXIS N SECONDS (AXIS x, y or z; N whole turns)"},
      {"turn q 1 2", "turn: axis is x, y or z, not 'q'"},
      {"turn z one 2", "turn: bad number in 'one 2'"},
      {"turn z 0.5 2", "turn: turns must be a whole number, not 0, within +-10"},
      {"turn z 0 2", "turn: turns must be a whole number, not 0, within +-10"},
      {"turn z 1e300 2", "turn: turns must be a whole number, not 0, within +-10"},
      {"turn z 1 0.1", "turn: a turn takes 0.5 .. 60 s"},
      {"turn z 1 1", "turn: peak rate 4 pi |N| / S = 12.57 rad/s is beyond the gyro's 8 rad/s: take longer"},
  };
  for (const auto& b : bad) {
    EXPECT_FALSE(qrsim::parse_truth_command(b.line, command, error)) << b.line;
    EXPECT_EQ(error, b.error) << b.line;
  }
}

// A hand tilt: axis, angle in degrees, seconds; the limits of sim/hand_tilt.hpp.
TEST(TruthChannel, ParsesATilt) {
  qrsim::TruthCommand command;
  std::string error;
  ASSERT_TRUE(qrsim::parse_truth_command(" tilt y -30 2\r", command, error)) << error;
  EXPECT_EQ(command.kind, qrsim::TruthCommand::Kind::tilt);
  EXPECT_EQ(command.tilt.axis, sim::BodyAxis::y);
  EXPECT_EQ(command.tilt.degrees, -30);
  EXPECT_EQ(command.tilt.seconds, 2);
  const struct {
    const char* line;
    const char* error;
  } bad[] = {
      {"tilt", "tilt needs AXIS DEG SECONDS (AXIS x, y or z)"},
      {"tilt x 45", "tilt needs AXIS DEG SECONDS (AXIS x, y or z)"},
      {"tilt w 45 2", "tilt: axis is x, y or z, not 'w'"},
      {"tilt x far 2", "tilt: bad number in 'far 2'"},
      {"tilt x 0 2", "tilt: the angle is a tilt: not 0, within +-90 degrees"},
      {"tilt x -120 2", "tilt: the angle is a tilt: not 0, within +-90 degrees"},
      {"tilt x 45 0.2", "tilt: a tilt takes 0.5 .. 60 s"},
      {"tilt x 90 0.5", "tilt: peak rate 3 pi |A| / (2 S) = 14.80 rad/s is beyond the gyro's 8 rad/s: take longer"},
  };
  for (const auto& b : bad) {
    EXPECT_FALSE(qrsim::parse_truth_command(b.line, command, error)) << b.line;
    EXPECT_EQ(error, b.error) << b.line;
  }
}

// The radio's switches (qrsim --serve --rc crsf): arm one of the three modes its mode switch
// picks, or the arm switch off; anything else names what the radio takes.
TEST(TruthChannel, ParsesTheRadiosSwitches) {
  qrsim::TruthCommand command;
  std::string error;
  ASSERT_TRUE(qrsim::parse_truth_command("radio arm manual", command, error)) << error;
  EXPECT_EQ(command.kind, qrsim::TruthCommand::Kind::radio_arm);
  EXPECT_EQ(command.mode, wire::Mode::manual);
  ASSERT_TRUE(qrsim::parse_truth_command("radio arm yaw", command, error)) << error;
  EXPECT_EQ(command.mode, wire::Mode::yaw_control);
  ASSERT_TRUE(qrsim::parse_truth_command(" radio  arm full\r", command, error)) << error;
  EXPECT_EQ(command.mode, wire::Mode::full_control);
  ASSERT_TRUE(qrsim::parse_truth_command("radio off", command, error)) << error;
  EXPECT_EQ(command.kind, qrsim::TruthCommand::Kind::radio_off);
  for (const char* bad : {"radio", "radio arm", "radio arm height", "radio arm safe", "radio on", "radio off now"}) {
    EXPECT_FALSE(qrsim::parse_truth_command(bad, command, error)) << bad;
    EXPECT_EQ(error, "radio takes 'arm manual', 'arm yaw', 'arm full' or 'off'") << bad;
  }
}

// After a panic the vehicle may lie on its side: a reset sets it level and still at the ground,
// where it lay and facing the way it faced.
TEST(TruthChannel, ResetSetsTheVehicleDownUpright) {
  sim::PlantState tilted;
  tilted.position = sim::Vec3{1.5, -2.0, -0.3};
  tilted.velocity = sim::Vec3{0.2, 0.1, 0.4};
  tilted.attitude = sim::from_euler(sim::Euler{0.84, -0.3, 1.2});
  tilted.rate = sim::Vec3{1, 2, 3};
  tilted.rotor_speed = {100, -100, 100, -100};
  const sim::PlantState upright = qrsim::reset_state(tilted);
  const sim::Euler e = sim::to_euler(upright.attitude);
  EXPECT_NEAR(e.roll, 0, 1e-12);
  EXPECT_NEAR(e.pitch, 0, 1e-12);
  EXPECT_NEAR(e.yaw, 1.2, 1e-9);
  EXPECT_DOUBLE_EQ(upright.position.x, 1.5);
  EXPECT_DOUBLE_EQ(upright.position.y, -2.0);
  EXPECT_DOUBLE_EQ(upright.position.z, 0.0);
  for (const double v :
       {upright.velocity.x, upright.velocity.y, upright.velocity.z, upright.rate.x, upright.rate.y, upright.rate.z})
    EXPECT_EQ(v, 0.0);
  for (const double w : upright.rotor_speed) EXPECT_EQ(w, 0.0);
}

TEST(TruthChannel, RefusesBadLines) {
  qrsim::TruthCommand push;
  std::string error;
  EXPECT_FALSE(qrsim::parse_truth_command("", push, error));
  EXPECT_EQ(error, "empty command");
  EXPECT_FALSE(qrsim::parse_truth_command("shove 1 2 3 4", push, error));
  EXPECT_EQ(error.rfind("unknown command 'shove'", 0), 0u) << error;
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 2 3", push, error));
  EXPECT_EQ(error, "push needs TX TY TZ SECONDS");
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 2 3 4 5", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 x 3 0.1", push, error));
  EXPECT_EQ(error, "bad number 'x'");
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 nan 3 0.1", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 11 0 0 0.1", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 0 0 0", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 0 0 -1", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 0 0 11", push, error));
}

TEST(TruthChannel, TruthLineFormat) {
  sim::Quadrotor plant(sim::default_vehicle());
  sim::PlantState s;
  s.position = {0.1, -0.02, -1.5};
  s.velocity = {0, 0, -0.25};
  s.rotor_speed = {0, 104.72, 0, 0.04};
  plant.set_state(s);
  EXPECT_EQ(qrsim::truth_line(12.34, plant),
            "truth t=12.340 roll=0.00 pitch=0.00 yaw=0.00 height=1.500 north=0.100 east=-0.020 climb=0.250 "
            "rotors=0.0,-104.7,0.0,0.0\n")
      << "the right rotor turns counter-clockwise seen from above; a still one is 0.0, unsigned";
}

// The devboard's figures for the console's CPU row (issue 36): its clock and the tick's RV32
// instructions, which the QR's own load cannot give while the board's time stands still in a tick.
TEST(TruthChannel, TheDevboardLineCarriesItsClockAndTheTicksInstructions) {
  EXPECT_EQ(qrsim::devboard_line(12.34, 16, 2738.4, 8012, 12340),
            "devboard t=12.340 core_mhz=16 tick_instr_mean=2738 tick_instr_max=8012 ticks=12340\n");
  EXPECT_EQ(qrsim::devboard_line(1, 0, 2738.6, 8012, 1000),
            "devboard t=1.000 core_mhz=0 tick_instr_mean=2739 tick_instr_max=8012 ticks=1000\n");
}

}  // namespace
