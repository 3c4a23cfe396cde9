// The host firmware flying in the simulator, headless, beyond what the scenario files' bands say
// (ScenarioFiles.* flies every file): the safety timelines, the figures' meaning on the truth,
// ground start and wind, determinism, replay and a sweep of vehicles. Each test prints its
// figures as the JSON line qrsim would.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <qr/host/replay.hpp>
#include <qr/sim_runner/scenario.hpp>
#include <sim/random.hpp>

#include "sim_test_support.hpp"

namespace {

qrsim::ScenarioScript builtin(const std::string& name) {
  qrsim::ScenarioScript script;
  std::string error;
  EXPECT_TRUE(qrsim::find_scenario(name, script, error)) << error;
  return script;
}

qrsim::ScenarioScript parsed(const std::string& text) {
  qrsim::ScenarioScript script;
  std::string error;
  EXPECT_TRUE(qrsim::parse_scenario(text, "test", "test", script, error)) << error;
  return script;
}

qrsim::ScenarioResult fly(const qrsim::ScenarioScript& script, double seconds = 0, uint64_t seed = 1,
                          const qrsim::VehicleDraw& draw = {}) {
  qrsim::RunOptions options;
  options.seconds = seconds;
  options.seed = seed;
  options.draw = draw;
  const qrsim::ScenarioResult result = qrsim::run_scenario(script, options);
  std::printf("%s\n", qrsim::to_json(result).c_str());
  return result;
}

qrsim::ScenarioResult fly(const std::string& name, double seconds = 0, uint64_t seed = 1) {
  return fly(builtin(name), seconds, seed);
}

void expect_bands_hold(const qrsim::ScenarioResult& r) {
  EXPECT_TRUE(r.error.empty()) << r.error;
  for (const qrsim::CheckResult& c : r.checks) EXPECT_TRUE(c.pass) << c.band << " (" << r.scenario << ")";
}

// On the truth against the pilot's set-point: the yaw loop's integral holds the rate where the P
// term alone would settle 28 % short (yaw_rate_p_only_rad_s).
TEST(ClosedLoop, YawRateStepReachesItsSetpoint) {
  const qrsim::ScenarioResult r = fly("yaw-rate");
  expect_bands_hold(r);
  EXPECT_LT(r.figure("yaw_rate_error_pct"), 10);
  EXPECT_LT(r.figure("yaw_rate_p_only_rad_s"), 0.9 * r.figure("yaw_rate_setpoint_rad_s"))
      << "the P term alone falls short";
}

TEST(ClosedLoop, FullYawStickReachesItsSetpoint) {
  const qrsim::ScenarioResult r = fly("yaw-full-stick");
  expect_bands_hold(r);
  EXPECT_NEAR(r.figure("yaw_rate_setpoint_rad_s"), 2.0, 0.01);
}

// An upset past the 45° tilt limit that the controller can take back: the tilt watchdog waits its
// tilt time (rule 9, docs/safety.md) and the vehicle recovers, judged on the truth, still flying.
TEST(ClosedLoop, LargePushPastTheTiltLimitRecoversWithoutPanic) {
  const qrsim::ScenarioResult r = fly("large-push");
  expect_bands_hold(r);
  EXPECT_GT(r.figure("max_tilt_deg_truth"), 45.0) << "the push must take the vehicle past the tilt limit";
  EXPECT_GT(r.figure("height_m_end"), 1.0) << "still flying, not on the ground";
}

// The step figures are the truth's: the true peak is the set-point plus the overshoot, and the
// estimate's figures (which read the bank low, issue 14) are printed beside, not instead.
TEST(ClosedLoop, StepFiguresJudgeTheTruth) {
  const qrsim::ScenarioResult r = fly("step-roll");
  const double peak = r.figure("step_setpoint_deg") * (1 + r.figure("overshoot_pct") / 100);
  EXPECT_NEAR(r.figure("max_tilt_deg_truth"), peak, 0.2);
  EXPECT_FALSE(std::isnan(r.figure("overshoot_pct_est")));
  EXPECT_NE(r.figure("overshoot_pct"), r.figure("overshoot_pct_est"));
}

// The safety timeline of a pulled cable, whatever the landing (link-loss.txt judges that).
TEST(ClosedLoop, LinkLossEndsInSafeWithEnginesStill) {
  const qrsim::ScenarioResult r = fly("link-loss");
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.final_mode, "safe");
  EXPECT_EQ(r.figure("engines_at_end_max"), 0);
  // docs/safety.md: panic after the 250 ms link timeout; full control with a height estimate, so
  // the panic lands: 1.4 m down to the feet at panic_descent_mm_s (0.5 m/s) takes about 2.8 s
  // (far longer than a fall), and safe comes at the touchdown, the engines stopping with it.
  EXPECT_NEAR(r.figure("panic_after_s"), 0.25, 0.03);
  const double landing_s = r.figure("safe_after_s") - r.figure("panic_after_s");
  EXPECT_GT(landing_s, 2.4);
  EXPECT_LT(landing_s, 4.0);
  EXPECT_LT(r.figure("touchdown_speed_m_s"), 1.0);
  EXPECT_LT(r.figure("engines_stop_s"), 0.05);
}

