// A vehicle file in the autotune's terms (tune/axis_model.hpp): what the fit should find on each
// axis, derived from the file's physics, so qrsim --autotune prints the truth beside the model it
// fitted (issue 34: within 15 %). The derivation, with the default vehicle's numbers, is in
// vehicle_axes.cpp.
#pragma once

#include <sim/vehicle.hpp>
#include <tune/axis_model.hpp>

namespace qrsim {

struct VehicleAxes {
  tune::AxisModel roll, pitch, yaw;
  double thrust_unit_n = 0;  // one thrust unit of the mixer (engine_mixer.hpp) at hover's voltage
  double hover_engine = 0;   // the engine command that hovers
};

VehicleAxes axes_of(const sim::VehicleParams& v);

}  // namespace qrsim
