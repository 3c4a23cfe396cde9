#include <pc/core/command_line.hpp>

#include <charconv>

#include <pc/core/battery_gauge.hpp>

namespace qrterm {
namespace {

struct OptionSpec {
  const char* name;
  const char* value;  // null: a flag without a value
  const char* help;
  // Takes the value; returns an error message, or an empty string.
  std::string (*set)(Options& options, const std::string& value);
};

constexpr uint32_t kBaudRates[] = {9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};

constexpr OptionSpec kOptions[] = {
    {"--port", "PATH", "fly the QR on this serial device or pty instead of the simulator",
     [](Options& o, const std::string& v) { return o.port = v, std::string(); }},
    {"--baud", "N", "serial line speed (default 115200)",
     [](Options& o, const std::string& v) {
       const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), o.baud);
       if (error != std::errc{} || end != v.data() + v.size() || o.baud == 0)
         return "--baud: \"" + v + "\" is not a number";
       // The rates a serial port takes (pc/platform/serial_port.cpp): another is a bad option, not a
       // port that fails to open.
       for (uint32_t rate : kBaudRates) {
         if (o.baud == rate) return std::string();
       }
       return "--baud: " + v +
              " is not a serial line speed (9600, 19200, 38400, 57600, 115200, 230400, 460800, "
              "921600)";
     }},
    {"--sim", "PATH", "the simulator to start (default: ../qr/qrsim next to qrterm)",
     [](Options& o, const std::string& v) { return o.sim = v, std::string(); }},
    {"--sim-arg", "ARG", "pass ARG to the simulator (repeatable)",
     [](Options& o, const std::string& v) { return o.sim_arguments.push_back(v), std::string(); }},
    {"--joystick", "PATH", "joystick device (default /dev/input/js0)",
     [](Options& o, const std::string& v) { return o.joystick = v, std::string(); }},
    {"--no-joystick", nullptr, "fly with the keyboard only",
     [](Options& o, const std::string&) { return o.no_joystick = true, std::string(); }},
    {"--joystick-map", "FILE", "axes, deadband, abort button (default ./qrterm-joystick.txt)",
     [](Options& o, const std::string& v) { return o.joystick_map = v, std::string(); }},
    {"--joystick-wizard", nullptr, "find the joystick's axes and fire button step by step, write --joystick-map",
     [](Options& o, const std::string&) { return o.joystick_wizard = true, std::string(); }},
    {"--params", "FILE", "parameter file, read at start, written at exit (default ./qrterm-params.txt)",
     [](Options& o, const std::string& v) { return o.params = v, std::string(); }},
    {"--log-dir", "DIR", "where the session's files go (default ./logs/<date>-<time>)",
     [](Options& o, const std::string& v) { return o.log_dir = v, std::string(); }},
    {"--keep-logs", "N", "log folders kept in ./logs, the oldest removed at start (default 20; 0 keeps all)",
     [](Options& o, const std::string& v) {
       const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), o.keep_logs);
       if (error != std::errc{} || end != v.data() + v.size() || o.keep_logs > 100000)
         return "--keep-logs: \"" + v + "\" is not a number of folders (0 keeps every one)";
       return std::string();
     }},
    {"--cells", "N", "LiPo cells of the QR's pack, 1..8 (default: counted from its voltage at connection)",
     [](Options& o, const std::string& v) {
       const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), o.battery_cells);
       if (error != std::errc{} || end != v.data() + v.size() || o.battery_cells < 1 || o.battery_cells > kMaxCells)
         return "--cells: \"" + v + "\" is not a number of cells, 1.." + std::to_string(kMaxCells);
       return std::string();
     }},
    {"--help", nullptr, "this text", [](Options& o, const std::string&) { return o.help = true, std::string(); }},
};

}  // namespace

ParsedCommandLine parse_command_line(const std::vector<std::string>& arguments) {
  ParsedCommandLine out;
  for (size_t i = 0; i < arguments.size(); ++i) {
    std::string name = arguments[i];
    std::string value;
    bool has_value = false;
    const size_t equals = name.find('=');
    if (name.rfind("--", 0) == 0 && equals != std::string::npos) {  // --port=/dev/ttyUSB0
      value = name.substr(equals + 1);
      name.resize(equals);
      has_value = true;
    }
    const OptionSpec* spec = nullptr;
    for (const OptionSpec& candidate : kOptions) {
      if (name == candidate.name || (name == "-h" && std::string(candidate.name) == "--help")) spec = &candidate;
    }
    if (spec == nullptr) {
      out.error = "unknown option \"" + arguments[i] + "\" (qrterm --help lists them)";
      return out;
    }
    if (spec->value != nullptr && !has_value) {
      if (i + 1 >= arguments.size()) {
        out.error = name + " needs a value: " + name + " " + spec->value;
        return out;
      }
      value = arguments[++i];
    } else if (spec->value == nullptr && has_value) {
      out.error = name + " takes no value";
      return out;
    }
    out.error = spec->set(out.options, value);
    if (!out.error.empty()) return out;
  }
  if (out.options.port && !out.options.sim.empty())
    out.error = "--port and --sim exclude each other: fly a QR or the simulator";
  if (out.options.joystick_wizard && out.options.no_joystick)
    out.error = "--joystick-wizard and --no-joystick exclude each other: the wizard maps a joystick";
  return out;
}

std::string usage_text() {
  std::string text =
      "usage: qrterm [options]\n"
      "The ground console of the QR: keyboard and joystick in, telemetry and logs out.\n"
      "Without --port it starts the simulator and flies it.\n\noptions:\n";
  for (const OptionSpec& spec : kOptions) {
    std::string left = std::string("  ") + spec.name + (spec.value != nullptr ? std::string(" ") + spec.value : "");
    left.resize(24, ' ');
    text += left + spec.help + "\n";
  }
  text += "\nKeys: h or ? in the console. Manual: docs/console.md\n";
  return text;
}

}  // namespace qrterm
