// One rotor on its motor: where it sits, which way it spins (the vehicle's wiring may reverse it), how its speed follows the engine
// command, and what it does to the airframe. Layout and signs from docs/conventions.md: engines
// 0 front, 1 right, 2 back, 3 left; front and back spin clockwise seen from above (their angular
// velocity points along body +z, down), left and right counter-clockwise.
#pragma once

#include <algorithm>
#include <array>

#include <sim/vehicle.hpp>
#include <sim/wrench.hpp>

namespace sim {

inline constexpr int kRotorCount = 4;

struct RotorGeometry {
  Vec3 hub;         // body frame, from the centre of mass
  double spin;      // +1 clockwise seen from above (angular velocity along +z), -1 counter-clockwise
  double lift = 1;  // thrust per k_f w^2, upwards: 1, or for a motor turning backwards a share down
};

std::array<RotorGeometry, kRotorCount> rotor_geometry(const VehicleParams& vehicle);

// The rotor with its motor turning the other way (two phase wires swapped, or an ESC's spin
// direction 2), its propeller as it was: the spin opposite, and a blade meeting the air backwards
// pushes down at kReversedThrustShare (sim/wiring.hpp); turned back, it lifts as made.
inline RotorGeometry turned_the_other_way(RotorGeometry rotor) {
  rotor.spin = -rotor.spin;
  rotor.lift = rotor.lift > 0 ? -kReversedThrustShare : 1.0;
  return rotor;
}

// The speed the motor settles at for `command` (0..1000) with `volts` across the ESC: the
// command is a share of full speed, full speed is proportional to the voltage (docs/conventions.md:
// commands are proportional to rotor speed).
inline double motor_target_speed(const VehicleParams& v, double command, double volts) {
  return std::clamp(command, 0.0, 1000.0) / 1000.0 * v.speed_per_volt() * std::max(0.0, volts);
}

// First-order lag toward the target, with its own time constant each way (vehicle file). Down is
// the ESC braking the motor as multirotor ESC firmware does by default (BLHeli's "damped light",
// regenerative braking), not the prop coasting: drag alone decelerates at k_m w^2 / J_r, about
// 880 rad/s^2 at this vehicle's hover speed, while a 50 ms lag takes 8000 rad/s^2 from hover to
// stop.
inline double motor_acceleration(const VehicleParams& v, double speed, double target) {
  const double tau = target > speed ? v.motor_tau_up_s : v.motor_tau_down_s;
  return (target - speed) / tau;
}

// Everything one rotor does to the airframe at rotor speed `speed` (rad/s, >= 0), changing at
// `speed_rate`, with the airframe turning at `body_rate` and the hub moving through the air at
// `hub_air_velocity` (body frame):
//   thrust k_f ω² along -z at the hub;
//   drag reaction torque -spin k_m ω² about z (a clockwise rotor pushes the body anticlockwise);
//   reaction to the motor accelerating the rotor, -spin J dω/dt about z;
//   gyroscopic torque of the rotor's angular momentum, -body_rate x (spin J ω z);
//   in-plane rotor drag -c ω v_inplane at the hub (induced drag and blade flapping).
// Inline, as the two above: the plant calls them four times per evaluation, 16 times a step.
inline Wrench rotor_wrench(const VehicleParams& v, const RotorGeometry& rotor, double speed, double speed_rate,
                           const Vec3& body_rate, const Vec3& hub_air_velocity) {
  const double w2 = speed * speed;
  const Vec3 inplane_drag{-v.rotor_drag_coeff * speed * hub_air_velocity.x,
                          -v.rotor_drag_coeff * speed * hub_air_velocity.y, 0};
  Wrench w = at_point(rotor.hub, Vec3{0, 0, -rotor.lift * v.thrust_coeff * w2} + inplane_drag);
  const Vec3 momentum{0, 0, rotor.spin * v.rotor_inertia * speed};
  w.torque += Vec3{0, 0, -rotor.spin * (v.torque_coeff * w2 + v.rotor_inertia * speed_rate)};
  w.torque -= cross(body_rate, momentum);
  return w;
}

// Shaft power the motor delivers to the rotor in steady rotation, W.
inline double rotor_shaft_power(const VehicleParams& v, double speed) { return v.torque_coeff * speed * speed * speed; }

}  // namespace sim
