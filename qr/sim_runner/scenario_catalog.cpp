// Where a scenario comes from: a built-in by name, else a file by path.
#include <filesystem>

#include <qr/sim_runner/builtin_scenarios.hpp>
#include <qr/sim_runner/scenario.hpp>

namespace qrsim {

bool find_scenario(const std::string& name_or_path, ScenarioScript& out, std::string& error) {
  for (const BuiltinScenario& b : builtin_scenarios()) {
    if (name_or_path != b.name) continue;
    if (!parse_scenario(b.text, b.name, std::string("built-in ") + b.name, out, error)) return false;
    if (!out.vehicle_file.empty()) {
      // A vehicle file is found relative to its scenario file, which a built-in does not have.
      error = "built-in " + name_or_path + ": a built-in scenario cannot name a vehicle file";
      return false;
    }
    return true;
  }
  if (std::filesystem::is_regular_file(name_or_path)) return load_scenario_file(name_or_path, out, error);
  error = "no scenario " + name_or_path + " (not a built-in, see qrsim --list, nor a file)";
  return false;
}

}  // namespace qrsim
