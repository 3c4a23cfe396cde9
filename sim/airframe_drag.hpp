// Drag of the centre body and arms, quadratic in air speed, each body axis with its own Cd·A.
#pragma once

#include <sim/vec3.hpp>
#include <sim/vehicle.hpp>

namespace sim {

inline constexpr double kAirDensity = 1.225;  // kg/m³, ISA sea level

// Force on the airframe (body axes) moving through still air at `air_velocity` (body axes).
inline Vec3 airframe_drag(const VehicleParams& v, const Vec3& air_velocity) {
  const Vec3& a = v.body_drag_area_m2;
  const double q = 0.5 * kAirDensity;
  return {-q * a.x * std::abs(air_velocity.x) * air_velocity.x, -q * a.y * std::abs(air_velocity.y) * air_velocity.y,
          -q * a.z * std::abs(air_velocity.z) * air_velocity.z};
}

}  // namespace sim
