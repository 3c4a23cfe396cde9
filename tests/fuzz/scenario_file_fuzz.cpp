// Fuzz target: arbitrary text into the scenario file parser (parse_scenario touches no file).
// Checks, beyond what ASan and UBSan catch: a refused text says where (the origin, then a line
// number within the text, or the origin alone for what is missing at the end); an accepted one
// is consistent: events in time order inside the window, at least one band, every band on a
// known figure, every number finite (a stuck bus's duration may be "for ever"), every hand turn
// within its limits and after the last one.
#include <stddef.h>
#include <stdint.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include <qr/sim_runner/scenario_figures.hpp>
#include <qr/sim_runner/scenario_script.hpp>

#include "fuzz_checks.hpp"

using fuzz::require;
using fuzz::line_count;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  qrsim::ScenarioScript script;
  std::string error;
  if (!qrsim::parse_scenario(text, "fuzz", "fuzz.txt", script, error)) {
    require(error.rfind("fuzz.txt:", 0) == 0);
    if (error.rfind("fuzz.txt: ", 0) != 0) {  // not the whole file's problem: a line's
      char* end = nullptr;
      const long line = std::strtol(error.c_str() + 9, &end, 10);
      require(line >= 1 && static_cast<size_t>(line) <= line_count(text) && *end == ':');
    }
    return 0;
  }
  require(std::isfinite(script.seconds) && script.seconds > 0);
  require(!script.bands.empty());
  for (const qrsim::Band& b : script.bands) require(qrsim::is_figure(b.figure) && std::isfinite(b.limit));
  double previous = 0, turned_until = 0;
  for (const qrsim::Event& e : script.events) {
    require(std::isfinite(e.at_s) && e.at_s >= previous && e.at_s < script.seconds);
    // A duration is finite, but a stuck bus's "for ever" (infinity).
    require(std::isfinite(e.value) && !std::isnan(e.duration_s) && e.duration_s >= 0);
    require(std::isfinite(e.duration_s) || e.action == qrsim::Action::sda_stuck);
    previous = e.at_s;
    if (e.action != qrsim::Action::turn) continue;
    require(sim::hand_turn_problem(e.turn).empty() && e.at_s >= turned_until);
    turned_until = e.at_s + e.turn.seconds;
  }
  return 0;
}
