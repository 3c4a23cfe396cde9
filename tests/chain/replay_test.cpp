// Test mode (qr/host/replay.hpp): the committed recording replays to the same bytes every time,
// to the very values the devboard computes (the host/devboard checksum), and to the double
// reference within stated bounds; bad input fails with its line number and leaves no output.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <qr/core/chain/flight_chain.hpp>
#include <qr/host/replay.hpp>

#include "chain_checksum.hpp"
#include "recording.hpp"

namespace qr::host {
namespace {

namespace fs = std::filesystem;
const fs::path kRecording = fs::path(QR_TEST_DATA_DIR) / "synthetic_flight.csv";

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() /
                     ("qr-replay-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::create_directories(d);
  return d;
}

std::vector<std::vector<int64_t>> parse_output(const std::string& csv) {
  std::vector<std::vector<int64_t>> rows;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<int64_t> row;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ',')) row.push_back(std::stoll(f));
    rows.push_back(row);
  }
  return rows;
}

std::string replay_text(const std::string& input, const ReplayOptions& options = {}) {
  std::istringstream in(input);
  std::ostringstream out, errors;
  EXPECT_EQ(run_replay(in, "input", out, errors, options), 0) << errors.str();
  return out.str();
}

TEST(Replay, CommittedRecordingIsTheGeneratorsOutput) {
  const std::string committed = read_file(kRecording);
  EXPECT_EQ(committed, chain::test::synthetic_recording_csv<1000>())
      << "regenerate: build/<dir>/tests/chain/make-recording > tests/data/synthetic_flight.csv";
  EXPECT_LT(committed.size(), 200u * 1024u);
}

TEST(Replay, SameRecordingSameBytes) {
  const fs::path dir = temp_dir();
  ASSERT_EQ(run_replay(kRecording.c_str(), (dir / "a.csv").c_str()), 0);
  ASSERT_EQ(run_replay(kRecording.c_str(), (dir / "b.csv").c_str()), 0);
  const std::string a = read_file(dir / "a.csv"), b = read_file(dir / "b.csv");
  EXPECT_GT(a.size(), 100000u);
  EXPECT_EQ(a, b);
  fs::remove_all(dir);
}

// The replay's columns after time_us and mode are the read-outs the host/devboard checksum folds,
// in its order: folding them must give the checksum the devboard program asserts, so the replay
// of the committed recording is bit for bit what the RV32 build computes.
TEST(Replay, OutputIsWhatTheDevboardComputes) {
  const std::string output = replay_text(read_file(kRecording));
  const auto rows = parse_output(output);
  ASSERT_EQ(rows.size(), chain::synthetic::Flight<1000>::kTicks);
  chain::checksum::Fnv1a h;
  for (const auto& row : rows) {
    for (size_t i = 2; i < row.size(); ++i) h.add(static_cast<int32_t>(row[i]));
  }
  EXPECT_EQ(h.value(), chain::checksum::kExpected);
}

TEST(Replay, Recordings500HzRunTheChainAt500Hz) {
  const auto rows = parse_output(replay_text(chain::test::synthetic_recording_csv<500>()));
  chain::checksum::Fnv1a h;
  for (const auto& row : rows) {
    for (size_t i = 2; i < row.size(); ++i) h.add(static_cast<int32_t>(row[i]));
  }
  FlightChain<chain::FixedNumbers, 500> direct;
  EXPECT_EQ(h.value(), chain::checksum::fly(direct));
}

