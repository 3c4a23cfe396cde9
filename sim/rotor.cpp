#include <sim/rotor.hpp>

#include <algorithm>

namespace sim {

std::array<RotorGeometry, kRotorCount> rotor_geometry(const VehicleParams& v) {
  const double l = v.arm_m;
  const double up = -v.hub_height_m;  // body z points down
  return {{
      {{l, 0, up}, +1},   // 0 front, clockwise
      {{0, l, up}, -1},   // 1 right, counter-clockwise
      {{-l, 0, up}, +1},  // 2 back, clockwise
      {{0, -l, up}, -1},  // 3 left, counter-clockwise
  }};
}

double motor_target_speed(const VehicleParams& v, double command, double volts) {
  return std::clamp(command, 0.0, 1000.0) / 1000.0 * v.speed_per_volt() * std::max(0.0, volts);
}

double motor_acceleration(const VehicleParams& v, double speed, double target) {
  const double tau = target > speed ? v.motor_tau_up_s : v.motor_tau_down_s;
  return (target - speed) / tau;
}

Wrench rotor_wrench(const VehicleParams& v, const RotorGeometry& rotor, double speed, double speed_rate,
                    const Vec3& body_rate, const Vec3& hub_air_velocity) {
  const double w2 = speed * speed;
  const Vec3 inplane_drag{-v.rotor_drag_coeff * speed * hub_air_velocity.x,
                          -v.rotor_drag_coeff * speed * hub_air_velocity.y, 0};
  Wrench w = at_point(rotor.hub, Vec3{0, 0, -v.thrust_coeff * w2} + inplane_drag);
  const Vec3 momentum{0, 0, rotor.spin * v.rotor_inertia * speed};
  w.torque += Vec3{0, 0, -rotor.spin * (v.torque_coeff * w2 + v.rotor_inertia * speed_rate)};
  w.torque -= cross(body_rate, momentum);
  return w;
}

double rotor_shaft_power(const VehicleParams& v, double speed) { return v.torque_coeff * speed * speed * speed; }

}  // namespace sim
