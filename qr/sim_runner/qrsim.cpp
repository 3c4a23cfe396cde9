// qrsim: the host firmware flying in the simulator.
//   qrsim --serve [--stdio]        real time, the QR's serial line on a pseudo terminal or stdio
//   qrsim --scenario NAME --json   headless, faster than real time, one JSON object of figures
//   qrsim --sweep NAME --seeds N   the scenario over N seeds and drawn vehicles, band summaries
//   qrsim --soak                   an hour over a damaged line, judged; one JSON line
//   qrsim --replay IN --out OUT    a recording through the flight chain (qr/host/replay.hpp)
// Run `qrsim --help` for everything; docs/simulator.md describes the model and the scenarios.
#include <fcntl.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>

#include <common/parameter_table.hpp>
#include <qr/sim_runner/builtin_scenarios.hpp>
#include <qr/sim_runner/scenario.hpp>
#include <qr/sim_runner/serve.hpp>
#include <qr/sim_runner/soak.hpp>
#include <qr/sim_runner/sweep.hpp>
#include <qr/sim_runner/text_fields.hpp>
#include <qr/core/rate.hpp>
#include <qr/host/replay.hpp>

namespace {

constexpr const char* kUsage = R"(usage:
  qrsim --serve [--stdio] [--seed N] [--vehicle FILE] [--seconds S] [--status] [--truth-fd N]
        [--devboard [ELF] [--core-mhz N] | --rc crsf] [--esc dshot]
  qrsim --scenario NAME|FILE [--seconds S] [--seed N] [--vehicle FILE] [--param NAME=VALUE]...
        [--no-noise] [--trace FILE.csv] [--record FILE.csv] [--json] [--devboard [ELF] [--core-mhz N]]
        [--rc crsf] [--esc dshot]
  qrsim --sweep NAME|FILE [--seeds N] [--no-draw] [--seed N] [--seconds S] [--vehicle FILE]
        [--param NAME=VALUE]... [--rc crsf] [--esc dshot]
  qrsim --soak [--seconds S] [--seed N]
  qrsim --replay IN.csv --out OUT.csv [--double] [--param NAME=VALUE]...
  qrsim --list
  qrsim --help

The QR firmware (the same code as on the RV32 board, fixed-point signal chain, %u Hz control
rate) flying in a simulated IN4073-class quadrotor.

