#include <sim/battery_sensor.hpp>

#include <algorithm>
#include <cmath>

namespace sim {

uint16_t BatterySensor::read_mv(double volts) {
  const double mv = volts * 1000 + noise_mv_ * random_.normal();
  const double steps = std::floor(std::max(0.0, mv) / lsb_mv_);
  return static_cast<uint16_t>(std::min(65535.0, steps * lsb_mv_));
}

}  // namespace sim