TEST(ClosedLoop, PanicEndsInSafeWithEnginesStill) {
  const qrsim::ScenarioResult r = fly("panic");
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.final_mode, "safe");
  EXPECT_EQ(r.figure("engines_at_end_max"), 0);
  EXPECT_LT(r.figure("panic_after_s"), 0.1);  // the request's first send is answered
  // The landing descends at panic_descent_mm_s (0.5 m/s): it touches down near that, well below
  // a fall from 1.5 m (5.4 m/s).
  const double touchdown = r.figure("touchdown_speed_m_s");
  EXPECT_GT(touchdown, 0.3);
  EXPECT_LT(touchdown, 0.8);
  EXPECT_LT(touchdown, std::sqrt(2 * 9.80665 * 1.6));
}

// Armed on the ground with the lift stick down: the window starts there, nothing takes off, and
// there is no touchdown to measure.
TEST(ClosedLoop, GroundStartStaysOnTheGroundWithTheLiftDown) {
  const qrsim::ScenarioResult r = fly(parsed("seconds: 2\nstart: ground\nband final_mode == full\n"));
  expect_bands_hold(r);
  EXPECT_LT(r.figure("height_m_end"), 0.1);
  EXPECT_TRUE(std::isnan(r.figure("touchdown_speed_m_s")));
  EXPECT_LT(r.figure("sim_seconds"), 8) << "no take-off and settle before the window";
}

// A steady wind blows the hovering vehicle downwind (the pilot holds height, not position).
TEST(ClosedLoop, WindBlowsTheVehicleDownwind) {
  const qrsim::ScenarioResult still = fly(parsed("seconds: 4\nband final_mode == full\n"));
  const qrsim::ScenarioResult windy = fly(parsed("seconds: 4\nat 0 wind 0 4 0\nband final_mode == full\n"));
  expect_bands_hold(windy);
  EXPECT_GT(windy.figure("drift_m_end"), 1.0);
  EXPECT_GT(windy.figure("drift_m_end"), 5 * still.figure("drift_m_end"));
}

TEST(ClosedLoop, SameSeedSameFlight) {
  const qrsim::ScenarioResult a = fly("disturbance", 1.5, 7), b = fly("disturbance", 1.5, 7);
  for (const char* figure :
       {"att_rms_deg_truth", "est_err_rms_deg", "peak_error_deg", "height_m_end", "battery_v_end"}) {
    EXPECT_EQ(a.figure(figure), b.figure(figure)) << figure;
  }
}

// step-roll flown with `parameters`, recorded and traced, then replayed with `replayed_with`
// into `replay_path`; the trace's rows by time in µs. The recording and the trace are named after
// the replay: each test has files of its own (CTest runs them side by side).
std::map<std::string, std::map<std::string, std::string>> fly_and_replay(
    const std::vector<std::pair<wire::ParamId, int32_t>>& parameters, const qr::host::ReplayOptions& replayed_with,
    const std::string& replay_path) {
  qrsim::RunOptions options;
  options.record_path = replay_path + ".record.csv";
  options.trace_path = replay_path + ".trace.csv";
  options.parameters = parameters;
  const qrsim::ScenarioResult flown = qrsim::run_scenario(builtin("step-roll"), options);
  EXPECT_TRUE(flown.error.empty()) << flown.error;
  std::ostringstream errors;
  EXPECT_EQ(qr::host::run_replay(options.record_path.c_str(), replay_path.c_str(), errors, replayed_with), 0)
      << errors.str();
  std::map<std::string, std::map<std::string, std::string>> flight;
  for (auto& row : sim_test::read_csv(options.trace_path)) {
    flight[std::to_string(std::lround(std::stod(row["t_s"]) * 1e6))] = row;
  }
  return flight;
}

