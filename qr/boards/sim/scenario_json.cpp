#include <qr/boards/sim/scenario.hpp>

#include <cmath>
#include <cstdio>

namespace qrsim {

std::string to_json(const ScenarioResult& r) {
  std::string out = "{\"scenario\": \"" + r.scenario + "\", \"vehicle\": \"" + r.vehicle + "\"";
  char buffer[64];
  for (const Figure& f : r.figures) {
    if (f.name == "final_mode") {
      out += ", \"final_mode\": \"" + r.final_mode + "\"";
      continue;
    }
    if (std::isnan(f.value) || std::isinf(f.value)) {
      std::snprintf(buffer, sizeof buffer, "null");
    } else if (f.value == std::floor(f.value) && std::abs(f.value) < 1e15) {
      std::snprintf(buffer, sizeof buffer, "%.0f", f.value);
    } else {
      std::snprintf(buffer, sizeof buffer, "%.4g", f.value);
    }
    out += ", \"" + f.name + "\": " + buffer;
  }
  if (!r.error.empty()) out += ", \"error\": \"" + r.error + "\"";
  out += ", \"bands\": {";
  for (size_t i = 0; i < r.checks.size(); ++i) {
    out += (i == 0 ? "\"" : ", \"") + r.checks[i].band + "\": " + (r.checks[i].pass ? "true" : "false");
  }
  out += std::string("}, \"pass\": ") + (r.pass ? "true" : "false") + "}";
  return out;
}

}  // namespace qrsim
