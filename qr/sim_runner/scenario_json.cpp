#include <cmath>
#include <cstdio>

#include <qr/sim_runner/scenario.hpp>

namespace qrsim {
namespace {

// A JSON string: quotes and backslashes escaped, control characters dropped.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

}  // namespace

std::string to_json(const ScenarioResult& r) {
  std::string out = "{\"scenario\": " + quoted(r.scenario) + ", \"vehicle\": " + quoted(r.vehicle);
  // The host build is the default and says nothing; the devboard's binary says so.
  if (r.firmware != "host") out += ", \"firmware\": " + quoted(r.firmware);
  char buffer[64];
  for (const Figure& f : r.figures) {
    if (f.name == "final_mode") {
      out += ", \"final_mode\": " + quoted(r.final_mode);
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
  if (!r.error.empty()) out += ", \"error\": " + quoted(r.error);
  if (!r.known_failure.empty()) out += ", \"known_failure\": " + quoted(r.known_failure);
  if (!r.notes.empty()) {
    out += ", \"notes\": [";
    for (size_t i = 0; i < r.notes.size(); ++i) out += (i == 0 ? "" : ", ") + quoted(r.notes[i]);
    out += "]";
  }
  out += ", \"bands\": {";
  for (size_t i = 0; i < r.checks.size(); ++i) {
    out += (i == 0 ? "" : ", ") + quoted(r.checks[i].band) + ": " + (r.checks[i].pass ? "true" : "false");
  }
  out += std::string("}, \"pass\": ") + (r.pass ? "true" : "false") + "}";
  return out;
}

}  // namespace qrsim
