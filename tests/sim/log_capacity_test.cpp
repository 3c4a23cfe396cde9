// How long a flight the QR's log holds (issue 36: at least 30 s of 1 kHz sensor lines in the
// devboard's log area, which the simulator's board has too). The host firmware flies the default
// vehicle with its noise and vibration: a take-off to 1.5 m, then roll and pitch steps of a few
// degrees every second, logging both logs at log_divider 1 from arming until the area is full. The
// lines are checked as they come out of the packing against what the logger was given, and the
// test prints {"log": {"bytes": ..., "seconds_at_1khz": ...}}.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <qr/boards/sim/sim_qr.hpp>
#include <qr/core/flight_log_lines.hpp>
#include <qr/sim_runner/pilot.hpp>

namespace {

struct LoggedFlight {
  std::vector<wire::SensorLogRecord> written;  // what the logger was given, line by line
  uint16_t lines = 0, telemetry_lines = 0;
  bool full = false;
  double truth_max_tilt_deg = 0;
};

LoggedFlight fly_until_the_log_is_full(qrsim::SimQr& qr) {
  LoggedFlight out;
  qrsim::Pilot pilot(qr.board);
  sim::Quadrotor& plant = qr.world.plant();
  double armed_at = -1;
  bool asked_calibration = false, asked_arm = false, asked_log = false;
  pilot.set_parameter(wire::ParamId::log_divider, 1);
  for (int tick = 0; tick < 90000 && !out.full; ++tick) {
    const double t = static_cast<double>(qr.world.now_us()) * 1e-6;
    const qrsim::ConsoleView& view = pilot.view();
    if (!asked_calibration && t > 0.3) {
      pilot.request_mode(wire::Mode::calibration);
      asked_calibration = true;
    }
    if (asked_calibration && !asked_arm && view.heard && (view.flags & wire::kFlagCalibrated) != 0 &&
        view.mode == wire::Mode::safe) {
      pilot.request_mode(wire::Mode::full_control);
      asked_arm = true;
    }
    if (armed_at < 0 && view.mode == wire::Mode::full_control) armed_at = t;
    if (armed_at >= 0 && !asked_log) {
      pilot.request(wire::LogStart{});
      asked_log = true;
    }
    if (armed_at >= 0) {
      // a step of about 3 degrees on roll, then on pitch, each second, after 4 s
      const double since = t - armed_at;
      const int second = static_cast<int>(since);
      const int16_t step = since > 4 && second % 2 == 0 ? 60 : 0;
      pilot.set_sticks({qrsim::lift_for_height(plant, 1.5, 1.0), second % 4 == 0 ? step : int16_t{0},
                        second % 4 == 2 ? step : int16_t{0}, 0});
    }
    pilot.step();
    if (!qr.tick()) break;
    const qr::FlightLog<qr::FixedChain>& log = qr.firmware.log();
    const wire::LogStatus status = log.status();
    if (log.logging() && status.sensor_lines > out.written.size())
      out.written.push_back(qr::sensor_log_line(qr.firmware));
    out.lines = status.sensor_lines;
    out.telemetry_lines = status.telemetry_lines;
    out.full = log.full();
    const sim::Vec3 down = sim::rotate(plant.state().attitude, {0, 0, 1});
    out.truth_max_tilt_deg = std::max(out.truth_max_tilt_deg, std::acos(std::clamp(down.z, -1.0, 1.0)) * 180 / M_PI);
  }
  return out;
}

TEST(LogCapacity, ThirtySecondsOfOneKilohertzLinesFitTheDevboardsArea) {
  const std::unique_ptr<qrsim::SimQr> qr = qrsim::make_qr(sim::default_vehicle(), {.seed = 1});
  const LoggedFlight flight = fly_until_the_log_is_full(*qr);
  ASSERT_TRUE(flight.full) << "the log never filled: " << flight.lines << " lines";
  ASSERT_EQ(flight.written.size(), flight.lines);
  EXPECT_LT(flight.truth_max_tilt_deg, 20) << "the flight went wrong: its figure would mean nothing";

  // Every sensor line comes out as the logger was given it; the telemetry lines come with every
  // tenth (100 Hz), at its time.
  const qr::FlightLog<qr::FixedChain>& log = qr->firmware.log();
  size_t different = 0;
  for (uint16_t i = 0; i < flight.lines; ++i) {
    qr::log_pack::LogLine line;
    ASSERT_TRUE(log.read_line(wire::LogKind::sensor, i, line)) << i;
    wire::SensorLogRecord want = flight.written[i];
    want.line = line.sensor.line;
    different += !(line.sensor == want);
  }
  EXPECT_EQ(different, 0u);
  EXPECT_EQ(flight.telemetry_lines, (flight.lines + 9) / 10);
  for (uint16_t t = 0; t < flight.telemetry_lines; t += 97) {
    qr::log_pack::LogLine line;
    ASSERT_TRUE(log.read_line(wire::LogKind::telemetry, t, line));
    EXPECT_EQ(line.telemetry.time_us, flight.written[t * 10u].time_us) << t;
  }

  const size_t area = qr->board.log_area().size;
  const double seconds = flight.lines / 1000.0;
  std::printf(
      "{\"log\": {\"bytes\": %zu, \"seconds_at_1khz\": %.1f, \"lines\": %u, \"telemetry_lines\": %u, "
      "\"bytes_per_line\": %.2f, \"index_bytes\": %zu, \"flight\": \"hover at 1.5 m with 3 deg steps, "
      "default vehicle, seed 1\"}}\n",
      area, seconds, flight.lines, flight.telemetry_lines,
      static_cast<double>(log.packed_bits_used()) / 8.0 / flight.lines, area - log.packed_bytes());
  EXPECT_GE(seconds, 30.0);
}

}  // namespace