// The height estimate at both control rates (it runs at 250 Hz in both): the synthetic barometer
// falls 6 Pa/s for 1.9 s, 0.95 m of climb; both estimates end near it and near each other.
TEST(Replay, HeightEstimateRunsAtBothRates) {
  std::istringstream header(replay_output_header());
  std::vector<std::string> names;
  for (std::string n; std::getline(header, n, ',');) names.push_back(n);
  const size_t height = static_cast<size_t>(std::find(names.begin(), names.end(), "height_mm") - names.begin());
  ASSERT_LT(height, names.size());
  const int64_t at_1000 = parse_output(replay_text(chain::test::synthetic_recording_csv<1000>())).back()[height];
  const int64_t at_500 = parse_output(replay_text(chain::test::synthetic_recording_csv<500>())).back()[height];
  std::printf("  height at the end: %lld mm at 1 kHz, %lld mm at 500 Hz (the barometer's ramp: 950 mm)\n",
              static_cast<long long>(at_1000), static_cast<long long>(at_500));
  EXPECT_LE(std::llabs(at_1000 - 950), 150);
  EXPECT_LE(std::llabs(at_500 - 950), 150);
  EXPECT_LE(std::llabs(at_500 - at_1000), 100);
}

// The flight build against the double chain over the recording, column by column, in the
// read-outs' own units. Bounds: the measured worst differences.
TEST(Replay, FixedMatchesTheDoubleReference) {
  const std::string input = read_file(kRecording);
  const auto fixed = parse_output(replay_text(input));
  const auto reference = parse_output(replay_text(input, {ReplayArithmetic::reference_double}));
  ASSERT_EQ(fixed.size(), reference.size());
  std::istringstream header(replay_output_header());
  std::vector<std::string> names;
  for (std::string n; std::getline(header, n, ',');) names.push_back(n);
  std::vector<int64_t> worst(names.size(), 0);
  for (size_t r = 0; r < fixed.size(); ++r) {
    for (size_t c = 0; c < names.size(); ++c)
      worst[c] = std::max<int64_t>(worst[c], std::llabs(fixed[r][c] - reference[r][c]));
  }
  std::string figures;
  for (size_t c = 0; c < names.size(); ++c) {
    if (worst[c] != 0) figures += " " + names[c] + "=" + std::to_string(worst[c]);
  }
  std::printf("  columns that differ (worst, in the column's unit):%s\n", figures.empty() ? " none" : figures.c_str());
  for (size_t c = 0; c < names.size(); ++c) {
    // The moments in 1e-3 thrust units: the recording flies (its barometer climbs, landed_detector.hpp),
    // so the rate loops' integrals sum their rounding: 2 measured. Everything else: at most one
    // unit of its read-out (rounding of a value that differs by far less).
    const bool moment = names[c].find("moment_") == 0 || names[c].find("applied_") == 0;
    EXPECT_LE(worst[c], moment ? 2 : 1) << names[c];
  }
}

// ---- bad input ----

struct Failure {
  int rc;
  std::string message;
};

Failure replay_failure(const std::string& input) {
  std::istringstream in(input);
  std::ostringstream out, errors;
  const int rc = run_replay(in, "in.csv", out, errors);
  return {rc, errors.str()};
}

std::string recording_with(size_t line, const std::string& replacement) {
  std::istringstream in(read_file(kRecording));
  std::string text, l;
  for (size_t n = 1; std::getline(in, l); ++n) text += (n == line ? replacement : l) + "\n";
  return text;
}

