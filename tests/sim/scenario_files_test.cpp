// Every scenario file of sim/scenarios/ flown at seed 1 and judged by its own bands on the
// simulator's truth. A file with a known_failure line must still fail (a band, not the
// preflight): when the firmware is fixed the test says so, and the line must go. The built-ins
// compiled into qrsim must be these files, byte for byte. ScenarioFlights.*: short flights of
// their own, for what the record measures in them (which modes, which ticks, what cause).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <qr/sim_runner/builtin_scenarios.hpp>
#include <qr/sim_runner/scenario.hpp>

namespace {

namespace fs = std::filesystem;

std::vector<std::string> scenario_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(QR_SIM_SCENARIO_DIR)) {
    if (entry.path().extension() == ".txt") files.push_back(entry.path().stem().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string path_of(const std::string& name) { return std::string(QR_SIM_SCENARIO_DIR) + "/" + name + ".txt"; }

class ScenarioFiles : public ::testing::TestWithParam<std::string> {};

TEST_P(ScenarioFiles, FliesAndIsJudgedByItsBands) {
  qrsim::ScenarioScript script;
  std::string error;
  ASSERT_TRUE(qrsim::load_scenario_file(path_of(GetParam()), script, error)) << error;
  const qrsim::ScenarioResult r = qrsim::run_scenario(script, {});
  std::printf("%s\n", qrsim::to_json(r).c_str());
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_EQ(r.checks.size(), script.bands.size());
  if (script.known_failure.empty()) {
    for (const qrsim::CheckResult& c : r.checks) EXPECT_TRUE(c.pass) << c.band;
    EXPECT_TRUE(r.pass);
  } else {
    EXPECT_FALSE(r.pass) << GetParam() << " passes every band now: remove its known_failure line ("
                         << script.known_failure << ")";
    for (const qrsim::CheckResult& c : r.checks) {
      if (!c.pass) std::printf("known failure, band fails: %s\n", c.band.c_str());
    }
  }
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(SimScenarios, ScenarioFiles, ::testing::ValuesIn(scenario_files()), test_name);

TEST(BuiltinScenarios, AreTheFilesOfSimScenarios) {
  std::vector<std::string> builtin;
  for (const qrsim::BuiltinScenario& b : qrsim::builtin_scenarios()) {
    builtin.push_back(b.name);
    std::ifstream in(path_of(b.name));
    ASSERT_TRUE(in) << b.name << " is built in but has no file";
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), b.text) << b.name << ": the compiled-in text is stale (reconfigure)";
  }
  std::sort(builtin.begin(), builtin.end());
  EXPECT_EQ(builtin, scenario_files());
}

// The issue's list of scenarios, each a file.
TEST(BuiltinScenarios, IncludeTheIssuesScenarios) {
  const std::vector<std::string> files = scenario_files();
  for (const char* name :
       {"hover", "step-roll", "step-pitch", "full-stick-30", "yaw-rate", "yaw-full-stick", "disturbance", "large-push",
        "link-loss", "panic", "bank-hold", "yaw-while-banked", "ground-windup-takeoff", "battery-sag-climb",
        "heavy-slow", "step-roll-20", "vibration-x5"}) {
    EXPECT_NE(std::find(files.begin(), files.end(), name), files.end()) << name;
  }
}

// A scenario's text flown at seed 1.
qrsim::ScenarioResult fly(const std::string& text) {
  qrsim::ScenarioScript script;
  std::string error;
  EXPECT_TRUE(qrsim::parse_scenario(text, "flight", "flight.txt", script, error)) << error;
  const qrsim::ScenarioResult r = qrsim::run_scenario(script, {});
  EXPECT_TRUE(r.error.empty()) << r.error;
  return r;
}

// Height hold flies the attitude loops as full control does: an upset in it is measured (the
// record took the attitude errors in full control only, so peak_error_deg was null).
TEST(ScenarioFlights, AnUpsetInHeightHoldIsMeasured) {
  const qrsim::ScenarioResult r = fly(
      "seconds: 4\nat 0 lift still\nat 0.5 mode height\nat 1.5 torque 1.0 1.0 0 for 0.2\n"
      "band final_mode == height\n");
  EXPECT_EQ(r.final_mode, "height") << "the push must not end height hold, or the test proves nothing";
  EXPECT_GT(r.figure("height_hold_s"), 3.0) << "height hold held through the push";
  EXPECT_GT(r.figure("max_tilt_deg_truth"), 30.0);
  EXPECT_GT(r.figure("peak_error_deg"), 30.0);
  EXPECT_TRUE(std::isfinite(r.figure("att_rms_deg_last_s")));
  EXPECT_GT(r.figure("att_rms_deg_truth"), 1.0) << "the upset is in the window's RMS";
  EXPECT_TRUE(std::isfinite(r.figure("est_err_max_deg")));
}

// The record knows a panic's cause from the firmware's announcement: a link loss in hover, the
// pack full, is no battery panic; a climb that sags a half-full pack below a battery_panic_mv set
// just under its resting voltage (the sag model off: battery_sag_mv 0) is one, the rest above.
TEST(ScenarioFlights, OnlyABatteryPanicIsJudgedOnTheRestedVoltage) {
  const qrsim::ScenarioResult link = fly("seconds: 3\nat 0.2 link off\nband entered_panic == 1\n");
  EXPECT_EQ(link.figure("entered_panic"), 1);
  EXPECT_EQ(link.figure("panic_while_rested_above_threshold"), 0) << "a link loss, not a battery panic";
  const qrsim::ScenarioResult sag = fly(
      "seconds: 4\nbattery_pct: 50\nparam: battery_sag_mv 0\nparam: battery_panic_mv 11200\n"
      "at 0 lift 1.6\nband entered_panic == 1\n");
  EXPECT_EQ(sag.figure("entered_panic"), 1);
  EXPECT_GT(sag.figure("battery_rested_v_min"), 11.2) << "the pack rested above the threshold all along";
  EXPECT_EQ(sag.figure("panic_while_rested_above_threshold"), 1);
}

// Armed on the ground with the lift stick down, every engine is at idle: that is no saturation.
// Only the ticks airborne in full control count (a ground start counted 100 % before the take-off).
TEST(ScenarioFlights, EngineSaturationCountsAirborneTicksOnly) {
  const qrsim::ScenarioResult ground = fly("seconds: 2\nstart: ground\nband final_mode == full\n");
  EXPECT_LT(ground.figure("height_m_end"), 0.2) << "it stayed on the ground";
  EXPECT_TRUE(std::isnan(ground.figure("engine_saturation_pct"))) << "no tick airborne: not measured";
  const qrsim::ScenarioResult takeoff = fly("seconds: 5\nstart: ground\nat 1 lift hold\nband final_mode == full\n");
  EXPECT_GT(takeoff.figure("height_m_end"), 1.0) << "it took off";
  EXPECT_LT(takeoff.figure("engine_saturation_pct"), 5) << "a gentle take-off and hover saturate no engine";
}

// A stick event beyond full stick (max_tilt_mrad, the default's 30 deg or one uploaded) is said
// in the flight's notes and its JSON; the set-point the firmware holds is full stick's.
TEST(ScenarioFlights, AStickBeyondFullStickIsNoted) {
  const qrsim::ScenarioResult beyond = fly("seconds: 3\nat 0 roll 45\nband final_mode == full\n");
  ASSERT_EQ(beyond.notes.size(), 1u);
  EXPECT_EQ(beyond.notes[0],
            "at 0 s: roll 45 deg asks for more than max_tilt_mrad allows (30 deg): the set-point is 30 deg");
  EXPECT_NEAR(beyond.figure("step_setpoint_deg"), 30, 0.1) << "the firmware holds full stick";
  EXPECT_NE(qrsim::to_json(beyond).find(", \"notes\": [\"at 0 s: roll 45 deg asks"), std::string::npos)
      << qrsim::to_json(beyond);

  // The max_tilt_mrad uploaded before the flight (698 mrad: 40 deg) and by an event in it.
  const qrsim::ScenarioResult uploaded = fly(
      "seconds: 3\nparam: max_tilt_mrad 698\nat 0 pitch -45\nat 1 pitch 35\nat 1.5 param max_tilt_mrad 524\n"
      "at 2 pitch 35\nband final_mode == full\n");
  ASSERT_EQ(uploaded.notes.size(), 2u);
  EXPECT_EQ(uploaded.notes[0],
            "at 0 s: pitch -45 deg asks for more than max_tilt_mrad allows (40 deg): the set-point is -40 deg");
  EXPECT_EQ(uploaded.notes[1],
            "at 2 s: pitch 35 deg asks for more than max_tilt_mrad allows (30 deg): the set-point is 30 deg");

  const qrsim::ScenarioResult within = fly("seconds: 1\nat 0 roll 30\nat 0.5 pitch -20\nband final_mode == full\n");
  EXPECT_TRUE(within.notes.empty()) << within.notes[0];
  EXPECT_EQ(qrsim::to_json(within).find("\"notes\""), std::string::npos) << "no notes, no field";
}

}  // namespace
