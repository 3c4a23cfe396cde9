// Test mode: recorded samples and sticks through the flight chain, tick by tick (replay.hpp).
#include "replay.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <common/mode.hpp>
#include <qr/core/chain/flight_chain.hpp>
#include <qr/core/replay_tick.hpp>
#include <qr/host/real_numbers.hpp>

namespace qr::host {
namespace {

// ---- input ----

struct Field {
  const char* name;
  int64_t min, max;
};

// The input columns, in order, with the range each must hold.
constexpr Field kInputFields[] = {
    {"time_us", 0, UINT32_MAX},
    {"gyro_x", INT16_MIN, INT16_MAX},
    {"gyro_y", INT16_MIN, INT16_MAX},
    {"gyro_z", INT16_MIN, INT16_MAX},
    {"accel_x", INT16_MIN, INT16_MAX},
    {"accel_y", INT16_MIN, INT16_MAX},
    {"accel_z", INT16_MIN, INT16_MAX},
    {"battery_mv", 0, UINT16_MAX},
    {"lift", 0, 1000},
    {"roll", -1000, 1000},
    {"pitch", -1000, 1000},
    {"yaw", -1000, 1000},
    // The barometer (board.hpp: 0 = absent); the MS5611 reads 1000..120000 Pa. Recordings made
    // before it existed end at yaw and replay with no barometer.
    {"pressure_pa", 0, 120000},
};
constexpr size_t kInputFieldCount = sizeof(kInputFields) / sizeof(kInputFields[0]);
constexpr size_t kFieldsWithoutPressure = kInputFieldCount - 1;

// A log downloaded by the console (qrterm's sensor_log_N.csv, docs/console.md) replays as it is:
// its raw samples, with the sticks neutral and no barometer (the log holds neither). Its columns
// in order, each with its range and the input field it fills (-1: checked, not used).
struct LogColumn {
  Field field;
  int input;
};
constexpr int kUnused = -1;
constexpr LogColumn kSensorLogColumns[] = {
    {{"line", 0, UINT16_MAX}, kUnused},
    {{"time_us", 0, UINT32_MAX}, 0},
    {{"gyro_x_counts", INT16_MIN, INT16_MAX}, 1},
    {{"gyro_y_counts", INT16_MIN, INT16_MAX}, 2},
    {{"gyro_z_counts", INT16_MIN, INT16_MAX}, 3},
    {{"accel_x_counts", INT16_MIN, INT16_MAX}, 4},
    {{"accel_y_counts", INT16_MIN, INT16_MAX}, 5},
    {{"accel_z_counts", INT16_MIN, INT16_MAX}, 6},
    {{"gyro_filtered_x_counts", INT16_MIN, INT16_MAX}, kUnused},
    {{"gyro_filtered_y_counts", INT16_MIN, INT16_MAX}, kUnused},
    {{"gyro_filtered_z_counts", INT16_MIN, INT16_MAX}, kUnused},
    {{"accel_filtered_x_counts", INT16_MIN, INT16_MAX}, kUnused},
    {{"accel_filtered_y_counts", INT16_MIN, INT16_MAX}, kUnused},
    {{"accel_filtered_z_counts", INT16_MIN, INT16_MAX}, kUnused},
    {{"battery_mv", 0, UINT16_MAX}, 7},
};
constexpr size_t kSensorLogColumnCount = sizeof(kSensorLogColumns) / sizeof(kSensorLogColumns[0]);

enum class InputFormat : uint8_t { recording, recording_without_pressure, sensor_log };

struct Row {
  size_t line;
  uint32_t time_us;
  SensorSample sample;
  ControlInput sticks;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    fields.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}

class InputError {
 public:
  InputError(const char* file, std::ostream& out) : file_(file), out_(out) {}
  int at(size_t line, const std::string& what) const {
    out_ << "replay: " << file_ << ":" << line << ": " << what << "\n";
    return 1;
  }
  int whole(const std::string& what) const {
    out_ << "replay: " << file_ << ": " << what << "\n";
    return 1;
  }
  // Not an error: the replay goes on.
  void note(const std::string& what) const { out_ << "replay: " << file_ << ": note: " << what << "\n"; }

