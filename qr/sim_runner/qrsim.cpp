// qrsim: the host firmware flying in the simulator.
//   qrsim --serve [--stdio]        real time, the QR's serial line on a pseudo terminal or stdio
//   qrsim --scenario NAME --json   headless, faster than real time, one JSON object of figures
//   qrsim --sweep NAME --seeds N   the scenario over N seeds and drawn vehicles, band summaries
//   qrsim --soak                   an hour over a damaged line, judged; one JSON line
//   qrsim --autotune               the identification flight, the models fitted, the gains designed
//   qrsim --replay IN --out OUT    a recording through the flight chain (qr/host/replay.hpp)
// Run `qrsim --help` for everything; docs/simulator.md describes the model and the scenarios.
#include <cstdio>
#include <iostream>
#include <string>

#include <qr/host/replay.hpp>
#include <qr/sim_runner/autotune.hpp>
#include <qr/sim_runner/builtin_scenarios.hpp>
#include <qr/sim_runner/qrsim_options.hpp>
#include <qr/sim_runner/scenario.hpp>
#include <qr/sim_runner/serve.hpp>
#include <qr/sim_runner/soak.hpp>
#include <qr/sim_runner/sweep.hpp>

namespace {

using qrsim::Command;
using qrsim::CommandLine;
using qrsim::usage_error;

// No command is a mistake too: the usage then goes with exit status 2.
int show_usage(CommandLine& line) {
  qrsim::print_usage();
  return line.command == Command::help ? 0 : 2;
}

int replay(CommandLine& line) {
  if (line.replay_out.empty()) return usage_error("--replay needs --out OUT.csv");
  return qr::host::run_replay(line.replay_in.c_str(), line.replay_out.c_str(), std::cerr, line.replay);
}

// Each built-in is read as --scenario reads it: its window and summary are in its text.
int list(CommandLine&) {
  qrsim::ScenarioScript script;
  for (const qrsim::BuiltinScenario& b : qrsim::builtin_scenarios()) {
    std::string error;
    if (!qrsim::find_scenario(b.name, script, error)) {
      std::fprintf(stderr, "qrsim: %s\n", error.c_str());
      return 1;
    }
    std::printf("%-22s %4.0f s  %s%s\n", b.name, script.seconds, script.summary.c_str(),
                script.known_failure.empty() ? "" : " [known failure]");
  }
  return 0;
}

int soak(CommandLine& line) {
  qrsim::SoakOptions soak;
  if (line.seconds > 0) soak.seconds = line.seconds;
  soak.seed = line.seed;
  return qrsim::run_soak(soak) ? 0 : 1;
}

int serve(CommandLine& line) {
  const qrsim::RunOptions& flight = line.flight;
  if (flight.radio && !flight.devboard_elf.empty())
    return usage_error("--rc crsf flies the host firmware only: the devboard's sensor link carries no radio");
  qrsim::ServeOptions serve;
  serve.radio = flight.radio;
  serve.dshot = flight.dshot;
  serve.stdio = line.stdio;
  serve.status = line.status;
  serve.truth_fd = line.truth_fd;
  serve.seconds = line.seconds;
  serve.seed = line.seed;
  serve.devboard_elf = flight.devboard_elf;
  serve.devboard_core_mhz = flight.devboard_core_mhz;
  serve.sensor_drivers = line.sensors_given && flight.sensor_drivers;
  serve.vehicle = line.vehicle ? *line.vehicle : sim::default_vehicle();
  return qrsim::serve(serve);
}

// What a scenario and a sweep share: the line's time, seed and vehicle into the flight's options.
void take_flight_settings(CommandLine& line) {
  line.flight.seconds = line.seconds;
  line.flight.seed = line.seed;
  line.flight.vehicle = line.vehicle;
  line.flight.vehicle_name = line.vehicle_name;
}

int sweep(CommandLine& line) {
  if (!line.flight.devboard_elf.empty()) return usage_error("--devboard goes with --scenario");
  take_flight_settings(line);
  bool all = true;
  for (const qrsim::BandSummary& b : qrsim::run_sweep(line.script, line.flight, line.seeds, line.draw, stdout))
    all = all && b.passed == b.of;
  return all ? 0 : 1;
}

// The figures for a person: one a line, then each band's verdict.
void print_scenario_result(const qrsim::ScenarioResult& result) {
  // Beside the figures on stdout: what the flight did otherwise than the file says.
  for (const std::string& note : result.notes) std::fprintf(stderr, "qrsim: note: %s\n", note.c_str());
  std::printf("scenario %s on %s: %s\n", result.scenario.c_str(), result.vehicle.c_str(),
              result.pass ? "PASS" : "FAIL");
  if (!result.error.empty()) std::printf("  error: %s\n", result.error.c_str());
  if (!result.known_failure.empty()) std::printf("  known failure: %s\n", result.known_failure.c_str());
  for (const qrsim::Figure& f : result.figures) {
    if (f.name == "final_mode") {
      std::printf("  %-26s %s\n", "final_mode", result.final_mode.c_str());
    } else {
      std::printf("  %-26s %.4g\n", f.name.c_str(), f.value);
    }
  }
  for (const qrsim::CheckResult& c : result.checks) std::printf("  [%s] %s\n", c.pass ? "ok" : "FAIL", c.band.c_str());
}

int scenario(CommandLine& line) {
  take_flight_settings(line);
  const qrsim::ScenarioResult result = qrsim::run_scenario(line.script, line.flight);
  if (line.json) {
    std::printf("%s\n", qrsim::to_json(result).c_str());
  } else {
    print_scenario_result(result);
  }
  return result.pass ? 0 : 1;
}

int autotune(CommandLine& line) {
  if (!line.flight.devboard_elf.empty() || line.flight.radio)
    return usage_error("--autotune flies the host firmware from the PC link (no --devboard, no --rc)");
  take_flight_settings(line);
  return qrsim::run_autotune(line.flight, stdout);
}

struct CommandRun {
  Command command;
  int (*run)(CommandLine& line);  // the process's exit status
};

constexpr CommandRun kCommands[] = {
    {Command::none, show_usage}, {Command::help, show_usage},   {Command::replay, replay},
    {Command::list, list},       {Command::soak, soak},         {Command::serve, serve},
    {Command::sweep, sweep},     {Command::scenario, scenario}, {Command::autotune, autotune},
};

}  // namespace

int main(int argc, char** argv) {
  CommandLine line;
  if (!qrsim::read_command_line(argc, argv, line)) return 2;
  for (const CommandRun& c : kCommands) {
    if (c.command == line.command) return c.run(line);
  }
  return 2;
}
