#include <sim/battery.hpp>

#include <algorithm>
#include <iterator>

namespace sim {
namespace {

// Resting cell voltage against state of charge: the curve RC battery vendors and chargers publish
// for LiPo cells (4.20 V full, a flat 3.7-3.9 V middle, a knee below 10 %). Linear between points.
struct CellPoint {
  double soc;
  double volts;
};
constexpr CellPoint kCellCurve[] = {
    {0.00, 3.27}, {0.05, 3.61}, {0.10, 3.69}, {0.20, 3.73}, {0.30, 3.77}, {0.40, 3.80},
    {0.50, 3.84}, {0.60, 3.87}, {0.70, 3.95}, {0.80, 4.02}, {0.90, 4.11}, {1.00, 4.20},
};

}  // namespace

double lipo_cell_volts(double soc) {
  soc = std::clamp(soc, 0.0, 1.0);
  for (size_t i = 1; i < std::size(kCellCurve); ++i) {
    const CellPoint& hi = kCellCurve[i];
    if (soc <= hi.soc) {
      const CellPoint& lo = kCellCurve[i - 1];
      return lo.volts + (hi.volts - lo.volts) * (soc - lo.soc) / (hi.soc - lo.soc);
    }
  }
  return kCellCurve[std::size(kCellCurve) - 1].volts;
}

Battery::Battery(const VehicleParams& vehicle)
    : cells_(vehicle.battery_cells), capacity_as_(vehicle.battery_capacity_mah * 3.6),
      resistance_(vehicle.battery_resistance_ohm), soc_(vehicle.battery_initial_soc) {}

double Battery::open_circuit_volts() const { return cells_ * lipo_cell_volts(soc_); }

double Battery::terminal_volts(double current_a) const {
  return std::max(0.0, open_circuit_volts() - current_a * resistance_);
}

void Battery::drain(double current_a, double seconds) {
  soc_ = std::max(0.0, soc_ - current_a * seconds / capacity_as_);
}

}  // namespace sim
