// qrterm: the QR's ground console. Everything that can fail for a reason the pilot can fix (a bad
// option, a bad file, no joystick, no simulator, a busy port) is checked before the screen opens,
// so its message lands on an ordinary terminal; after that the terminal is always given back.
#include <errno.h>
#include <sys/stat.h>
#include <unistd.h>

#include <clocale>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pc/core/command_line.hpp>
#include <pc/core/console.hpp>
#include <pc/core/joystick_map.hpp>
#include <pc/core/param_file.hpp>
#include <pc/core/session_settings.hpp>
#include <pc/platform/clock.hpp>
#include <pc/platform/joystick_device.hpp>
#include <pc/platform/log_folder.hpp>
#include <pc/platform/serial_port.hpp>
#include <pc/platform/signals.hpp>
#include <pc/platform/sim_process.hpp>
#include <pc/ui/cockpit.hpp>
#include <pc/ui/joystick_wizard_screen.hpp>
#include <pc/ui/main_loop.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {
namespace {

constexpr int kUsageError = 2;                  // bad command line or bad file: nothing was started
constexpr int kStartError = 1;                  // the QR, the simulator or a file could not be reached
constexpr uint32_t kSimStartTimeoutMs = 10000;  // a sanitizer build of the simulator starts slowly
constexpr uint32_t kJoystickSettleMs = 200;     // the driver reports every axis right after open

struct Failure {
  int status;
  std::string message;
};

std::string folder_of_this_program() {
  char path[4096];
  const ssize_t n = ::readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) return ".";
  std::string self(path, static_cast<size_t>(n));
  return self.substr(0, self.rfind('/'));
}

struct StartedParams {
  wire::ParameterValues values;
  std::string note;        // for the log: where they came from
  bool from_file = false;  // false: no file, the defaults
};

StartedParams load_params(const std::string& path) {
  // A folder would read as nothing and fail only at the save, after the flight.
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    throw Failure{kUsageError, path + " is a folder: --params names a file (qrterm-params.txt is the default)"};
  std::string text;
  if (!read_file(path, text)) {
    if (errno != ENOENT) throw Failure{kUsageError, "cannot read " + path + ": " + std::strerror(errno)};
    return {wire::ParameterValues{}, "no parameter file " + path + ": defaults; it is written at exit"};
  }
  ParamFileContents contents = parse_param_file(text);
  if (!contents.errors.empty()) {
    throw Failure{kUsageError, describe(path, contents.errors) +
                                   "qrterm: fix the parameter file (or move it away to start from the defaults)"};
  }
  return {contents.values, "parameters from " + path, true};
}

JoystickMap load_joystick_map(const std::string& path) {
  std::string text;
  if (!read_file(path, text)) {
    if (errno != ENOENT) throw Failure{kUsageError, "cannot read " + path + ": " + std::strerror(errno)};
    return JoystickMap{};
  }
  JoystickMapFile file = parse_joystick_map(text);
  if (!file.errors.empty()) throw Failure{kUsageError, describe(path, file.errors) + "qrterm: fix the joystick map"};
  return file.map;
}

// Waits briefly for the driver's report of every axis, so the start-up check sees the stick.
void settle(JoystickDevice& joystick) {
  const uint32_t start = monotonic_ms();
  while (monotonic_ms() - start < kJoystickSettleMs && !joystick.reader().position_known()) {
    joystick.read();
    ::usleep(5000);
  }
}

// A joystick, unless --no-joystick; it must be there when asked for.
std::unique_ptr<JoystickDevice> open_joystick(const Options& options) {
  if (options.no_joystick) return nullptr;
  const JoystickMap map = load_joystick_map(options.joystick_map);
  std::unique_ptr<JoystickDevice> joystick;
  try {
    joystick = std::make_unique<JoystickDevice>(options.joystick, map);
  } catch (const JoystickError& e) {
    // An error, not a warning: the fire button is the pilot's abort, and a pilot who expects it
    // must not find out in the air that it is not there.
    throw Failure{
        kUsageError,
        std::string(e.what()) +
            "\n  plug one in, name another with --joystick PATH, or fly with the keyboard only: --no-joystick"};
  }
  settle(*joystick);
  return joystick;
}

// The QR's serial line: a port (--port), or the simulator started here and its pty.
struct QrLine {
  std::unique_ptr<SimProcess> sim;  // null on a port
  std::unique_ptr<SerialPort> serial;
  std::string source;  // for the title and the log: "sim /dev/pts/3", "/dev/ttyUSB0 115200"
};

