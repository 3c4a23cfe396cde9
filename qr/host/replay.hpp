// Test mode on the host: recorded sensor samples and sticks run through the flight chain tick by
// tick, and every tick's estimates, controller outputs and engine values written out. The
// simulator's `qrsim --replay IN.csv --out OUT.csv` and the small `qrreplay` call this.
//
// docs/replay.md describes both CSV formats. In short: the input has a header and one row per
// control period (time_us, gyro_x..z, accel_x..z in raw counts, battery_mv, lift, roll, pitch,
// yaw sticks, pressure_pa); the control rate (1000 or 500 Hz) is the input's time step. The first
// kCalibrationSamples rows (512) calibrate the sensors, so the vehicle must be level and still
// in them; the rest run in full control. Deterministic: the flight build is integer arithmetic.
#pragma once

#include <iosfwd>
#include <string>

#include <common/parameter_table.hpp>

namespace qr::host {

enum class ReplayArithmetic {
  fixed,             // FixedChain: what the QR computes, bit for bit
  reference_double,  // FlightChain<DoubleNumbers>: the accuracy reference, same output format
};

struct ReplayOptions {
  ReplayArithmetic arithmetic = ReplayArithmetic::fixed;
  // The chain's parameters: a recording replays bit for bit with the ones it flew with (the
  // defaults unless the flight changed some: gains, the filter's cut-off, a measured gyro scale).
  wire::ParameterValues parameters{};
};

// Reads `in_csv`, writes `out_csv`. Returns 0 on success. On bad input (a missing or unreadable
// file, a bad header, a short or long row, a field that is not an integer or is out of range,
// a time step that is not the control period, too few rows to calibrate) writes one line
// "replay: IN.csv:LINE: what" to `errors`, and returns 1; 2 when the output cannot be written.
int run_replay(const char* in_csv, const char* out_csv, std::ostream& errors, const ReplayOptions& options = {});
// The same without the standard error stream in the signature.
int run_replay(const char* in_csv, const char* out_csv);

// Streams instead of files; `in_name` names the input in messages.
int run_replay(std::istream& in, const char* in_name, std::ostream& out, std::ostream& errors,
               const ReplayOptions& options = {});

// The header lines of both formats (without the line end). Input without the last column,
// pressure_pa, is the format before the barometer: it replays with no barometer, and says so on
// the error stream.
const std::string& replay_input_header();
const std::string& replay_input_header_without_pressure();
const std::string& replay_output_header();

}  // namespace qr::host
