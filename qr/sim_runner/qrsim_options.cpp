// qrsim's command line: a table of its options, each with the reader of its value. The messages
// are the ones tests and scripts look for: keep them word for word.
#include <qr/sim_runner/qrsim_options.hpp>

#include <fcntl.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <common/parameter_table.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/sim_runner/text_fields.hpp>

namespace qrsim {
namespace {

constexpr const char* kUsage = R"(usage:
  qrsim --serve [--stdio] [--seed N] [--vehicle FILE] [--seconds S] [--status] [--truth-fd N]
        [--devboard [ELF] [--core-mhz N] | --rc crsf] [--esc dshot] [--sensors drivers|direct]
  qrsim --scenario NAME|FILE [--seconds S] [--seed N] [--vehicle FILE] [--param NAME=VALUE]...
        [--no-noise] [--trace FILE.csv] [--record FILE.csv] [--json] [--devboard [ELF] [--core-mhz N]]
        [--rc crsf] [--esc dshot] [--sensors drivers|direct]
  qrsim --sweep NAME|FILE [--seeds N] [--no-draw] [--seed N] [--seconds S] [--vehicle FILE]
        [--param NAME=VALUE]... [--rc crsf] [--esc dshot] [--sensors drivers|direct]
  qrsim --soak [--seconds S] [--seed N]
  qrsim --autotune [--vehicle FILE] [--seed N] [--param NAME=VALUE]... [--no-noise] [--sensors drivers|direct]
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
  --autotune       fly the identification flight (mode autotune from a hover, the built-in
                   scenario autotune), fit each axis' model to what the firmware logged, design
                   the gains from it and print one JSON line {"autotune": {"model", "truth",
                   "params", "margins", ...}}; the params go back as --param NAME=VALUE
                   (docs/signal-chain.md "Autotune"); exit status 1 when a fit failed
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
  --sensors WHICH  scenario, sweep, serve: drivers (the default, but for serve): the MPU-6050
                   and the MS5611 are register-level chips on the board's I2C bus (400 kHz, in
                   simulated time), read by the firmware's own drivers, a sample one tick old
                   (with --devboard the bus is carried over the sensor link); direct (serve's
                   default): the board hands the firmware the plant's sample (docs/drivers.md)
  --replay IN      run a recording through the flight chain tick by tick (test mode) and write
                   every tick's estimates, controller outputs and engines to --out OUT
                   (docs/replay.md); --double runs the double-precision reference chain
  --list           the built-in scenarios (sim/scenarios/*.txt, compiled in) and what they do

)";

// The arguments in order; an option's value is the argument after it.
class Arguments {
 public:
  Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}

  // Moves to the next option; false when none is left.
  bool next() {
    if (++at_ >= argc_) return false;
    option_ = argv_[at_];
    return true;
  }
  const std::string& option() const { return option_; }

  // The option's value, taken; null when the line ends before it.
  const char* value() { return at_ + 1 < argc_ ? argv_[++at_] : nullptr; }

  // A value the option may go without: the next argument unless it is another option.
  const char* optional_value() { return at_ + 1 < argc_ && argv_[at_ + 1][0] != '-' ? argv_[++at_] : nullptr; }

 private:
  int argc_;
  char** argv_;
  int at_ = 0;  // argv[0] is the program
  std::string option_;
};

bool refuse(const std::string& message) {
  usage_error(message);
  return false;
}

// A scenario that does not read: --help does not describe the file, the document does.
bool refuse_scenario(const std::string& message) {
  std::fprintf(stderr, "qrsim: %s (the scenario file format: %s)\n", message.c_str(), kScenarioFormatDoc);
  return false;
}

// A whole number in min .. max, written as any number parse_real reads ("1e3" is 1000).
bool whole_number(const char* text, double min, double max, double& n) {
  return text != nullptr && parse_real(text, n) && n >= min && n <= max && n == std::floor(n);
}

template <Command kCommand>
bool command(Arguments&, CommandLine& line) {
  line.command = kCommand;
  return true;
}

bool stdio(Arguments&, CommandLine& line) {
  line.stdio = true;
  return true;
}

bool status(Arguments&, CommandLine& line) {
  line.status = true;
  return true;
}

bool json(Arguments&, CommandLine& line) {
  line.json = true;
  return true;
}

bool no_noise(Arguments&, CommandLine& line) {
  line.flight.sensor_noise = false;
  return true;
}

bool no_draw(Arguments&, CommandLine& line) {
  line.draw = false;
  return true;
}

bool reference_double(Arguments&, CommandLine& line) {
  line.replay.arithmetic = qr::host::ReplayArithmetic::reference_double;
  return true;
}

bool truth_fd(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  double n = 0;
  if (!whole_number(v, 0, 65535, n)) return refuse("--truth-fd needs a descriptor number");
  line.truth_fd = static_cast<int>(n);
  if (fcntl(line.truth_fd, F_GETFD) < 0) return refuse("--truth-fd " + std::string(v) + " is not an open descriptor");
  return true;
}

bool devboard(Arguments& args, CommandLine& line) {
  const char* elf = args.optional_value();
  line.flight.devboard_elf = elf != nullptr ? elf : QR_DEVBOARD_ELF;
  return true;
}

bool core_mhz(Arguments& args, CommandLine& line) {
  double n = 0;
  if (!whole_number(args.value(), 1, 1000, n)) return refuse("--core-mhz needs a whole number of MHz, 1 to 1000");
  line.flight.devboard_core_mhz = static_cast<uint32_t>(n);
  return true;
}

// --scenario and --sweep: the scenario is read at once, so a bad file is said before anything flies.
template <Command kCommand>
bool scenario(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  if (v == nullptr) return refuse(args.option() + " needs a scenario name or file");
  line.command = kCommand;
  std::string error;
  return find_scenario(v, line.script, error) || refuse_scenario(error);
}

bool seeds(Arguments& args, CommandLine& line) {
  double n = 0;
  if (!whole_number(args.value(), 1, 100000, n)) return refuse("--seeds needs a whole number >= 1");
  line.seeds = static_cast<int>(n);
  return true;
}

bool seconds(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  if (v == nullptr || !parse_real(v, line.seconds) || line.seconds <= 0) return refuse("--seconds needs a time > 0");
  return true;
}

// In any base strtoull reads with base 0 (0x2a, 052, 42).
bool seed(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  if (v == nullptr) return refuse("--seed needs a number");
  char* end = nullptr;
  line.seed = std::strtoull(v, &end, 0);
  return *end == '\0' || refuse("--seed needs a number");
}

bool vehicle(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  if (v == nullptr) return refuse("--vehicle needs a file");
  std::string error;
  sim::VehicleParams loaded;
  if (!sim::load_vehicle_file(v, loaded, error)) return refuse(error);
  line.vehicle = loaded;
  line.vehicle_name = v;
  return true;
}

// An option whose value is a file name, stored in `path`.
bool file(Arguments& args, std::string& path) {
  const char* v = args.value();
  if (v == nullptr) return refuse(args.option() + " needs a file");
  path = v;
  return true;
}

bool trace(Arguments& args, CommandLine& line) { return file(args, line.flight.trace_path); }
bool record(Arguments& args, CommandLine& line) { return file(args, line.flight.record_path); }
bool replay_out(Arguments& args, CommandLine& line) { return file(args, line.replay_out); }

bool replay(Arguments& args, CommandLine& line) {
  if (!file(args, line.replay_in)) return false;
  line.command = Command::replay;
  return true;
}

bool radio(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  if (v == nullptr || std::strcmp(v, "crsf") != 0) return refuse("--rc knows one receiver: crsf");
  line.flight.radio = true;
  return true;
}

bool esc(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  if (v == nullptr || std::strcmp(v, "dshot") != 0) return refuse("--esc knows one protocol: dshot");
  line.flight.dshot = true;
  return true;
}

bool sensors(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  if (v == nullptr || (std::strcmp(v, "drivers") != 0 && std::strcmp(v, "direct") != 0))
    return refuse("--sensors is drivers or direct");
  line.flight.sensor_drivers = std::strcmp(v, "drivers") == 0;
  line.sensors_given = true;
  return true;
}

// A parameter goes to whichever flies: the scenario's pilot uploads it, the replay's chain runs with it.
bool parameter(Arguments& args, CommandLine& line) {
  const char* v = args.value();
  const char* eq = v == nullptr ? nullptr : std::strchr(v, '=');
  if (eq == nullptr) return refuse("--param needs NAME=VALUE");
  wire::ParamId id{};
  int32_t raw = 0;
  const std::string problem = parameter_from_text(std::string(v, eq), eq + 1, id, raw);
  if (!problem.empty()) return refuse("--param: " + problem);
  line.flight.parameters.emplace_back(id, raw);
  line.replay.parameters.set(static_cast<uint8_t>(id), raw);
  return true;
}

struct Option {
  const char* name;
  bool (*read)(Arguments& args, CommandLine& line);  // false: it has said what is wrong
};

constexpr Option kOptions[] = {
    {"--help", command<Command::help>},
    {"-h", command<Command::help>},
    {"--list", command<Command::list>},
    {"--soak", command<Command::soak>},
    {"--autotune", command<Command::autotune>},
    {"--serve", command<Command::serve>},
    {"--stdio", stdio},
    {"--status", status},
    {"--truth-fd", truth_fd},
    {"--json", json},
    {"--devboard", devboard},
    {"--core-mhz", core_mhz},
    {"--no-noise", no_noise},
    {"--scenario", scenario<Command::scenario>},
    {"--sweep", scenario<Command::sweep>},
    {"--no-draw", no_draw},
    {"--seeds", seeds},
    {"--seconds", seconds},
    {"--seed", seed},
    {"--vehicle", vehicle},
    {"--trace", trace},
    {"--record", record},
    {"--replay", replay},
    {"--out", replay_out},
    {"--double", reference_double},
    {"--rc", radio},
    {"--esc", esc},
    {"--sensors", sensors},
    {"--param", parameter},
};

const Option* find_option(const std::string& name) {
  for (const Option& option : kOptions) {
    if (name == option.name) return &option;
  }
  return nullptr;
}

}  // namespace

int usage_error(const std::string& message) {
  std::fprintf(stderr, "qrsim: %s (see qrsim --help)\n", message.c_str());
  return 2;
}

void print_usage() { std::printf(kUsage, static_cast<unsigned>(qr::kControlHz), QR_DEVBOARD_ELF); }

bool read_command_line(int argc, char** argv, CommandLine& line) {
  Arguments args(argc, argv);
  while (args.next()) {
    const Option* option = find_option(args.option());
    if (option == nullptr) return refuse("unknown argument " + args.option());
    if (!option->read(args, line)) return false;
  }
  if (line.flight.devboard_core_mhz != 0 && line.flight.devboard_elf.empty()) {
    return refuse("--core-mhz goes with --devboard");
  }
  return true;
}

}  // namespace qrsim
