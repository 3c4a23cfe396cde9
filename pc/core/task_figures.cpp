#include <pc/core/task_figures.hpp>

#include <cstdio>

#include <common/task_names.hpp>

namespace qrterm {
namespace {

// The QR's scheduler tasks as the wire numbers them in telemetry_task (common/task_names.hpp).
std::string task_name(uint8_t number) {
  const char* name = wire::task_name(number);
  return name != nullptr ? name : "task " + std::to_string(number);
}

}  // namespace

std::vector<std::string> task_figure_lines(const std::map<uint8_t, wire::TelemetryTask>& tasks, bool simulator) {
  std::vector<std::string> lines{simulator
                                     ? "QR task     ns: mean    max overruns  (the host's ns: the simulator's board)"
                                     : "QR task   cycles: mean    max overruns  (instructions on the devboard)"};
  for (const auto& [number, task] : tasks) {
    char line[64];
    std::snprintf(line, sizeof line, "  %-14s %6u %6u %8u", task_name(number).c_str(), task.mean, task.max,
                  task.overruns);
    lines.emplace_back(line);
  }
  return lines;
}

}  // namespace qrterm
