// The scenario file format: what a good file reads as, and for each kind of mistake a message
// that names the file and the line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <qr/sim_runner/scenario.hpp>
#include <qr/sim_runner/scenario_script.hpp>

namespace {

struct Parsed {
  bool ok;
  qrsim::ScenarioScript script;
  std::string error;
};

Parsed parse(const std::string& text) {
  Parsed p;
  p.ok = qrsim::parse_scenario(text, "mine", "mine.txt", p.script, p.error);
  return p;
}

TEST(ScenarioFile, ReadsSettingsEventsAndBands) {
  const Parsed p = parse(
      "# a comment\n"
      "summary: a test flight  # trailing comment\n"
      "seconds: 12\n"
      "start: ground\n"
      "mass: 1.5\n"
      "inertia: 0.8\n"
      "motor_tau_ms: 60\n"
      "battery_pct: 7\n"
      "noise: 2\n"
      "vibration: 5\n"
      "param: yaw_p 20\n"
      "known_failure: not yet\n"
      "\n"
      "at 0 roll 20\n"
      "at 0 pitch -5\n"
      "at 0.5 yaw 1.5\n"
      "at 1 lift 0.75\n"
      "at 1 lift hold\n"
      "at 2 lift height 4\n"
      "at 3 mode panic\n"
      "at 3 param yaw_p 10\n"
      "at 4 torque 0.1 0.2 0 for 0.05\n"
      "at 5 force 0 0 -2 for 1\n"
      "at 6 wind 3 0 0\n"
      "at 7 link off\n"
      "at 8 link on\n"
      "at 9 console full\n"
      "at 10 console normal\n"
      "at 10 log start\n"
      "at 11 log stop\n"
      "at 11 log download telemetry\n"
      "band rise_s < 0.3\n"
      "band overshoot_pct <= 8\n"
      "band final_mode == safe\n");
  ASSERT_TRUE(p.ok) << p.error;
  const qrsim::ScenarioScript& s = p.script;
  EXPECT_EQ(s.name, "mine");
  EXPECT_EQ(s.summary, "a test flight");
  EXPECT_EQ(s.seconds, 12);
  EXPECT_EQ(s.start, qrsim::Start::ground);
  EXPECT_EQ(s.mass_scale, 1.5);
  EXPECT_EQ(s.inertia_scale, 0.8);
  EXPECT_EQ(s.motor_tau_ms, 60);
  EXPECT_EQ(s.battery_pct, 7);
  EXPECT_EQ(s.noise_scale, 2);
  EXPECT_EQ(s.vibration_scale, 5);
  ASSERT_EQ(s.parameters.size(), 1u);
  EXPECT_EQ(s.parameters[0].first, wire::ParamId::yaw_p);
  EXPECT_EQ(s.known_failure, "not yet");
  ASSERT_EQ(s.events.size(), 18u);
  EXPECT_EQ(s.events[0].action, qrsim::Action::roll);
  EXPECT_EQ(s.events[0].value, 20);
  EXPECT_EQ(s.events[0].line, 14);
  EXPECT_EQ(s.events[1].value, -5);
  EXPECT_EQ(s.events[2].action, qrsim::Action::yaw);
  EXPECT_EQ(s.events[3].action, qrsim::Action::lift_share);
  EXPECT_EQ(s.events[3].value, 0.75);
  EXPECT_EQ(s.events[4].action, qrsim::Action::lift_hold);
  EXPECT_EQ(s.events[5].action, qrsim::Action::lift_height);
  EXPECT_EQ(s.events[5].value, 4);
  EXPECT_EQ(s.events[6].mode, wire::Mode::panic);
  EXPECT_EQ(s.events[7].param, wire::ParamId::yaw_p);
  EXPECT_EQ(s.events[8].action, qrsim::Action::torque);
  EXPECT_EQ(s.events[8].vector.y, 0.2);
  EXPECT_EQ(s.events[8].duration_s, 0.05);
  EXPECT_EQ(s.events[9].vector.z, -2);
  EXPECT_EQ(s.events[10].action, qrsim::Action::wind);
  EXPECT_EQ(s.events[10].vector.x, 3);
  EXPECT_EQ(s.events[11].value, 0);
  EXPECT_EQ(s.events[12].value, 1);
  EXPECT_EQ(s.events[13].action, qrsim::Action::console);
  EXPECT_EQ(s.events[13].value, 1);
  EXPECT_EQ(s.events[14].action, qrsim::Action::console);
  EXPECT_EQ(s.events[14].value, 0);
  EXPECT_EQ(s.events[15].action, qrsim::Action::log_start);
  EXPECT_EQ(s.events[16].action, qrsim::Action::log_stop);
  EXPECT_EQ(s.events[17].action, qrsim::Action::download);
  EXPECT_EQ(s.events[17].value, 1);
  ASSERT_EQ(s.bands.size(), 3u);
  EXPECT_EQ(s.bands[1].compare, qrsim::Compare::at_most);
  EXPECT_EQ(s.bands[2].limit, static_cast<double>(wire::Mode::safe));
}

// Several parameters before the flight, each on its own line, uploaded in the file's order.
TEST(ScenarioFile, ReadsSeveralParamLinesInOrder) {
  const Parsed p = parse(
      "seconds: 3\nparam: yaw_p 20\nparam: max_tilt_mrad 600\nparam: idle_level 150\n"
      "band final_mode == full\n");
  ASSERT_TRUE(p.ok) << p.error;
  ASSERT_EQ(p.script.parameters.size(), 3u);
  EXPECT_EQ(p.script.parameters[0].first, wire::ParamId::yaw_p);
  EXPECT_EQ(p.script.parameters[0].second, 20 * 16);  // yaw_p has 4 fraction bits
  EXPECT_EQ(p.script.parameters[1].first, wire::ParamId::max_tilt_mrad);
  EXPECT_EQ(p.script.parameters[1].second, 600);
  EXPECT_EQ(p.script.parameters[2].first, wire::ParamId::idle_level);
  EXPECT_EQ(p.script.parameters[2].second, 150);
}

// Height hold with the hand still, and again after a lift change once the hand is still again.
TEST(ScenarioFile, ModeHeightFollowsLiftStill) {
  const Parsed p = parse(
      "seconds: 9\nat 0 lift still\nat 0.5 mode height\nat 3 lift 1.05\nat 4 lift still\n"
      "at 4 mode height\nat 5 roll 5\nat 6 mode full\nband final_mode == full\n");
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_EQ(p.script.events.size(), 7u);
}

// Every comparison a band may make, and its text back as written.
TEST(ScenarioFile, ReadsEveryComparison) {
  const Parsed p = parse(
      "seconds: 3\nband rise_s < 1\nband rise_s <= 1\nband entered_panic == 0\n"
      "band height_m_end > 1.2\nband height_m_end >= 1.25\n");
  ASSERT_TRUE(p.ok) << p.error;
  ASSERT_EQ(p.script.bands.size(), 5u);
  const qrsim::Compare expected[] = {qrsim::Compare::below, qrsim::Compare::at_most, qrsim::Compare::equal,
                                     qrsim::Compare::above, qrsim::Compare::at_least};
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(p.script.bands[i].compare, expected[i]) << i;
  EXPECT_EQ(qrsim::band_text(p.script.bands[3]), "height_m_end > 1.2");
  EXPECT_EQ(qrsim::band_text(p.script.bands[4]), "height_m_end >= 1.25");
}

// A hand turn: the axis, whole turns (negative the other way) and the time; one may follow the
// last as it ends.
TEST(ScenarioFile, ReadsTurns) {
  const Parsed p = parse("seconds: 9\nat 0.5 turn y -3 for 5\nat 5.5 turn x 1 for 2\nband final_mode == safe\n");
  ASSERT_TRUE(p.ok) << p.error;
  ASSERT_EQ(p.script.events.size(), 2u);
  const qrsim::Event& e = p.script.events[0];
  EXPECT_EQ(e.action, qrsim::Action::turn);
  EXPECT_EQ(e.turn.axis, sim::BodyAxis::y);
  EXPECT_EQ(e.turn.turns, -3);
  EXPECT_EQ(e.turn.seconds, 5);
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(p.script.events[1].turn.axis, sim::BodyAxis::x);
}

// The sensors' faults: each keyword, its target and its time.
TEST(ScenarioFile, ReadsSensorFaults) {
  const Parsed p = parse(
      "seconds: 9\nat 1 nack imu for 0.05\nat 1 nack baro for 0.2\nat 2 sda stuck for 0.5\nat 3 sda stuck\n"
      "at 4 imu identity 0x70\nat 4 imu fifo overflow\nat 5 baro prom bad\nat 6 baro slow 5 for 0.05\n"
      "band final_mode == safe\n");
  ASSERT_TRUE(p.ok) << p.error;
  const std::vector<qrsim::Event>& e = p.script.events;
  ASSERT_EQ(e.size(), 8u);
  const Parsed self_test = parse("seconds: 3\nat 0 imu selftest bad\nband final_mode == safe\n");
  ASSERT_TRUE(self_test.ok) << self_test.error;
  EXPECT_EQ(self_test.script.events.at(0).action, qrsim::Action::imu_self_test);
  EXPECT_EQ(e[0].action, qrsim::Action::nack);
  EXPECT_EQ(e[0].value, 0x68);
  EXPECT_EQ(e[0].duration_s, 0.05);
  EXPECT_EQ(e[1].value, 0x77);
  EXPECT_EQ(e[2].action, qrsim::Action::sda_stuck);
  EXPECT_EQ(e[2].duration_s, 0.5);
  EXPECT_TRUE(std::isinf(e[3].duration_s)) << "for ever";
  EXPECT_EQ(e[4].action, qrsim::Action::imu_identity);
  EXPECT_EQ(e[4].value, 0x70);
  EXPECT_EQ(e[5].action, qrsim::Action::fifo_overflow);
  EXPECT_EQ(e[6].action, qrsim::Action::prom_bad);
  EXPECT_EQ(e[7].action, qrsim::Action::baro_slow);
  EXPECT_EQ(e[7].value, 5);
  EXPECT_EQ(e[7].duration_s, 0.05);
}

TEST(ScenarioFile, DefaultsAreTheVehicleAsWritten) {
  const Parsed p = parse("seconds: 3\nband final_mode == full\n");
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_EQ(p.script.start, qrsim::Start::hover);
  EXPECT_EQ(p.script.mass_scale, 1);
  EXPECT_TRUE(std::isnan(p.script.motor_tau_ms));
  EXPECT_TRUE(std::isnan(p.script.battery_pct));
  EXPECT_TRUE(p.script.events.empty());
}

// Each mistake, the line it is on, and words of the message.
struct Mistake {
  const char* text;
  const char* message;  // the whole "file:line: ..." start, and a distinctive part
  const char* words;
};

class ScenarioFileErrors : public ::testing::TestWithParam<Mistake> {};

TEST_P(ScenarioFileErrors, NameTheFileAndLine) {
  const Parsed p = parse(GetParam().text);
  EXPECT_FALSE(p.ok);
  EXPECT_EQ(p.error.rfind(GetParam().message, 0), 0u) << p.error;
  EXPECT_NE(p.error.find(GetParam().words), std::string::npos) << p.error;
}

const Mistake kMistakes[] = {
    {"seconds: 3\nfly away\n", "mine.txt:2: ", "unknown keyword 'fly'"},
    {"seconds: 3\ncolour: red\n", "mine.txt:2: ", "unknown setting 'colour:'"},
    {"seconds: three\n", "mine.txt:1: ", "bad number 'three'"},
    {"seconds: 3\nat 1 roll ten\n", "mine.txt:2: ", "bad number 'ten'"},
    {"seconds: 3\nat 1x roll 10\n", "mine.txt:2: ", "bad number '1x'"},
    {"seconds: 3\nat 1 roll nan\n", "mine.txt:2: ", "bad number 'nan'"},
    {"seconds: 3\nat 2 roll 10\nat 1 roll 0\n", "mine.txt:3: ", "event out of order"},
    {"seconds: 3\nat -1 roll 10\n", "mine.txt:2: ", "must be >= 0"},
    {"seconds: 3\nat 5 roll 10\nband rise_s < 1\n", "mine.txt:2: ", "past the window"},
    {"seconds: 3\nparam: no_such 1\n", "mine.txt:2: ", "unknown parameter 'no_such'"},
    {"seconds: 3\nat 1 param yaw_q 1\n", "mine.txt:2: ", "unknown parameter 'yaw_q'"},
    // Out of range: the message says the range and the unit, in the unit the value is written in.
    {"seconds: 3\nparam: yaw_p 100000\n",
     "mine.txt:2: ", "parameter yaw_p: 100000 is out of its range 0 .. 1000 (thrust units per rad/s)"},
    {"seconds: 3\nat 1 param max_tilt_mrad 800\n",
     "mine.txt:2: ", "parameter max_tilt_mrad: 800 is out of its range 87 .. 698 (mrad)"},
    {"seconds: 3\nparam: attitude_c2 0\n", "mine.txt:2: ", "out of its range 1 .. 1073741824 (samples^2)"},
    {"seconds: 3\nparam: yaw_p many\n", "mine.txt:2: ", "bad number 'many' for parameter yaw_p"},
    {"seconds: 3\nparam: yaw_p 20\nparam: idle_level 150\nparam: yaw_p 30\n",
     "mine.txt:4: ", "param: yaw_p given twice (first on line 2)"},
    {"seconds: 3\nband rise < 1\n", "mine.txt:2: ", "unknown band figure 'rise'"},
    {"seconds: 3\nband rise_s != 1\n", "mine.txt:2: ", "unknown comparison '!=' (<, <=, ==, > or >=)"},
    {"seconds: 3\nband rise_s => 1\n", "mine.txt:2: ", "unknown comparison '=>'"},
    {"seconds: 3\nband final_mode >= full\n", "mine.txt:2: ", "compared with =="},
    {"seconds: 3\nband rise_s < 1 2\n", "mine.txt:2: ", "band FIGURE OP LIMIT"},
    {"seconds: 3\nband final_mode < 1\n", "mine.txt:2: ", "compared with =="},
    {"seconds: 3\nband final_mode == flying\n", "mine.txt:2: ", "unknown mode 'flying'"},
    {"seconds: 3\nat 0 mode hover\n", "mine.txt:2: ", "unknown mode 'hover'"},
    {"seconds: 3\nat 0 jump 1\n", "mine.txt:2: ", "unknown action 'jump'"},
    {"seconds: 3\nat 0\n", "mine.txt:2: ", "an event is"},
    {"seconds: 3\nat 0 roll\n", "mine.txt:2: ", "roll needs one number"},
    {"seconds: 3\nat 0 roll 1 2\n", "mine.txt:2: ", "roll needs one number"},
    {"seconds: 3\nat 0 torque 1 1 for 0.2\n", "mine.txt:2: ", "torque needs X Y Z for SECONDS"},
    {"seconds: 3\nat 0 torque 1 1 0 during 0.2\n", "mine.txt:2: ", "torque needs X Y Z for SECONDS"},
    {"seconds: 3\nat 0 force 1 1 0 for 0\n", "mine.txt:2: ", "duration must be > 0"},
    {"seconds: 3\nat 0 roll 1e300\n", "mine.txt:2: ", "beyond +-90 degrees"},
    {"seconds: 3\nat 0 yaw -25\n", "mine.txt:2: ", "beyond +-20 rad/s"},
    {"seconds: 3\nat 0 torque 0 0 1e9 for 1\n", "mine.txt:2: ", "torque is beyond +-10"},
    {"seconds: 3\nat 0 wind 60 0 0\n", "mine.txt:2: ", "wind is beyond +-50"},
    {"seconds: 3\nat 0 wind 1 1\n", "mine.txt:2: ", "wind needs N E D"},
    {"seconds: 9\nat 0 turn w 1 for 2\n", "mine.txt:2: ", "turn axis is x, y or z, not 'w'"},
    {"seconds: 9\nat 0 turn z 1 2\n", "mine.txt:2: ", "turn needs AXIS N for SECONDS"},
    {"seconds: 9\nat 0 turn z 1.5 for 2\n", "mine.txt:2: ", "turns must be a whole number, not 0"},
    {"seconds: 9\nat 0 turn z 0 for 2\n", "mine.txt:2: ", "turns must be a whole number, not 0"},
    {"seconds: 9\nat 0 turn z 11 for 60\n", "mine.txt:2: ", "within +-10"},
    {"seconds: 9\nat 0 turn z one for 2\n", "mine.txt:2: ", "bad number 'one'"},
    {"seconds: 9\nat 0 turn z 1 for 0.4\n", "mine.txt:2: ", "a turn takes 0.5 .. 60 s"},
    {"seconds: 99\nat 0 turn z 1 for 61\n", "mine.txt:2: ", "a turn takes 0.5 .. 60 s"},
    {"seconds: 9\nat 0 turn z 1 for 1.5\n", "mine.txt:2: ", "beyond the gyro's 8 rad/s"},
    {"seconds: 9\nat 0 turn z 1 for 2\nat 1.9 turn x 1 for 2\n",
     "mine.txt:3: ", "starts while the turn of line 2 still acts"},
    {"seconds: 3\nat 0 link maybe\n", "mine.txt:2: ", "link is 'on' or 'off'"},
    {"seconds: 3\nat 0 console fast\n", "mine.txt:2: ", "console is 'full' (the line's full rate) or 'normal'"},
    {"seconds: 3\nat 0 log download flight\n", "mine.txt:2: ", "log is 'start', 'stop' or 'download sensor|telemetry'"},
    {"seconds: 3\nat 0 lift up\n", "mine.txt:2: ", "bad number 'up'"},
    {"seconds: 3\nat 0 lift height\n", "mine.txt:2: ", "bad number 'height'"},
    {"seconds: 3\nat 0 lift 5\n", "mine.txt:2: ", "lift share must be"},
    // Height hold ends at the lift stick's first change: the pilot's hand must be still first.
    {"seconds: 3\nat 0.5 mode height\n", "mine.txt:2: ", "add 'at T lift still' before it"},
    {"seconds: 3\nat 0 lift still\nat 0.2 lift hold\nat 0.5 mode height\n",
     "mine.txt:4: ", "mode height with the pilot's lift hand moving"},
    {"seconds: 3\nat 0 lift still\nat 0 lift 1.02\nat 0.5 mode height\n", "mine.txt:4: ", "lift still"},
    {"seconds: 3\nat 0.5 mode height\nat 0.5 lift still\n", "mine.txt:2: ", "lift still"},
    // So does the autotune (rule 23): the same rule, the mode's own name.
    {"seconds: 3\nat 0.5 mode autotune\n",
     "mine.txt:2: ", "mode autotune with the pilot's lift hand moving: autotune ends"},
    // The sensors' faults (docs/drivers.md section 7, "Faults").
    {"seconds: 3\nat 0 nack gps for 1\n", "mine.txt:2: ", "nack needs imu|baro for SECONDS"},
    {"seconds: 3\nat 0 nack imu 1\n", "mine.txt:2: ", "nack needs imu|baro for SECONDS"},
    {"seconds: 3\nat 0 nack imu for 0\n", "mine.txt:2: ", "the duration must be > 0"},
    {"seconds: 3\nat 0 nack baro for soon\n", "mine.txt:2: ", "bad number 'soon'"},
    {"seconds: 3\nat 0 sda low\n", "mine.txt:2: ", "sda needs 'stuck' or 'stuck for SECONDS'"},
    {"seconds: 3\nat 0 sda stuck for -1\n", "mine.txt:2: ", "the duration must be > 0"},
    {"seconds: 3\nat 0 imu identity 0x100\n", "mine.txt:2: ", "imu identity is a byte"},
    {"seconds: 3\nat 0 imu identity seventy\n", "mine.txt:2: ", "imu identity is a byte"},
    {"seconds: 3\nat 0 imu identity 0x68\n", "mine.txt:2: ", "the MPU-6050's own"},
    {"seconds: 3\nat 1 imu selftest bad\n",
     "mine.txt:2: ", "from power-up (the driver self-tests then only): write it at 0"},
    {"seconds: 3\nat 0 imu selftest good\n",
     "mine.txt:2: ", "imu needs 'identity BYTE', 'fifo overflow' or 'selftest bad'"},
    {"seconds: 3\nat 0 imu fifo full\n",
     "mine.txt:2: ", "imu needs 'identity BYTE', 'fifo overflow' or 'selftest bad'"},
    {"seconds: 3\nat 0 baro prom good\n", "mine.txt:2: ", "baro needs 'prom bad' or 'slow MS for SECONDS'"},
    {"seconds: 3\nat 0 baro slow 500 for 1\n", "mine.txt:2: ", "baro slow must be > 0 and at most 100 ms"},
    {"seconds: 3\nstart: sky\n", "mine.txt:2: ", "start: is 'hover', 'ground' or 'safe'"},
    {"seconds: 3\nseconds: 4\n", "mine.txt:2: ", "given twice"},
    {"seconds: 3\nmass: 0\n", "mine.txt:2: ", "outside"},
    {"seconds: 3\nknown_failure:\n", "mine.txt:2: ", "needs its reason"},
    {"band rise_s < 1\n", "mine.txt: ", "no 'seconds:' line"},
    {"seconds: 3\n", "mine.txt: ", "no band"},
};

INSTANTIATE_TEST_SUITE_P(Each, ScenarioFileErrors, ::testing::ValuesIn(kMistakes));

// A vehicle file is found next to the scenario file; a missing one is an error at its line.
TEST(ScenarioFile, VehicleFileIsRelativeToTheScenarioFile) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream out(dir + "scenario_with_vehicle.txt");
    out << "seconds: 1\nvehicle: " << QR_SIM_VEHICLE_DIR << "/in4073_heavy.txt\nband final_mode == full\n";
  }
  qrsim::ScenarioScript script;
  std::string error;
  // An absolute path stays absolute when joined to the scenario's folder.
  ASSERT_TRUE(qrsim::load_scenario_file(dir + "scenario_with_vehicle.txt", script, error)) << error;
  ASSERT_TRUE(script.vehicle.has_value());
  EXPECT_GT(script.vehicle->mass_kg, 1.0);
  {
    std::ofstream out(dir + "scenario_missing_vehicle.txt");
    out << "seconds: 1\n\nvehicle: no_such_vehicle.txt\nband final_mode == full\n";
  }
  EXPECT_FALSE(qrsim::load_scenario_file(dir + "scenario_missing_vehicle.txt", script, error));
  EXPECT_NE(error.find("scenario_missing_vehicle.txt:3: vehicle "), std::string::npos) << error;
}

TEST(ScenarioFile, BuiltinOrFileOrNeither) {
  qrsim::ScenarioScript script;
  std::string error;
  EXPECT_TRUE(qrsim::find_scenario("hover", script, error)) << error;
  EXPECT_EQ(script.origin, "built-in hover");
  EXPECT_FALSE(qrsim::find_scenario("no-such-scenario", script, error));
  EXPECT_NE(error.find("no scenario no-such-scenario"), std::string::npos) << error;
}

}  // namespace
