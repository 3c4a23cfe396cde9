// A robustness sweep: one scenario flown over N seeds, each run on a vehicle drawn around the
// scenario's (mass, inertia, motor lag, vibration and sensor noise together, from kSweepRanges)
// with its own sensor seed. Prints one JSON line per run and a summary line per band.
#pragma once

#include <stdint.h>

#include <cstdio>

#include <qr/sim_runner/scenario.hpp>

namespace qrsim {

struct SweepRange {
  const char* what;
  double low, high;  // a multiplier, drawn uniformly
};

// Documented in docs/simulator.md ("Robustness sweep").
inline constexpr SweepRange kSweepRanges[] = {
    {"mass", 0.8, 1.2},       {"inertia", 0.7, 1.3},
    {"motor_tau", 0.67, 1.5},  // both time constants: 30 ms spin-up -> 20 .. 45 ms
    {"vibration", 0.5, 2.0},  {"noise", 0.5, 2.0},
};

// The draw of run `seed`: from a generator of its own, so the same seed draws the same vehicle
// whatever else the run does.
VehicleDraw draw_vehicle(uint64_t seed);

struct BandSummary {
  std::string band;
  int passed = 0;
  int of = 0;
  double worst = 0;  // NaN when a run did not measure the figure
};

// Runs seeds options.seed .. options.seed + seeds - 1, each on its drawn vehicle (draw false:
// on the scenario's own, the seeds alone); prints each run's JSON line (with "sweep": the
// scenario) and then one summary line per band to `out`. Returns the summaries.
std::vector<BandSummary> run_sweep(const ScenarioScript& script, const RunOptions& options, int seeds, bool draw,
                                   FILE* out);

}  // namespace qrsim
