// The plant: a 6-DOF rigid body with four rotors, a battery and the ground, integrated at a
// fixed step with classical Runge-Kutta (RK4).
//
// Why RK4 at a fixed step of 125 µs (8 kHz) by default: the fastest dynamics in the model are
// the ground contact (about 240 rad/s in rotation on the feet) and the vibration is computed
// analytically, not integrated; at ω·dt = 0.03 RK4 is far inside its stability region, and its
// fourth-order accuracy keeps a torque-free spin's energy and angular momentum to better than
// 1e-9 per second, where semi-implicit Euler would drift in the momentum direction of an
// asymmetric body. Four evaluations per step cost a few µs; the step divides both control
// periods (1000 and 2000 µs), so kicks fall on step boundaries and the control rate never
// changes the physics.
#pragma once

#include <stdint.h>

#include <array>

#include <sim/battery.hpp>
#include <sim/ground_contact.hpp>
#include <sim/quaternion.hpp>
#include <sim/rotor.hpp>
#include <sim/vehicle.hpp>

namespace sim {

inline constexpr double kGravity = 9.80665;  // m/s², standard gravity

struct PlantState {
  Vec3 position;                                  // world frame (north, east, down), m; the ground is z = 0
  Vec3 velocity;                                  // world frame, m/s
  Quat attitude;                                  // body -> world
  Vec3 rate;                                      // body rates p, q, r, rad/s
  std::array<double, kRotorCount> rotor_speed{};  // rad/s, each in its own spin direction
};

class Quadrotor {
 public:
  explicit Quadrotor(const VehicleParams& vehicle);

  // Engine outputs 0..1000 (engine order of docs/conventions.md), held until changed; the vehicle's
  // wiring says which rotor each output drives.
  void set_engines(const std::array<uint16_t, kRotorCount>& commands);
  // External loads (a gust, a push), held until changed: a torque in body axes and a force in
  // world axes, both acting on the centre of mass.
  void set_disturbance(const Vec3& torque_body, const Vec3& force_world);
  // The air's velocity in world axes (a steady wind), held until changed: the airframe and rotor
  // drag act on the velocity relative to it. Still air by default.
  void set_wind(const Vec3& wind_world);

  void step(double dt);

  const PlantState& state() const { return state_; }
  void set_state(const PlantState& state) { state_ = state; }
  // Level, at rest, standing on its feet at (north, east).
  void rest_on_ground(double north = 0, double east = 0);

  // What an accelerometer at the centre of mass feels now: every force but gravity, over the
  // mass, in body axes. At rest and level that is the ground's push, (0, 0, -g).
  Vec3 specific_force() const;
  double rotor_phase(int rotor) const { return phase_[static_cast<size_t>(rotor)]; }
  // Where each rotor sits and which way it turns (rotor order: front, right, back, left).
  const std::array<RotorGeometry, kRotorCount>& rotors() const { return rotors_; }
  // Output `output`'s ESC turns its motor the other way (a DShot ESC's spin direction 2): the
  // rotor that output drives turns opposite to the way the vehicle's wiring makes it turn.
  void set_output_reversed(int output, bool reversed);

  const Battery& battery() const { return battery_; }
  double battery_volts() const { return volts_; }
  double battery_current() const { return current_; }
  // How far the lowest contact point is below the ground (negative: airborne).
  double deepest_contact() const;
  // True when no contact point can reach the ground within the next `seconds`, whatever the
  // attitude does meanwhile: the centre is higher than the farthest point's reach plus the
  // distance it can sink. In that time the contact term is zero and the plant has no stiff part.
  bool clear_of_ground_for(double seconds) const;
  const VehicleParams& vehicle() const { return vehicle_; }
  // Per rotor: output i's command drives rotor wiring.rotor_of_output[i].
  const std::array<uint16_t, kRotorCount>& engines() const { return commands_; }

  // The engine command (all four equal) that settles the rotors at `speed`, with the battery
  // sagging under the current that speed draws.
  double steady_command(double speed) const;
  // The engine command that holds the vehicle's weight at the battery's present charge: what a
  // pilot learns to hold the lift stick at.
  double hover_command() const { return steady_command(vehicle_.hover_speed()); }

 private:
  struct Derivative {
    Vec3 velocity;
    Vec3 acceleration;
    Quat attitude_rate;
    Vec3 angular_acceleration;
    std::array<double, kRotorCount> rotor_acceleration{};
  };

  // The state's derivative; with `specific_force`, also what an accelerometer feels (body axes).
  Derivative evaluate(const PlantState& s, Vec3* specific_force = nullptr) const;
  double current_draw(const std::array<double, kRotorCount>& speeds, double volts) const;

  VehicleParams vehicle_;
  std::array<RotorGeometry, kRotorCount> rotors_;
  GroundContact ground_;
  Battery battery_;
  PlantState state_;
  std::array<uint16_t, kRotorCount> commands_{};
  std::array<double, kRotorCount> target_speed_{};
  std::array<double, kRotorCount> phase_{};
  Vec3 disturbance_torque_;
  Vec3 disturbance_force_;
  Vec3 wind_;
  double volts_;
  double current_ = 0;
};

}  // namespace sim
