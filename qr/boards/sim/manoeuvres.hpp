// What the pilot does in each kind of manoeuvre, one control period at a time: a table with one
// row per Manoeuvre (scenario.hpp), each row a function over the same step.
#pragma once

#include <common/parameter_table.hpp>
#include <qr/boards/sim/pilot.hpp>
#include <qr/boards/sim/scenario.hpp>
#include <sim/quadrotor.hpp>

namespace qrsim {

struct ManoeuvreStep {
  const ScenarioSpec& spec;
  double since;    // s since the manoeuvre began
  bool first;      // the manoeuvre's first control period
  Sticks& sticks;  // in: the hover sticks (lift held by the pilot); out: what the pilot holds
  Pilot& pilot;
  sim::Quadrotor& plant;
  const wire::ParameterValues& parameters;  // the QR's, as the pilot set them
};

void fly_manoeuvre(ManoeuvreStep& step);

}  // namespace qrsim
