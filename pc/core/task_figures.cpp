#include <pc/core/task_figures.hpp>

#include <cstdarg>
#include <cstdio>

#include <common/task_names.hpp>

namespace qrterm {
namespace {

// The QR's scheduler tasks as the wire numbers them in telemetry_task (common/task_names.hpp).
std::string task_name(uint8_t number) {
  const char* name = wire::task_name(number);
  return name != nullptr ? name : "task " + std::to_string(number);
}

// The unit of the task figures, said in the header.
constexpr const char* kHeaders[] = {
    "QR task   cycles: mean    max overruns  (the board's cycle counter: instructions on the devboard)",
    "QR task       ns: mean    max overruns  (the host's ns: the simulator's board)",
    "QR task   instr.: mean    max overruns  (RV32 instructions: the devboard in the simulator)",
};

std::string printed(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printed(const char* format, ...) {
  char line[160];
  va_list values;
  va_start(values, format);
  std::vsnprintf(line, sizeof line, format, values);
  va_end(values);
  return line;
}

// The whole tick on the devboard, and what it needs of a core at the control rate.
std::vector<std::string> tick_lines(const DevboardFigures& d, uint32_t control_hz) {
  const double period_us = 1e6 / control_hz;
  std::vector<std::string> lines{
      printed("  %-14s %6.0f %6u           (the whole tick)", "tick", d.tick_instr_mean, d.tick_instr_max)};
  if (d.core_mhz > 0) {
    lines.push_back(printed("  at %u MHz: the tick %.0f us mean, %.0f us at most, of %.0f us", d.core_mhz,
                            d.tick_instr_mean / d.core_mhz, d.tick_instr_max / static_cast<double>(d.core_mhz),
                            period_us));
  } else {
    lines.push_back(printed("  no clock (qrsim --core-mhz N): %.1f MHz runs the longest tick in %.0f us",
                            d.tick_instr_max / period_us, period_us));
  }
  return lines;
}

}  // namespace

std::vector<std::string> task_figure_lines(const std::map<uint8_t, wire::TelemetryTask>& tasks, FiguresFrom from,
                                           const std::optional<DevboardFigures>& devboard, uint32_t control_hz) {
  std::vector<std::string> lines{kHeaders[static_cast<size_t>(from)]};
  for (const auto& [number, task] : tasks) {
    lines.push_back(printed("  %-14s %6u %6u %8u", task_name(number).c_str(), task.mean, task.max, task.overruns));
  }
  if (from == FiguresFrom::simulator_devboard && devboard && control_hz > 0) {
    for (std::string& line : tick_lines(*devboard, control_hz)) lines.push_back(std::move(line));
  }
  return lines;
}

CpuRow cpu_row(const wire::TelemetrySystem& s, FiguresFrom from, const std::optional<DevboardFigures>& devboard) {
  // The simulator's host build: its board's clock is simulated time, which stands still while a
  // tick runs (load and loop time 0), and its misses count the host's scheduling.
  if (from == FiguresFrom::simulator_host) return {"cpu n/a  loop n/a  misses n/a (simulator)", false};
  if (from == FiguresFrom::simulator_devboard) {
    if (!devboard) return {"cpu n/a  (devboard: its figures come each second)", false};
    // With a core clock the board's time runs on by its instructions: its own load, longest tick
    // and misses are a core of that speed's.
    if (devboard->core_mhz > 0) {
      return {printed("cpu %.1f %%  loop %u us  misses %u at %u MHz", s.cpu_load / 10.0, s.loop_time_us,
                      s.deadline_misses, devboard->core_mhz)};
    }
    return {printed("cpu %.0f instr/tick, max %u (no clock)", devboard->tick_instr_mean, devboard->tick_instr_max)};
  }
  if (s.loop_time_us == 0) return {"cpu n/a  loop n/a (the board has no clock)", false};
  return {printed("cpu %5.1f %%  loop %5u us  misses %u", s.cpu_load / 10.0, s.loop_time_us, s.deadline_misses)};
}

}  // namespace qrterm