QrLine open_qr_line(const Options& options) {
  QrLine line;
  std::string serial_path;
  if (options.port) {
    serial_path = *options.port;
    line.source = serial_path + " " + std::to_string(options.baud);
  } else {
    const std::string program = options.sim.empty() ? folder_of_this_program() + "/../qr/qrsim" : options.sim;
    std::vector<std::string> arguments{"--serve", "--truth-fd", std::to_string(SimProcess::kTruthFd)};
    arguments.insert(arguments.end(), options.sim_arguments.begin(), options.sim_arguments.end());
    try {
      line.sim = std::make_unique<SimProcess>(program, arguments, kSimStartTimeoutMs);
    } catch (const SimError& e) {
      throw Failure{kStartError, e.what()};
    }
    serial_path = line.sim->serial_path();
    line.source = "sim " + serial_path;
  }
  try {
    line.serial = std::make_unique<SerialPort>(serial_path, options.baud);
  } catch (const SerialError& e) {
    throw Failure{kStartError, e.what()};
  }
  return line;
}

// The session's files in the log folder, open for the whole session; rx.hex is started again
// when full (ConsoleFiles::restart_rx_hex).
class SessionFiles {
 public:
  explicit SessionFiles(std::string folder) : folder_(std::move(folder)) {
    // Made once the QR is reachable: a start that failed leaves no empty folder behind.
    try {
      make_folders(folder_);
    } catch (const LogFolderError& e) {
      throw Failure{kStartError, e.what()};
    }
    console_ = open_in(folder_, "console.log");
    hex_ = open_in(folder_, "rx.hex");
    telemetry_ = open_in(folder_, "telemetry.csv");
    if (!console_ || !hex_ || !telemetry_) throw Failure{kStartError, "cannot write files in " + folder_};
  }

  SessionFiles(const SessionFiles&) = delete;
  SessionFiles& operator=(const SessionFiles&) = delete;

  const std::string& folder() const { return folder_; }
  std::ostream* console_log() const { return console_.get(); }

  ConsoleFiles for_console() {
    ConsoleFiles files;
    files.rx_hex = hex_.get();
    files.restart_rx_hex = [this]() -> std::ostream* {
      hex_.reset();
      hex_ = start_again_in(folder_, "rx.hex", kRxHexPrevious);
      return hex_.get();
    };
    files.telemetry_csv = telemetry_.get();
    const std::string folder = folder_;
    files.open = [folder](const std::string& name) -> std::unique_ptr<std::ostream> { return open_in(folder, name); };
    files.rename = [folder](const std::string& from, const std::string& to) { return rename_in(folder, from, to); };
    return files;
  }

 private:
  std::string folder_;
  std::unique_ptr<std::ofstream> console_;
  std::unique_ptr<std::ofstream> hex_;
  std::unique_ptr<std::ofstream> telemetry_;
};

// The first lines of the log: where the console flies, where it writes, and whether the joystick
// is neutral, so a refused flight mode is no surprise.
void note_start(Console& console, const QrLine& line, const std::string& log_folder, const StartedParams& params,
                JoystickDevice* joystick, const Options& options) {
  console.note(Severity::info, "qrterm on " + line.source +
                                   (line.sim ? " (simulator pid " + std::to_string(line.sim->pid()) + ")" : ""));
  if (line.sim) {
    for (const std::string& text : line.sim->early_output()) console.note(Severity::info, "sim: " + text);
  }
  console.note(Severity::info, "logs in " + log_folder);
  console.note(Severity::info, params.note);
  if (joystick) {
    JoystickReader& reader = joystick->reader();
    console.joystick_moved(reader.sticks(), reader.position_known(), monotonic_ms());
    PilotControls check;
    check.set_joystick(reader.sticks());
    const std::string not_neutral = !reader.position_known() ? "the joystick has not reported its position"
                                                             : check.not_neutral_reason();
    if (!not_neutral.empty())
      console.note(Severity::warning, not_neutral + ": flight modes are refused until it is neutral");
    else console.note(Severity::info, "joystick " + options.joystick + " neutral");
  } else {
    console.note(Severity::info, "no joystick: keyboard only");
  }
  console.note(Severity::info, "h or ? shows the keys");
  // Last, so they are the newest lines on the screen at start: saved values this session cannot use.
  const SessionKind session{line.sim != nullptr, simulator_has_radio(options.sim_arguments)};
  for (const std::string& trap : settings_that_trap(params.values, session)) console.note(Severity::warning, trap);
}

// After the screen is closed, on the ordinary terminal: how the session ended, the parameters
// saved for the next start (which changed, and how back), and where the logs are.
void say_goodbye(const ConsoleLog& log, const Console& console, const StartedParams& params, const Options& options,
                 const std::string& log_folder) {
  // Gains changed by keys (perhaps a stray one) and settings (pilot) load at the next start: say
  // which, and how to undo each.
  const std::vector<std::string> changes = undo_lines(params.values, console.params());
  const std::string saved = write_file_atomically(options.params, format_param_file(console.params()));
  // The last few lines of the log say how the session ended.
  const auto& lines = log.lines();
  for (size_t i = lines.size() > 3 ? lines.size() - 3 : 0; i < lines.size(); ++i) {
    std::fprintf(stderr, "qrterm: %s\n", lines[i].text.c_str());
  }
  if (!saved.empty()) {
    std::fprintf(stderr, "qrterm: %s\n", saved.c_str());
  } else if (changes.empty()) {
    std::fprintf(stderr, "qrterm: parameters unchanged, in %s\n", options.params.c_str());
  } else {
    std::fprintf(stderr, "qrterm: parameters changed in this session, saved to %s for the next start:\n",
                 options.params.c_str());
    for (const std::string& change : changes) std::fprintf(stderr, "  %s\n", change.c_str());
    std::fprintf(stderr,
                 "  (undo: that line in %s, or the value on the parameter screen: Tab Tab, Enter; ! there sets "
                 "every default)\n",
                 options.params.c_str());
  }
  std::fprintf(stderr, "qrterm: logs in %s\n", log_folder.c_str());
}

