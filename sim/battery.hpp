// A lithium-polymer pack: open-circuit voltage from the state of charge, sag across the internal
// resistance under load. The firmware's battery watchdog (10.5 V panic, docs/safety.md) must see
// the sag a climb causes, or it is tested against a battery that never dips.
#pragma once

#include <sim/vehicle.hpp>

namespace sim {

// Resting voltage of one LiPo cell at state of charge `soc` (0..1).
double lipo_cell_volts(double soc);

class Battery {
 public:
  explicit Battery(const VehicleParams& vehicle);

  double soc() const { return soc_; }
  double open_circuit_volts() const;
  double terminal_volts(double current_a) const;
  // Takes `current_a` for `seconds` out of the pack.
  void drain(double current_a, double seconds);

 private:
  double cells_;
  double capacity_as_;  // ampere-seconds
  double resistance_;
  double soc_;
};

}  // namespace sim
