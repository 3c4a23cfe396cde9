// The QR's CPU figures as the console shows them: the task table the b key prints (per scheduler
// task its mean and largest cost a run, and its overruns, in the board's own unit) and the CPU row
// of the cockpit. What the figures are depends on what flies: a board's own clock and cycle
// counter; the simulator's host build, whose counter is the host's ns and whose clock stands still
// while a tick runs; or the devboard in the simulator, whose counter is RV32 instructions and whose
// clock runs only when the simulator gives its core a speed (--core-mhz).
#pragma once

#include <stdint.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <common/telemetry.hpp>

namespace qrterm {

enum class FiguresFrom : uint8_t {
  board,               // a QR on --port (a real one, or the devboard on its own): its clock and counter
  simulator_host,      // qrsim's host build: ns of the host, no load
  simulator_devboard,  // qrsim --devboard: RV32 instructions; a load only with a core clock
};

// The simulator's line about the devboard it flies (docs/simulator.md section 5: "devboard ...").
struct DevboardFigures {
  uint32_t core_mhz = 0;  // 0: no clock (time stands still while a tick runs)
  double tick_instr_mean = 0;
  uint32_t tick_instr_max = 0;
  uint32_t ticks = 0;
};

// A header, then a line per task; on the devboard, the whole tick and what it means for a core at
// the control rate `control_hz`.
std::vector<std::string> task_figure_lines(const std::map<uint8_t, wire::TelemetryTask>& tasks, FiguresFrom from,
                                           const std::optional<DevboardFigures>& devboard, uint32_t control_hz);

// The cockpit's CPU row after "battery ...": "cpu 17.1 %  loop 501 us  misses 0 at 16 MHz".
// `figures`: false when what it says is no measurement (drawn dim).
struct CpuRow {
  std::string text;
  bool figures = true;
};
CpuRow cpu_row(const wire::TelemetrySystem& system, FiguresFrom from, const std::optional<DevboardFigures>& devboard);

}  // namespace qrterm
