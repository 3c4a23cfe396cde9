// The flight computer's battery voltage reading: the pack's terminal voltage through a divider
// and an ADC, with noise and the ADC's step.
#pragma once

#include <stdint.h>

#include <sim/random.hpp>
#include <sim/vehicle.hpp>

namespace sim {

class BatterySensor {
 public:
  BatterySensor(const VehicleParams& vehicle, const Random& random)
      : random_(random), noise_mv_(vehicle.battery_sense_noise_mv), lsb_mv_(vehicle.battery_sense_lsb_mv) {}

  uint16_t read_mv(double volts);

 private:
  Random random_;
  double noise_mv_;
  double lsb_mv_;
};

}  // namespace sim
