// qrterm's command line, as a table of options: parsing, defaults and the --help text come from
// the same rows.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <optional>
#include <string>
#include <vector>

#include <pc/core/log_retention.hpp>

namespace qrterm {

struct Options {
  std::optional<std::string> port;  // fly a QR on this serial device; absent: start the simulator
  uint32_t baud = 115200;
  std::string sim;                         // empty: <folder of qrterm>/../qr/qrsim
  std::vector<std::string> sim_arguments;  // passed to the simulator after --serve
  std::string joystick = "/dev/input/js0";
  bool no_joystick = false;
  std::string joystick_map = "./qrterm-joystick.txt";
  bool joystick_wizard = false;  // find the joystick's map step by step and write it; flies nothing
  std::string params = "./qrterm-params.txt";
  std::string log_dir;                 // empty: ./logs/<date>-<time>
  size_t keep_logs = kLogFoldersKept;  // session folders kept in ./logs, the oldest removed at start; 0: all
  int battery_cells = 0;               // 0: counted from the voltage at connection
  bool help = false;
};

struct ParsedCommandLine {
  Options options;
  std::string error;  // empty when the command line was good
};

ParsedCommandLine parse_command_line(const std::vector<std::string>& arguments);

std::string usage_text();

}  // namespace qrterm
