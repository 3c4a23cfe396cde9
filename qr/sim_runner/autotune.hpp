// qrsim --autotune (issue 34): the identification flight flown headless (the built-in scenario
// `autotune`: mode autotune from a steady hover), each axis' model fitted to what the firmware
// asked of its mixer and the rate its loops saw (tune/axis_fit.hpp), the gains designed from the
// models (tune/loop_design.hpp), and one JSON line {"autotune": {...}}: the models beside the
// vehicle file's truth, the parameters as --param takes them, and the margins and step response
// of the gains flown and of the gains designed.
#pragma once

#include <cstdio>

#include <qr/sim_runner/scenario.hpp>

namespace qrsim {

// The process's exit status: 0 with the line printed, 1 when the flight or a fit failed (said on
// stderr, and the line's "error").
int run_autotune(const RunOptions& options, FILE* out);

}  // namespace qrsim