// qrterm --joystick-wizard: the wizard's screen instead of the cockpit; no QR, no simulator, no
// log folder. The map it writes is what the next start reads.
int run_wizard(const Options& options) {
  struct stat info {};
  if (::stat(options.joystick_map.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    throw Failure{kUsageError, options.joystick_map + " is a folder: --joystick-map names a file"};
  std::unique_ptr<RawJoystick> joystick;
  try {
    joystick = std::make_unique<RawJoystick>(options.joystick);
  } catch (const JoystickError& e) {
    throw Failure{kUsageError, std::string(e.what()) + "\n  plug one in, or name it with --joystick PATH"};
  }
  install_signal_handlers();
  WizardOutcome outcome;
  {
    Terminal terminal;
    outcome = run_joystick_wizard({joystick->fd(), options.joystick, options.joystick_map}, terminal);
  }
  std::fprintf(stderr, "qrterm: %s\n", outcome.message.c_str());
  if (outcome.status == 0 && options.joystick_map != Options{}.joystick_map)
    std::fprintf(stderr, "  fly with it: qrterm --joystick-map %s\n", options.joystick_map.c_str());
  return outcome.status;
}

int run(int argc, char** argv) {
  const ParsedCommandLine parsed = parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed.error.empty()) throw Failure{kUsageError, parsed.error};
  const Options& options = parsed.options;
  if (options.help) {
    std::fputs(usage_text().c_str(), stdout);
    return 0;
  }
  // The cockpit and the wizard are screens and read single keys: nothing here runs without one.
  if (!::isatty(STDIN_FILENO) || !::isatty(STDOUT_FILENO)) {
    throw Failure{kUsageError, std::string(::isatty(STDIN_FILENO) ? "standard output" : "standard input") +
                                   " is not a terminal: run qrterm in a terminal window (over ssh: ssh -t, or in "
                                   "tmux); it has no mode without a screen, only qrterm --help"};
  }
  if (options.joystick_wizard) return run_wizard(options);

  const StartedParams params = load_params(options.params);
  std::unique_ptr<JoystickDevice> joystick = open_joystick(options);
  QrLine line = open_qr_line(options);
  SessionFiles files(options.log_dir.empty() ? default_log_folder() : options.log_dir);
  // Folders of earlier starts beyond --keep-logs go; a folder named with --log-dir is the pilot's.
  std::string prune_failed;
  const size_t pruned = options.log_dir.empty()
                            ? remove_old_log_folders(files.folder(), options.keep_logs, prune_failed)
                            : 0;

  ConsoleLog log(500, files.console_log());
  Console::Setup setup;
  setup.params = params.values;
  setup.joystick = joystick != nullptr;
  setup.first_seq = static_cast<uint8_t>(::time(nullptr));
  setup.simulator = line.sim != nullptr;
  setup.devboard = line.sim != nullptr && simulator_flies_devboard(options.sim_arguments);
  setup.params_file = options.params;
  setup.params_file_exists = params.from_file;
  setup.battery_cells = options.battery_cells;
  Console console(log, files.for_console(), setup, monotonic_ms());
  note_start(console, line, files.folder(), params, joystick.get(), options);
  if (pruned > 0)
    console.note(Severity::info, "removed the " + std::to_string(pruned) + " oldest log folders: the newest " +
                                     std::to_string(options.keep_logs) + " are kept (--keep-logs N, 0 keeps all)");
  if (!prune_failed.empty()) console.note(Severity::warning, "could not remove an old log folder: " + prune_failed);

  install_signal_handlers();
  bool confirmed = false;
  {
    Terminal terminal;
    Cockpit cockpit({line.source, files.folder(), joystick ? options.joystick : std::string()});
    Session session{console, *line.serial, line.sim.get(), joystick.get(), terminal, cockpit};
    run_main_loop(session);
    confirmed = console.exit_confirmed();
    const std::string latency = cockpit.latency_summary();
    if (!latency.empty()) console.note(Severity::info, latency);
  }
  if (line.sim) line.sim->stop(confirmed ? 1000 : 0);
  say_goodbye(log, console, params, options, files.folder());
  return 0;
}

}  // namespace
}  // namespace qrterm

int main(int argc, char** argv) {
  try {
    return qrterm::run(argc, argv);
  } catch (const qrterm::Failure& failure) {
    std::fprintf(stderr, "qrterm: %s\n", failure.message.c_str());
    return failure.status;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "qrterm: %s\n", e.what());
    return 1;
  }
}