// A simulated flight recorded (--record) and replayed (--replay, the chain engineer's test mode)
// gives, tick for tick, the estimates and engine values the firmware computed in flight: the
// recording carries exactly what the QR read, and the replay is the same integer chain.
TEST(ClosedLoop, ReplayOfASimulatedFlightIsBitIdentical) {
  const std::string dir = ::testing::TempDir();
  auto flight = fly_and_replay({}, {}, dir + "sim_flight_replay.csv");

  size_t compared = 0;
  for (auto& replayed : sim_test::read_csv(dir + "sim_flight_replay.csv")) {
    const auto it = flight.find(replayed["time_us"]);
    if (it == flight.end() || it->second["mode"] != "5") continue;  // full control only
    auto& flown_row = it->second;
    ++compared;
    ASSERT_EQ(replayed["roll_e4"], flown_row["roll_est_e4"]) << "at " << replayed["time_us"] << " us";
    ASSERT_EQ(replayed["pitch_e4"], flown_row["pitch_est_e4"]) << "at " << replayed["time_us"] << " us";
    ASSERT_EQ(replayed["yaw_e4"], flown_row["yaw_est_e4"]) << "at " << replayed["time_us"] << " us";
    for (int e = 0; e < 4; ++e) {
      ASSERT_EQ(replayed["ae" + std::to_string(e)], flown_row["engine" + std::to_string(e)])
          << "engine " << e << " at " << replayed["time_us"] << " us";
    }
  }
  EXPECT_GT(compared, 8000u);  // take-off, hover and the step: 8.3 s in full control
}

// A flight with parameters of its own (measured gyro scales, another cut-off) replays bit for bit
// with them (--param), and not with the defaults.
TEST(ClosedLoop, ReplayWithTheFlightsParametersIsBitIdentical) {
  const std::vector<std::pair<wire::ParamId, int32_t>> parameters = {{wire::ParamId::gyro_scale_x_ppm, 15000},
                                                                     {wire::ParamId::gyro_scale_y_ppm, -12000},
                                                                     {wire::ParamId::filter_cutoff_hz, 30}};
  qr::host::ReplayOptions with_them;
  for (const auto& [id, raw] : parameters) with_them.parameters.set(static_cast<uint8_t>(id), raw);
  const std::string dir = ::testing::TempDir();
  for (const bool same : {true, false}) {
    auto flight = fly_and_replay(parameters, same ? with_them : qr::host::ReplayOptions{},
                                 dir + "sim_flight_replay_parameters.csv");
    size_t compared = 0, differ = 0;
    for (auto& replayed : sim_test::read_csv(dir + "sim_flight_replay_parameters.csv")) {
      const auto it = flight.find(replayed["time_us"]);
      if (it == flight.end() || it->second["mode"] != "5") continue;
      ++compared;
      differ += replayed["roll_e4"] != it->second["roll_est_e4"] || replayed["ae0"] != it->second["engine0"];
    }
    EXPECT_GT(compared, 8000u);
    if (same) {
      EXPECT_EQ(differ, 0u);
    } else {
      EXPECT_GT(differ, compared / 2) << "the defaults would have flown another flight";
    }
  }
}

// Vehicles around the default: mass ±20 %, inertia ±30 %, motor lag 10-70 ms (spin-down 5/3 of
// spin-up, as the default), each with its own sensor seed. The two corners come first, then
// seeded draws. Stable: still in full control, never tilted past 30°, and the attitude error of
// the last second of the disturbance window is below 2° RMS.
TEST(ClosedLoop, SeededSweepOfVehiclesStaysStable) {
  struct Variant {
    double mass, inertia, tau_up;
  };
  std::vector<Variant> variants = {{0.8, 0.7, 0.010}, {1.2, 1.3, 0.070}};
  sim::Random random(2026);
  while (variants.size() < 8) {
    variants.push_back({random.uniform(0.8, 1.2), random.uniform(0.7, 1.3), random.uniform(0.010, 0.070)});
  }
  for (size_t i = 0; i < variants.size(); ++i) {
    const Variant& v = variants[i];
    const double tau_default = sim::default_vehicle().motor_tau_up_s;
    char label[96];
    std::snprintf(label, sizeof label, "in4073 mass x%.2f inertia x%.2f lag %.0f ms", v.mass, v.inertia,
                  v.tau_up * 1000);
    const qrsim::ScenarioResult r = fly(builtin("disturbance"), 3, 100 + i,
                                        {v.mass, v.inertia, v.tau_up / tau_default, 1, 1});
    EXPECT_TRUE(r.error.empty()) << label << ": " << r.error;
    EXPECT_EQ(r.final_mode, "full") << label;
    EXPECT_NEAR(r.figure("motor_tau_ms"), v.tau_up * 1000, 1e-6) << label;
    EXPECT_LT(r.figure("max_tilt_deg_truth"), 30) << label;
    EXPECT_LT(r.figure("att_rms_deg_last_s"), 2) << label;
  }
}

}  // namespace