TEST(Replay, BadInputFailsWithItsLineNumber) {
  const struct {
    std::string input;
    std::string message;
  } cases[] = {
      {"", "in.csv:1: empty"},
      {"time_us,gyro_x\n1,2\n",
       "in.csv:1: header must be 'time_us,gyro_x,gyro_y,gyro_z,accel_x,accel_y,accel_z,"
       "battery_mv,lift,roll,pitch,yaw,pressure_pa', got 'time_us,gyro_x'"},
      {recording_with(5, "1004000,1,2,3,4,5,6,7,8,9,10,11"), "in.csv:5: expected 13 fields, got 12"},
      {recording_with(7, "1006000,1,2,3,4,x5,6,7,8,9,10,11,0"), "in.csv:7: accel_y: 'x5' is not an integer"},
      {recording_with(7, "1006000,1,2,3,4,5.5,6,7,8,9,10,11,0"), "in.csv:7: accel_y: '5.5' is not an integer"},
      {recording_with(9, "1008000,1,2,3,4,5,6,7,1200,9,10,11,0"), "in.csv:9: lift: 1200 is outside 0..1000"},
      {recording_with(9, "1008000,40000,2,3,4,5,6,7,8,9,10,11,0"), "in.csv:9: gyro_x: 40000 is outside -32768..32767"},
      {recording_with(9, "1008000,1,2,3,4,5,6,7,8,9,10,11,"), "in.csv:9: pressure_pa: '' is not an integer"},
      {recording_with(9, "1008000,1,2,3,4,5,6,7,8,9,10,11,130000"),
       "in.csv:9: pressure_pa: 130000 is outside 0..120000"},
      {recording_with(11, "1009500,1,2,3,4,5,6,7,8,9,10,11,0"),
       "in.csv:11: time step 1500 us differs from the first, 1000 us"},
      {recording_with(3, "1003000,1,2,3,4,5,6,7,8,9,10,11,0"), "in.csv:3: time step 3000 us: the chain runs at"},
      {replay_input_header() + "\n1000,0,0,0,0,0,-8192,12000,0,0,0,0,0\n", "in.csv: has 1 rows; the first 512"},
  };
  for (const auto& c : cases) {
    const Failure f = replay_failure(c.input);
    EXPECT_EQ(f.rc, 1) << c.message;
    EXPECT_NE(f.message.find("replay: " + c.message), std::string::npos) << "got: " << f.message;
  }
}

TEST(Replay, MissingInputAndUnwritableOutputFail) {
  const fs::path dir = temp_dir();
  std::ostringstream errors;
  EXPECT_EQ(run_replay((dir / "missing.csv").c_str(), (dir / "out.csv").c_str(), errors), 1);
  EXPECT_NE(errors.str().find("cannot open"), std::string::npos) << errors.str();
  EXPECT_FALSE(fs::exists(dir / "out.csv"));
  errors.str("");
  EXPECT_EQ(run_replay(kRecording.c_str(), (dir / "no" / "such" / "dir.csv").c_str(), errors), 2);
  EXPECT_NE(errors.str().find("cannot write"), std::string::npos) << errors.str();
  fs::remove_all(dir);
}

TEST(Replay, BadInputLeavesNoOutputFile) {
  const fs::path dir = temp_dir();
  {
    std::ofstream bad(dir / "bad.csv");
    bad << recording_with(600, "oops");
  }
  std::ostringstream errors;
  EXPECT_EQ(run_replay((dir / "bad.csv").c_str(), (dir / "out.csv").c_str(), errors), 1);
  EXPECT_NE(errors.str().find(":600: expected 13 fields, got 1"), std::string::npos) << errors.str();
  EXPECT_FALSE(fs::exists(dir / "out.csv"));
  fs::remove_all(dir);
}

TEST(Replay, HeaderMayEndInCarriageReturnAndBlankLinesAreSkipped) {
  std::string input = read_file(kRecording);
  input.insert(input.find('\n'), "\r");
  input += "\n\n";
  EXPECT_EQ(replay_text(input), replay_text(read_file(kRecording)));
}

