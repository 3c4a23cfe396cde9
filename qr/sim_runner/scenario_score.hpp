// A flight's record into figures (scenario_figures.hpp names them all), and the figures against
// the scenario's bands. Every band is judged on the simulator's truth; the estimate's step
// figures are printed beside with an _est suffix, and the estimator is scored on its own.
#pragma once

#include <vector>

#include <qr/sim_runner/flight_record.hpp>
#include <qr/sim_runner/scenario.hpp>

namespace qrsim {

// How long after the set-point moves a step must have settled (the step target, settle < 0.8 s):
// from then on the held part begins, in which the error is judged sample by sample.
inline constexpr double kSettleAllowanceS = 0.8;

// The attitude, step, yaw, push, panic, battery and touchdown figures.
void add_flight_figures(const ScenarioScript& script, const FlightRecord& rec, const EndState& end,
                        std::vector<Figure>& figures);

// Each band with its verdict; pass when every band holds and the flight got to its manoeuvre.
void judge(const ScenarioScript& script, ScenarioResult& result);

}  // namespace qrsim