 private:
  const char* file_;
  std::ostream& out_;
};

// One field as an integer within its range, or what is wrong with it.
std::string parse_field(std::string_view f, const Field& field, int64_t& value) {
  const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), value);
  if (f.empty() || ec != std::errc() || end != f.data() + f.size()) {
    return std::string(field.name) + ": '" + std::string(f) + "' is not an integer";
  }
  if (value < field.min || value > field.max) {
    return std::string(field.name) + ": " + std::to_string(value) + " is outside " + std::to_string(field.min) + ".." +
           std::to_string(field.max);
  }
  return {};
}

// Parses one data row into the input fields `v` (those a format lacks stay 0), or says what is
// wrong with it.
std::string parse_fields(std::string_view line, InputFormat format, int64_t (&v)[kInputFieldCount]) {
  const std::vector<std::string_view> fields = split(line);
  const size_t count = format == InputFormat::sensor_log                   ? kSensorLogColumnCount
                       : format == InputFormat::recording_without_pressure ? kFieldsWithoutPressure
                                                                           : kInputFieldCount;
  if (fields.size() != count) {
    return "expected " + std::to_string(count) + " fields, got " + std::to_string(fields.size());
  }
  for (size_t i = 0; i < count; ++i) {
    int64_t value = 0;
    const LogColumn column = format == InputFormat::sensor_log ? kSensorLogColumns[i]
                                                               : LogColumn{kInputFields[i], static_cast<int>(i)};
    if (std::string what = parse_field(fields[i], column.field, value); !what.empty()) return what;
    if (column.input != kUnused) v[column.input] = value;
  }
  return {};
}

std::string parse_row(std::string_view line, InputFormat format, Row& row) {
  int64_t v[kInputFieldCount] = {};
  if (std::string what = parse_fields(line, format, v); !what.empty()) return what;
  row.time_us = static_cast<uint32_t>(v[0]);
  for (int k = 0; k < 3; ++k) {
    row.sample.gyro[k] = static_cast<int16_t>(v[1 + k]);
    row.sample.accel[k] = static_cast<int16_t>(v[4 + k]);
  }
  row.sample.battery_mv = static_cast<uint16_t>(v[7]);
  row.sticks.lift = static_cast<uint16_t>(v[8]);
  row.sticks.roll = static_cast<int16_t>(v[9]);
  row.sticks.pitch = static_cast<int16_t>(v[10]);
  row.sticks.yaw = static_cast<int16_t>(v[11]);
  row.sample.pressure_pa = static_cast<int32_t>(v[12]);  // 0 when the file has no such column
  return {};
}

// ---- output ----

void append(std::string& line, int64_t v) {
  char buffer[24];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  (void)ec;
  line.append(buffer, end);
}

template <class Chain>
int fly(const std::vector<Row>& rows, std::ostream& out, const wire::ParameterValues& parameters) {
  Chain chain;
  chain.set_parameters(parameters);
  ChainReplay<Chain> test_mode(chain, rows.empty() ? ChainReplay<Chain>::kPeriodUs : rows.front().time_us);
  out << replay_output_header() << "\n";
  std::string line;
  for (const Row& row : rows) {
    const wire::Mode mode = test_mode.tick(row.sample, row.sticks);
    line.clear();
    append(line, row.time_us);
    line += ',';
    append(line, static_cast<int>(mode));
    for (const auto& column : kReplayColumns<Chain>) {
      line += ',';
      append(line, column.value(chain));
    }
    line += '\n';
    out << line;
  }
  return out ? 0 : 2;
}

template <uint32_t Hz>
int fly_at(const std::vector<Row>& rows, std::ostream& out, const ReplayOptions& options) {
  if (options.arithmetic == ReplayArithmetic::reference_double)
    return fly<FlightChain<chain::DoubleNumbers, Hz>>(rows, out, options.parameters);
  return fly<FlightChain<chain::FixedNumbers, Hz>>(rows, out, options.parameters);
}

const std::string& sensor_log_header() {
  static const std::string header = [] {
    std::vector<std::string> names;
    for (const LogColumn& c : kSensorLogColumns) names.push_back(c.field.name);
    return join(names);
  }();
  return header;
}

