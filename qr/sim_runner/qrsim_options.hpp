// qrsim's command line (`qrsim --help` describes it): read whole before anything runs, so a
// mistake anywhere on the line is said before a flight starts. qrsim.cpp runs what it asks for.
#pragma once

#include <stdint.h>

#include <optional>
#include <string>

#include <qr/host/replay.hpp>
#include <qr/sim_runner/scenario.hpp>
#include <sim/vehicle.hpp>

namespace qrsim {

enum class Command { none, serve, scenario, sweep, soak, autotune, replay, list, help };

// What the command line says. Which fields matter depends on the command; the options that go
// with another command are read and left unused, as they always were.
struct CommandLine {
  Command command = Command::none;
  // scenario, sweep; serve takes the devboard, the radio and the ESCs from it too.
  RunOptions flight;
  ScenarioScript script;       // --scenario, --sweep: read as soon as it is named
  int seeds = 30;              // sweep
  bool draw = true;            // sweep: each run on a vehicle drawn around the scenario's
  bool json = false;           // scenario
  bool stdio = false;          // serve
  bool status = false;         // serve
  int truth_fd = -1;           // serve
  bool sensors_given = false;  // --sensors: serve flies direct unless told drivers
  double seconds = 0;          // 0: the command's own
  uint64_t seed = 1;
  std::optional<sim::VehicleParams> vehicle;
  std::string vehicle_name;
  std::string replay_in, replay_out;
  qr::host::ReplayOptions replay;
};

// Reads argv[1..] into `line`. The first mistake is said on stderr and ends the reading: false,
// and qrsim's exit status is 2.
bool read_command_line(int argc, char** argv, CommandLine& line);

// Says on stderr what is wrong with the command line; returns the exit status for it (2).
int usage_error(const std::string& message);

// `qrsim --help`'s text, on stdout.
void print_usage();

}  // namespace qrsim