// A recording from before the barometer (no pressure_pa column) still replays: no height estimate,
// a note, and the same attitude, engines and every other column as with its pressures until the
// barometer's climb lets the landed detector see the take-off (the height estimate 0.1 m up,
// landed_detector.hpp): from then on the chain with a barometer flies and the other still rests.
TEST(Replay, RecordingWithoutPressureReplaysWithNoBarometer) {
  std::istringstream full(read_file(kRecording));
  std::string old, line;
  for (bool first = true; std::getline(full, line); first = false) {
    old += (first ? replay_input_header_without_pressure() : line.substr(0, line.rfind(','))) + "\n";
  }
  std::istringstream in(old);
  std::ostringstream out, errors;
  ASSERT_EQ(run_replay(in, "old.csv", out, errors), 0) << errors.str();
  EXPECT_NE(errors.str().find("replay: old.csv: note: no pressure_pa column: the barometer is absent"),
            std::string::npos)
      << errors.str();
  const auto without = parse_output(out.str());
  const auto with = parse_output(replay_text(read_file(kRecording)));
  ASSERT_EQ(without.size(), with.size());
  std::istringstream header(replay_output_header());
  std::vector<std::string> names;
  for (std::string n; std::getline(header, n, ',');) names.push_back(n);
  bool height_moved = false, apart = false;
  const size_t height_column = static_cast<size_t>(std::find(names.begin(), names.end(), "height_mm") - names.begin());
  ASSERT_LT(height_column, names.size());
  for (size_t r = 0; r < with.size(); ++r) {
    for (size_t c = 0; c < names.size(); ++c) {
      const bool height = names[c].find("height") != std::string::npos || names[c] == "climb_mm_s" ||
                          names[c] == "accel_bias_mm_s2";
      if (height) {
        EXPECT_EQ(without[r][c], 0) << names[c] << " row " << r;
        height_moved = height_moved || with[r][c] != 0;
      } else if (!apart && without[r][c] != with[r][c]) {
        apart = true;
        EXPECT_GT(with[r][height_column], 100) << names[c] << " differs at row " << r << " before the climb";
      }
    }
  }
  EXPECT_TRUE(apart) << "the climb the barometer shows is a take-off";
  EXPECT_TRUE(height_moved) << "with its pressures the same recording has a height estimate";
}

// A downloaded sensor log (qrterm's sensor_log_N.csv) replays as it is: the same as the recording
// of its samples with the sticks neutral and no barometer, which it does not hold. Logged slower
// than every period, it is refused with what to change.
TEST(Replay, DownloadedSensorLogReplaysAsItsSamples) {
  std::istringstream recording(read_file(kRecording));
  std::string line, log, neutral;
  std::getline(recording, line);
  log =
      "line,time_us,gyro_x_counts,gyro_y_counts,gyro_z_counts,accel_x_counts,accel_y_counts,accel_z_counts,"
      "gyro_filtered_x_counts,gyro_filtered_y_counts,gyro_filtered_z_counts,accel_filtered_x_counts,"
      "accel_filtered_y_counts,accel_filtered_z_counts,battery_mv\r\n";
  neutral = replay_input_header_without_pressure() + "\n";
  std::vector<std::string> slow;  // the same samples a line every 10 ms: log_divider 10
  for (size_t n = 0; std::getline(recording, line); ++n) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string v; std::getline(fields, v, ',');) f.push_back(v);
    ASSERT_EQ(f.size(), 13u) << line;
    // time, gyro x y z, accel x y z, then the filtered values (any: the replay filters itself), battery
    const std::string row = std::to_string(n) + "," + f[0] + "," + f[1] + "," + f[2] + "," + f[3] + "," + f[4] + "," +
                            f[5] + "," + f[6] + ",1,2,3,4,5,6," + f[7] + "\r\n";
    log += row;
    slow.push_back(std::to_string(n) + "," + std::to_string((n + 1) * 10000) +
                   row.substr(row.find(',', row.find(',') + 1)));
    neutral += f[0] + "," + f[1] + "," + f[2] + "," + f[3] + "," + f[4] + "," + f[5] + "," + f[6] + "," + f[7] +
               ",0,0,0,0\n";
  }
  std::istringstream in(log);
  std::ostringstream out, errors;
  ASSERT_EQ(run_replay(in, "sensor_log_1.csv", out, errors), 0) << errors.str();
  EXPECT_NE(errors.str().find("note: a downloaded sensor log"), std::string::npos) << errors.str();
  EXPECT_EQ(out.str(), replay_text(neutral));

  std::string slow_log = log.substr(0, log.find('\n') + 1);
  for (const std::string& row : slow) slow_log += row;
  std::istringstream slow_in(slow_log);
  std::ostringstream slow_out, slow_errors;
  EXPECT_EQ(run_replay(slow_in, "sensor_log_2.csv", slow_out, slow_errors), 1);
  EXPECT_NE(slow_errors.str().find("log with log_divider = 1 to replay a sensor log"), std::string::npos)
      << slow_errors.str();
}

}  // namespace
}  // namespace qr::host