// Reads and checks every row before the first tick, so bad input produces no output at all.
int read_rows(std::istream& in, const InputError& error, std::vector<Row>& rows, InputFormat& format) {
  std::string line;
  size_t number = 0;
  if (!std::getline(in, line)) return error.at(1, "empty: expected the header '" + replay_input_header() + "'");
  ++number;
  format = InputFormat::recording;
  if (trim(line) == replay_input_header_without_pressure()) {
    format = InputFormat::recording_without_pressure;
    error.note("no pressure_pa column: the barometer is absent, so the height estimate stays 0");
  } else if (trim(line) == sensor_log_header()) {
    format = InputFormat::sensor_log;
    error.note(
        "a downloaded sensor log: its raw samples replay with the sticks neutral and no barometer "
        "(the log holds neither)");
  } else if (trim(line) != replay_input_header()) {
    return error.at(number, "header must be '" + replay_input_header() + "', got '" + std::string(trim(line)) +
                                "' (a sensor log downloaded by qrterm replays too)");
  }
  while (std::getline(in, line)) {
    ++number;
    if (trim(line).empty()) continue;
    Row row{};
    row.line = number;
    if (const std::string what = parse_row(line, format, row); !what.empty()) return error.at(number, what);
    rows.push_back(row);
  }
  if (in.bad()) return error.whole("read error");
  return 0;
}

}  // namespace

const std::string& replay_input_header() {
  static const std::string header = [] {
    std::vector<std::string> names;
    for (const Field& f : kInputFields) names.push_back(f.name);
    return join(names);
  }();
  return header;
}

const std::string& replay_input_header_without_pressure() {
  static const std::string header = [] {
    std::vector<std::string> names;
    for (size_t i = 0; i < kFieldsWithoutPressure; ++i) names.push_back(kInputFields[i].name);
    return join(names);
  }();
  return header;
}

const std::string& replay_output_header() {
  static const std::string header = [] {
    std::vector<std::string> names = {"time_us", "mode"};
    for (const auto& column : kReplayColumns<FixedChain>) names.push_back(column.name);
    return join(names);
  }();
  return header;
}

int run_replay(std::istream& in, const char* in_name, std::ostream& out, std::ostream& errors,
               const ReplayOptions& options) {
  const InputError error(in_name, errors);
  std::vector<Row> rows;
  InputFormat format = InputFormat::recording;
  if (const int rc = read_rows(in, error, rows, format); rc != 0) return rc;
  // A sensor log holds a line every log_divider periods; the chain needs every period.
  const std::string divider_hint = format == InputFormat::sensor_log
                                       ? "; log with log_divider = 1 to replay a sensor log"
                                       : "";
  if (rows.size() < static_cast<size_t>(chain::kCalibrationSamples) + 1) {
    return error.whole("has " + std::to_string(rows.size()) + " rows; the first " +
                       std::to_string(chain::kCalibrationSamples) +
                       " calibrate the sensors, so at least one more is needed");
  }
  // The control rate is the time step, the same on every row (modulo the clock's wrap).
  const uint32_t step = rows[1].time_us - rows[0].time_us;
  if (step != 1000 && step != 2000) {
    return error.at(rows[1].line, "time step " + std::to_string(step) +
                                      " us: the chain runs at 1000 Hz (1000 us) or 500 Hz (2000 us)" + divider_hint);
  }
  for (size_t i = 1; i < rows.size(); ++i) {
    const uint32_t d = rows[i].time_us - rows[i - 1].time_us;
    if (d != step) {
      return error.at(rows[i].line, "time step " + std::to_string(d) + " us differs from the first, " +
                                        std::to_string(step) + " us: one row per control period" + divider_hint);
    }
  }
  const int rc = step == 1000 ? fly_at<1000>(rows, out, options) : fly_at<500>(rows, out, options);
  if (rc != 0) errors << "replay: cannot write the output\n";
  return rc;
}

int run_replay(const char* in_csv, const char* out_csv, std::ostream& errors, const ReplayOptions& options) {
  std::ifstream in(in_csv);
  if (!in) {
    errors << "replay: cannot open " << in_csv << " for reading\n";
    return 1;
  }
  // Checked and run into memory first: bad input leaves no output file behind.
  std::ostringstream buffer;
  if (const int rc = run_replay(in, in_csv, buffer, errors, options); rc != 0) return rc;
  std::ofstream out(out_csv, std::ios::binary);
  if (!out || !(out << buffer.str()) || !out.flush()) {
    errors << "replay: cannot write " << out_csv << "\n";
    return 2;
  }
  return 0;
}

int run_replay(const char* in_csv, const char* out_csv) { return run_replay(in_csv, out_csv, std::cerr); }

}  // namespace qr::host