  --serve          run in real time; the QR's serial line (115200 baud timing) is a pseudo
                   terminal whose path is the first line on stdout ("qrsim: serial on /dev/pts/N"),
                   for the console to open as it would the real line
  --stdio          with --serve: the serial line is stdin/stdout instead (messages go to stderr)
  --status         with --serve: one status line a second on stderr
  --truth-fd N     with --serve: N is an open, two-way descriptor (a socketpair end) for the
                   simulator's side channel: a truth line per 20 ms of simulated time out, commands
                   in (push, reset, turn, radio: docs/simulator.md); the firmware never sees it
  --scenario NAME  fly a scenario headless, in simulated time, and score it on the simulator's
                   truth; exit status 0 when every pass band holds, 1 when one does not. NAME is
                   a built-in (qrsim --list) or a scenario file: its format (settings, events,
                   bands) is docs/simulator.md section 6.2, its figures section 6.5
  --sweep NAME     fly the scenario over --seeds N seeds (default 30), each on a vehicle drawn
                   around it (mass, inertia, motor lag, vibration, noise); one JSON line per run,
                   then per band {"sweep", "band", "passed", "of", "worst"}; exit status 0 when
                   every run passed
  --seeds N        sweep: how many runs (seeds --seed .. --seed + N - 1)
  --no-draw        sweep: every run on the scenario's own vehicle, only the seed changes
  --seconds S      scenario: scored flight time from the manoeuvre on (default per scenario);
                   serve: stop after S seconds of flight time (default: run until exit)
  --seed N         seed of every random source (sensor noise, biases, vibration phases);
                   same seed, same flight (default 1)
  --vehicle FILE   vehicle parameter file (default: the compiled-in sim/vehicles/in4073.txt)
  --param N=V      scenario: the pilot uploads parameter N (a name from docs/parameters.md,
                   e.g. attitude_c1) with value V in the parameter's unit before flying;
                   replay: the chain runs with it, as the recorded flight did
  --no-noise       scenario: perfect sensors (no noise, bias, scale error or vibration)
  --trace FILE     scenario: write every control period to FILE as CSV (truth and estimated
                   attitude and rates, set-points, engines, position, battery)
  --record FILE    scenario: write the QR's sensor samples and sticks, from its first
                   calibration tick on, in the replay's input format (docs/replay.md)
  --json           scenario: print the figures as one JSON object on one line
  --devboard [ELF] scenario, serve: fly the cross-compiled firmware (default %s)
                   on the emulated devboard (QEMU virt, riscv32) instead of the host build, in
                   lock-step over the sensor link (docs/devboard.md); a scenario's figures add
                   "firmware": "rv32" and the binary's instructions per tick and task (instr_*)
  --core-mhz N     with --devboard: the board's core runs at N MHz (1 to 1000): its clock runs on
                   by its instructions while a tick runs, so a tick longer than its period is a
                   deadline miss, and its engines go out late (docs/devboard.md); the figures
                   add "core_mhz". Without it the clock stands still while a tick runs
  --soak           an hour (--seconds S of flight) of full control over a damaged line, logging,
                   the log downloaded at the end, judged by a referee; one JSON line {"soak": ...}
                   (docs/simulator.md section 9); exit status 1 when it failed
  --rc crsf        scenario, sweep: the pilot flies through a radio: CRSF RC frames at 150 Hz
                   on the QR's receiver line, flight modes armed with the arm switch, the pilot
                   parameter set to the radio; the PC link keeps requests, parameters and the
                   abort key; a `link 0` event silences the radio (docs/drivers.md).
                   serve: the console's sticks reach the QR through the radio (CRSF at 150 Hz;
                   silent once its control frames stop for 0.1 s) and the side channel's
                   "radio arm manual|yaw|full" and "radio off" move its switches; the QR flies
                   by them when its pilot parameter says radio (docs/simulator.md)
  --esc dshot      scenario, sweep, serve: the engines go out as bidirectional DShot frames to
                   simulated ESCs (a bad check keeps the last good value) that answer with the
                   rotor speed's eRPM, reported in telemetry as RPM
  --replay IN      run a recording through the flight chain tick by tick (test mode) and write
                   every tick's estimates, controller outputs and engines to --out OUT
                   (docs/replay.md); --double runs the double-precision reference chain
  --list           the built-in scenarios (sim/scenarios/*.txt, compiled in) and what they do

)";

int usage_error(const std::string& message) {
  std::fprintf(stderr, "qrsim: %s (see qrsim --help)\n", message.c_str());
  return 2;
}

// A scenario that does not read: --help does not describe the file, the document does.
int scenario_error(const std::string& message) {
  std::fprintf(stderr, "qrsim: %s (the scenario file format: %s)\n", message.c_str(), qrsim::kScenarioFormatDoc);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  enum class Command { none, serve, scenario, sweep, soak, replay, list, help } command = Command::none;
  std::string replay_in, replay_out;
  qr::host::ReplayOptions replay_options;
  qrsim::RunOptions scenario;
  qrsim::ScenarioScript script;
  int seeds = 30;
  bool draw = true;
  qrsim::ServeOptions serve;
  bool json = false;
  bool stdio = false;
  bool status = false;
  int truth_fd = -1;
  double seconds = 0;
  uint64_t seed = 1;
  std::optional<sim::VehicleParams> vehicle;
  std::string vehicle_name;

  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&](const char* what) -> const char* {
      if (i + 1 >= argc) return nullptr;
      (void)what;
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      command = Command::help;
    } else if (arg == "--list") {
      command = Command::list;
    } else if (arg == "--soak") {
      command = Command::soak;
    } else if (arg == "--serve") {
      command = Command::serve;
    } else if (arg == "--stdio") {
      stdio = true;
    } else if (arg == "--status") {
      status = true;
    } else if (arg == "--truth-fd") {
      const char* v = value("N");
      double n = 0;
      if (v == nullptr || !qrsim::parse_real(v, n) || n < 0 || n != std::floor(n) || n > 65535) {
        return usage_error("--truth-fd needs a descriptor number");
      }
      truth_fd = static_cast<int>(n);
      if (fcntl(truth_fd, F_GETFD) < 0)
        return usage_error("--truth-fd " + std::string(v) + " is not an open descriptor");
    } else if (arg == "--json") {
      json = true;
    } else if (arg == "--devboard") {
      // The ELF is optional: the next argument is it unless it is another option.
      scenario.devboard_elf = QR_DEVBOARD_ELF;
      if (i + 1 < argc && argv[i + 1][0] != '-') scenario.devboard_elf = argv[++i];
    } else if (arg == "--core-mhz") {
      const char* v = value("N");
      double n = 0;
      if (v == nullptr || !qrsim::parse_real(v, n) || n < 1 || n > 1000 || n != std::floor(n)) {
        return usage_error("--core-mhz needs a whole number of MHz, 1 to 1000");
      }
      scenario.devboard_core_mhz = static_cast<uint32_t>(n);
    } else if (arg == "--no-noise") {
      scenario.sensor_noise = false;
    } else if (arg == "--scenario" || arg == "--sweep") {
      const char* v = value("NAME");
      if (v == nullptr) return usage_error(arg + " needs a scenario name or file");
      command = arg == "--scenario" ? Command::scenario : Command::sweep;
      std::string error;
      if (!qrsim::find_scenario(v, script, error)) return scenario_error(error);
    } else if (arg == "--no-draw") {
      draw = false;
    } else if (arg == "--seeds") {
      const char* v = value("N");
      double n = 0;
      if (v == nullptr || !qrsim::parse_real(v, n) || n < 1 || n != std::floor(n) || n > 100000) {
        return usage_error("--seeds needs a whole number >= 1");
      }
      seeds = static_cast<int>(n);
    } else if (arg == "--seconds") {
      const char* v = value("S");
      if (v == nullptr || !qrsim::parse_real(v, seconds) || seconds <= 0)
        return usage_error("--seconds needs a time > 0");
    } else if (arg == "--seed") {
      const char* v = value("N");
      char* end = nullptr;
      if (v == nullptr) return usage_error("--seed needs a number");
      seed = std::strtoull(v, &end, 0);
      if (*end != '\0') return usage_error("--seed needs a number");
    } else if (arg == "--vehicle") {
      const char* v = value("FILE");
      if (v == nullptr) return usage_error("--vehicle needs a file");
      std::string error;
      sim::VehicleParams loaded;
      if (!sim::load_vehicle_file(v, loaded, error)) return usage_error(error);
      vehicle = loaded;
      vehicle_name = v;
    } else if (arg == "--trace") {
      const char* v = value("FILE");
      if (v == nullptr) return usage_error("--trace needs a file");
      scenario.trace_path = v;
    } else if (arg == "--record") {
      const char* v = value("FILE");
      if (v == nullptr) return usage_error("--record needs a file");
      scenario.record_path = v;
    } else if (arg == "--replay" || arg == "--out") {
      const char* v = value("FILE");
      if (v == nullptr) return usage_error(arg + " needs a file");
      (arg == "--replay" ? replay_in : replay_out) = v;
      if (arg == "--replay") command = Command::replay;
    } else if (arg == "--double") {
      replay_options.arithmetic = qr::host::ReplayArithmetic::reference_double;
    } else if (arg == "--rc") {
      const char* v = value("crsf");
      if (v == nullptr || std::strcmp(v, "crsf") != 0) return usage_error("--rc knows one receiver: crsf");
      scenario.radio = true;
    } else if (arg == "--esc") {
      const char* v = value("dshot");
      if (v == nullptr || std::strcmp(v, "dshot") != 0) return usage_error("--esc knows one protocol: dshot");
      scenario.dshot = true;
    } else if (arg == "--param") {
      const char* v = value("NAME=VALUE");
      const char* eq = v == nullptr ? nullptr : std::strchr(v, '=');
      if (eq == nullptr) return usage_error("--param needs NAME=VALUE");
      wire::ParamId id{};
      int32_t raw = 0;
      const std::string problem = qrsim::parameter_from_text(std::string(v, eq), eq + 1, id, raw);
      if (!problem.empty()) return usage_error("--param: " + problem);
      scenario.parameters.emplace_back(id, raw);
      replay_options.parameters.set(static_cast<uint8_t>(id), raw);
    } else {
      return usage_error("unknown argument " + arg);
    }
  }

  if (scenario.devboard_core_mhz != 0 && scenario.devboard_elf.empty()) {
    return usage_error("--core-mhz goes with --devboard");
  }
  switch (command) {
    case Command::none:
    case Command::help:
      std::printf(kUsage, static_cast<unsigned>(qr::kControlHz), QR_DEVBOARD_ELF);
      return command == Command::help ? 0 : 2;
    case Command::replay:
      if (replay_out.empty()) return usage_error("--replay needs --out OUT.csv");
      return qr::host::run_replay(replay_in.c_str(), replay_out.c_str(), std::cerr, replay_options);
    case Command::list:
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
    case Command::soak: {
      qrsim::SoakOptions soak;
      if (seconds > 0) soak.seconds = seconds;
      soak.seed = seed;
      return qrsim::run_soak(soak) ? 0 : 1;
    }
    case Command::serve:
      if (scenario.radio && !scenario.devboard_elf.empty())
        return usage_error("--rc crsf flies the host firmware only: the devboard's sensor link carries no radio");
      serve.radio = scenario.radio;
      serve.dshot = scenario.dshot;
      serve.stdio = stdio;
      serve.status = status;
      serve.truth_fd = truth_fd;
      serve.seconds = seconds;
      serve.seed = seed;
      serve.devboard_elf = scenario.devboard_elf;
      serve.devboard_core_mhz = scenario.devboard_core_mhz;
      serve.vehicle = vehicle ? *vehicle : sim::default_vehicle();
      return qrsim::serve(serve);
    case Command::sweep: {
      if (!scenario.devboard_elf.empty()) return usage_error("--devboard goes with --scenario");
      scenario.seconds = seconds;
      scenario.seed = seed;
      scenario.vehicle = vehicle;
      scenario.vehicle_name = vehicle_name;
      bool all = true;
      for (const qrsim::BandSummary& b : qrsim::run_sweep(script, scenario, seeds, draw, stdout))
        all = all && b.passed == b.of;
      return all ? 0 : 1;
    }
    case Command::scenario: {
      scenario.seconds = seconds;
      scenario.seed = seed;
      scenario.vehicle = vehicle;
      scenario.vehicle_name = vehicle_name;
      const qrsim::ScenarioResult result = qrsim::run_scenario(script, scenario);
      if (json) {
        std::printf("%s\n", qrsim::to_json(result).c_str());
      } else {
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
        for (const qrsim::CheckResult& c : result.checks)
          std::printf("  [%s] %s\n", c.pass ? "ok" : "FAIL", c.band.c_str());
      }
      return result.pass ? 0 : 1;
    }
  }
  return 2;
}
