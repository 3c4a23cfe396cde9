// The height estimate (qr/core/chain/height_estimator.hpp) judged on the simulator's truth: the
// host firmware flies a take-off to 1.5 m, a hover, a climb at 0.5 m/s to 4.5 m and a hover there,
// with the MS5611 model's noise, delay and drift, and the IMU's noise, vibration and errors. Each
// tick the chain's height_mm() and climb_mm_s() are compared with the plant's height above the
// calibration's and its vertical speed. The bands are about three times the figures measured on
// seeds 1-5 (docs/signal-chain.md), so a broken fusion fails them and a fair one does not.
// More seeds for measuring: QR_HEIGHT_SEEDS=N.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <map>
#include <sstream>
#include <string>

#include <qr/boards/sim/sim_qr.hpp>
#include <qr/host/replay.hpp>
#include <qr/sim_runner/pilot.hpp>

namespace {

struct Errors {
  std::vector<double> height, climb, baro;  // m, m/s, m (the barometer's own height)

  double rms(const std::vector<double>& e) const {
    double s = 0;
    for (double x : e) s += x * x;
    return e.empty() ? std::nan("") : std::sqrt(s / static_cast<double>(e.size()));
  }
  double max(const std::vector<double>& e) const {
    double m = 0;
    for (double x : e) m = std::max(m, std::abs(x));
    return m;
  }
};

struct HeightFlight {
  Errors hover, climb;
  double bias_end_mm_s2 = std::nan("");
  bool valid = false;
  bool flew = false;
  // The flight as the replay's input (from the first calibration tick), and the height read-outs
  // of each of those ticks, by time.
  std::string recording;
  std::map<uint32_t, std::pair<int32_t, int32_t>> flown;
};

// The pilot's thumb on the lift stick, following a height target (as the scenarios' pilot does,
// on the truth: this is the pilot, not the firmware's estimate).
uint16_t lift_for(const sim::Quadrotor& plant, double target, double target_climb, double ramp) {
  const sim::PlantState& s = plant.state();
  const double accel = std::clamp(2.0 * (target - -s.position.z) + 2.5 * (target_climb - -s.velocity.z), -3.0, 3.0);
  const sim::Vec3 body_down = sim::rotate(s.attitude, {0, 0, 1});
  const double ratio = std::max(0.0, (sim::kGravity + accel) / (sim::kGravity * std::max(0.5, body_down.z)));
  return static_cast<uint16_t>(
      std::clamp(std::lround(plant.hover_command() * std::sqrt(ratio) * std::clamp(ramp, 0.0, 1.0)), 0L, 1000L));
}

// Times from arming, s.
constexpr double kHoverFrom = 4, kHoverTo = 9;   // the hover window at 1.5 m
constexpr double kClimbFrom = 9, kClimbTo = 15;  // target climbs 0.5 m/s to 4.5 m
constexpr double kEnd = 20;

HeightFlight fly(uint64_t seed) {
  HeightFlight out;
  const std::unique_ptr<qrsim::SimQr> qr = qrsim::make_qr(sim::default_vehicle(), {.seed = seed});
  qrsim::Pilot pilot(qr->board);
  sim::Quadrotor& plant = qr->world.plant();
  double armed_at = -1, ground = std::nan("");
  bool asked_calibration = false, asked_arm = false, recording = false;
  out.recording = qr::host::replay_input_header() + "\n";
  for (int tick = 0; tick < 40000; ++tick) {
    const double t = static_cast<double>(qr->world.now_us()) * 1e-6;
    const qrsim::ConsoleView& view = pilot.view();
    const bool calibrated = view.heard && (view.flags & wire::kFlagCalibrated) != 0;
    if (!asked_calibration && t > 0.3) {
      pilot.request_mode(wire::Mode::calibration);
      asked_calibration = true;
    }
    if (asked_calibration && !asked_arm && calibrated && view.mode == wire::Mode::safe) {
      pilot.request_mode(wire::Mode::full_control);
      asked_arm = true;
    }
    if (armed_at < 0 && view.mode == wire::Mode::full_control) armed_at = t;
    const double since = armed_at < 0 ? -1 : t - armed_at;
    if (since >= 0) {
      const double climb_target = since < kClimbFrom ? 0 : since < kClimbTo ? 0.5 : 0;
      const double target = 1.5 + 0.5 * std::clamp(since - kClimbFrom, 0.0, kClimbTo - kClimbFrom);
      pilot.set_sticks({lift_for(plant, target, climb_target, since), 0, 0, 0});
    }
    pilot.step();
    if (since > kEnd) break;
    recording = recording || qr->firmware.mode() == wire::Mode::calibration;
    if (!qr->tick()) break;

    const auto& chain = qr->firmware.chain();
    if (recording) {
      const qr::SensorSample& in = qr->board.read_sensors();
      const qr::ControlInput& c = qr->firmware.controls();
      char line[160];
      std::snprintf(line, sizeof line, "%u,%d,%d,%d,%d,%d,%d,%u,%u,%d,%d,%d,%d\n", qr->board.now_us(), in.gyro[0],
                    in.gyro[1], in.gyro[2], in.accel[0], in.accel[1], in.accel[2], in.battery_mv, c.lift, c.roll,
                    c.pitch, c.yaw, in.pressure_pa);
      out.recording += line;
      out.flown[qr->board.now_us()] = {chain.height_mm(), chain.climb_mm_s()};
    }
    // Height 0 is where the vehicle stood while it calibrated.
    if (std::isnan(ground) && chain.height_valid()) ground = -plant.state().position.z;
    if (since < 0 || std::isnan(ground)) continue;
    const double height = -plant.state().position.z - ground, climb = -plant.state().velocity.z;
    Errors* window = since >= kHoverFrom && since < kHoverTo   ? &out.hover
                     : since >= kClimbFrom && since < kClimbTo ? &out.climb
                                                               : nullptr;
    if (window != nullptr) {
      window->height.push_back(chain.height_mm() * 1e-3 - height);
      window->climb.push_back(chain.climb_mm_s() * 1e-3 - climb);
      window->baro.push_back(chain.baro_height_mm() * 1e-3 - height);
    }
    out.bias_end_mm_s2 = chain.accel_bias_mm_s2();
    out.valid = chain.height_valid();
    out.flew = since > kEnd - 0.1 && -plant.state().position.z > 4;
  }
  return out;
}

int seeds() {
  const char* n = std::getenv("QR_HEIGHT_SEEDS");
  return n != nullptr ? std::max(1, std::atoi(n)) : 2;
}

TEST(HeightEstimate, FollowsTheTruthInHoverAndClimb) {
  for (int seed = 1; seed <= seeds(); ++seed) {
    const HeightFlight f = fly(static_cast<uint64_t>(seed));
    ASSERT_TRUE(f.valid) << "seed " << seed << ": no barometer reference after calibration";
    ASSERT_TRUE(f.flew) << "seed " << seed << ": the flight plan did not reach 4.5 m";
    const Errors& h = f.hover;
    const Errors& c = f.climb;
    std::printf(
        "{\"seed\": %d, \"hover_height_rms_m\": %.4f, \"hover_height_max_m\": %.4f, \"hover_climb_rms_m_s\": %.4f, "
        "\"hover_climb_max_m_s\": %.4f, \"hover_baro_rms_m\": %.4f, \"climb_height_rms_m\": %.4f, "
        "\"climb_height_max_m\": %.4f, \"climb_climb_rms_m_s\": %.4f, \"climb_climb_max_m_s\": %.4f, "
        "\"climb_baro_rms_m\": %.4f, \"accel_bias_end_mm_s2\": %.0f}\n",
        seed, h.rms(h.height), h.max(h.height), h.rms(h.climb), h.max(h.climb), h.rms(h.baro), c.rms(c.height),
        c.max(c.height), c.rms(c.climb), c.max(c.climb), c.rms(c.baro), f.bias_end_mm_s2);
    EXPECT_LT(h.rms(h.height), 0.08) << "seed " << seed;
    EXPECT_LT(h.max(h.height), 0.25) << "seed " << seed;
    EXPECT_LT(h.rms(h.climb), 0.06) << "seed " << seed;
    EXPECT_LT(c.rms(c.height), 0.10) << "seed " << seed;
    EXPECT_LT(c.max(c.height), 0.30) << "seed " << seed;
    EXPECT_LT(c.rms(c.climb), 0.08) << "seed " << seed;
    // The fusion is worth having: smoother than the barometer alone.
    EXPECT_LT(h.rms(h.height), 0.7 * h.rms(h.baro)) << "seed " << seed;
  }
}

// Test mode reproduces the flight's height estimate: the recorded samples replayed give the
// height and speed the firmware had, tick for tick (the flight's safe mode between calibration and
// arming runs the height row as full control does, so the replay's shortcut changes nothing).
TEST(HeightEstimate, ReplayOfTheFlightGivesItsHeightBitForBit) {
  const HeightFlight f = fly(1);
  std::istringstream in(f.recording);
  std::ostringstream out, errors;
  ASSERT_EQ(qr::host::run_replay(in, "flight", out, errors), 0) << errors.str();
  std::istringstream rows(out.str());
  std::string line;
  std::getline(rows, line);
  std::vector<std::string> names;
  {
    std::istringstream header(line);
    for (std::string n; std::getline(header, n, ',');) names.push_back(n);
  }
  const auto column = [&](const std::string& name) {
    return static_cast<size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const size_t time = column("time_us"), height = column("height_mm"), climb = column("climb_mm_s");
  ASSERT_LT(climb, names.size());
  size_t compared = 0, moving = 0;
  while (std::getline(rows, line)) {
    std::vector<std::string> v;
    std::istringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) v.push_back(x);
    const auto it = f.flown.find(static_cast<uint32_t>(std::stoul(v[time])));
    ASSERT_NE(it, f.flown.end()) << v[time];
    ASSERT_EQ(std::stol(v[height]), it->second.first) << "height at " << v[time] << " us";
    ASSERT_EQ(std::stol(v[climb]), it->second.second) << "climb at " << v[time] << " us";
    ++compared;
    if (it->second.first > 1000) ++moving;
  }
  EXPECT_GT(compared, 20000u);
  EXPECT_GT(moving, 10000u) << "the comparison covers the flight above 1 m";
}

}  // namespace
