// Fuzz target: arbitrary text as a replay recording (qr/host/replay.cpp, docs/replay.md), read and
// run through the flight chain. Beyond what ASan and UBSan catch: a refused input says so in one
// line naming the input and a line of it; an accepted one writes the output header first.
#include <stddef.h>
#include <stdint.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include <qr/host/replay.hpp>

#include "fuzz_checks.hpp"

using fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::ostringstream out;
  std::ostringstream errors;
  const int status = qr::host::run_replay(in, "fuzz.csv", out, errors);
  require(status == 0 || status == 1);
  if (status == 1) {
    const std::string said = errors.str();
    require(said.rfind("replay: fuzz.csv", 0) == 0 && !said.empty() && said.back() == '\n');
    return 0;
  }
  require(out.str().rfind(qr::host::replay_output_header(), 0) == 0);
  return 0;
}
