// The QR's task figures as the log prints them (the b key): per scheduler task its mean and
// largest cost a tick, and its overruns, in the board's own unit.
#pragma once

#include <stdint.h>

#include <map>
#include <string>
#include <vector>

#include <common/telemetry.hpp>

namespace qrterm {

// A header, then a line per task. The unit is the board's cycle counter: instructions on the
// devboard, the host's ns on the simulator's board (`simulator`).
std::vector<std::string> task_figure_lines(const std::map<uint8_t, wire::TelemetryTask>& tasks, bool simulator);

}  // namespace qrterm
