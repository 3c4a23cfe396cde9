#include <sim/quadrotor.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <sim/airframe_drag.hpp>

namespace sim {
namespace {

PlantState advance(const PlantState& s, const auto& d, double h) {
  PlantState out;
  out.position = s.position + h * d.velocity;
  out.velocity = s.velocity + h * d.acceleration;
  out.attitude = {s.attitude.w + h * d.attitude_rate.w, s.attitude.x + h * d.attitude_rate.x,
                  s.attitude.y + h * d.attitude_rate.y, s.attitude.z + h * d.attitude_rate.z};
  out.rate = s.rate + h * d.angular_acceleration;
  for (size_t i = 0; i < kRotorCount; ++i) out.rotor_speed[i] = s.rotor_speed[i] + h * d.rotor_acceleration[i];
  return out;
}

}  // namespace

Quadrotor::Quadrotor(const VehicleParams& vehicle)
    : vehicle_(vehicle), rotors_(rotor_geometry(vehicle)), ground_(vehicle), battery_(vehicle),
      volts_(battery_.open_circuit_volts()) {
  current_ = vehicle_.avionics_current_a;
  volts_ = battery_.terminal_volts(current_);
  rest_on_ground();
}

void Quadrotor::set_engines(const std::array<uint16_t, kRotorCount>& commands) {
  // The wiring: output i drives the rotor it is soldered to.
  for (size_t i = 0; i < kRotorCount; ++i) {
    commands_[static_cast<size_t>(vehicle_.wiring.rotor_of_output[i])] = std::min<uint16_t>(commands[i], 1000);
  }
}

void Quadrotor::set_output_reversed(int output, bool reversed) {
  const auto rotor = static_cast<size_t>(vehicle_.wiring.rotor_of_output[static_cast<size_t>(output)]);
  const RotorGeometry wired = rotor_geometry(vehicle_)[rotor];
  rotors_[rotor] = reversed ? turned_the_other_way(wired) : wired;
}

void Quadrotor::set_disturbance(const Vec3& torque_body, const Vec3& force_world) {
  disturbance_torque_ = torque_body;
  disturbance_force_ = force_world;
}

void Quadrotor::set_wind(const Vec3& wind_world) { wind_ = wind_world; }

void Quadrotor::rest_on_ground(double north, double east) {
  PlantState s;
  // Standing on four feet, each carrying a quarter of the weight.
  const double sink = vehicle_.mass_kg * kGravity / (4 * vehicle_.contact_stiffness);
  s.position = {north, east, -vehicle_.foot_depth_m + sink};
  s.rotor_speed = state_.rotor_speed;
  state_ = s;
}

Quadrotor::Derivative Quadrotor::evaluate(const PlantState& s, Vec3* specific_force) const {
  const VehicleParams& v = vehicle_;
  Derivative d;
  // The vehicle's velocity through the air, which moves at the wind's velocity.
  const Vec3 air_velocity = rotate_inverse(s.attitude, s.velocity - wind_);

  Wrench body = {airframe_drag(v, air_velocity), {}};
  for (size_t i = 0; i < kRotorCount; ++i) {
    d.rotor_acceleration[i] = motor_acceleration(v, s.rotor_speed[i], target_speed_[i]);
    const Vec3 hub_velocity = air_velocity + cross(s.rate, rotors_[i].hub);
    body += rotor_wrench(v, rotors_[i], s.rotor_speed[i], d.rotor_acceleration[i], s.rate, hub_velocity);
  }
  body += ground_.at(s.position, s.velocity, s.attitude, s.rate).wrench;
  body.torque += disturbance_torque_;

  const Vec3 force_world = rotate(s.attitude, body.force) + disturbance_force_;
  // Only the accelerometer wants it, once a kick; the four RK4 stages of a step do not.
  if (specific_force != nullptr) *specific_force = rotate_inverse(s.attitude, force_world) * (1 / v.mass_kg);
  d.velocity = s.velocity;
  d.acceleration = force_world * (1 / v.mass_kg) + Vec3{0, 0, kGravity};
  d.attitude_rate = sim::derivative(s.attitude, s.rate);
  // Euler's equations; the rotors' angular momentum is in rotor_wrench's gyroscopic term.
  const Vec3& inertia = v.inertia_kgm2;
  const Vec3 torque = body.torque - cross(s.rate, scale(inertia, s.rate));
  d.angular_acceleration = {torque.x / inertia.x, torque.y / inertia.y, torque.z / inertia.z};
  return d;
}

double Quadrotor::current_draw(const std::array<double, kRotorCount>& speeds, double volts) const {
  double shaft = 0;
  for (double w : speeds) shaft += rotor_shaft_power(vehicle_, w);
  return vehicle_.avionics_current_a + shaft / (vehicle_.powertrain_efficiency * std::max(volts, 1.0));
}

void Quadrotor::step(double dt) {
  // The ESCs see the terminal voltage of the previous step: the algebraic loop between current
  // and voltage is broken by one step (125 µs), far below the motors' lag.
  for (size_t i = 0; i < kRotorCount; ++i) target_speed_[i] = motor_target_speed(vehicle_, commands_[i], volts_);

  const std::array<double, kRotorCount> speed_before = state_.rotor_speed;
  const Derivative k1 = evaluate(state_);
  const Derivative k2 = evaluate(advance(state_, k1, dt / 2));
  const Derivative k3 = evaluate(advance(state_, k2, dt / 2));
  const Derivative k4 = evaluate(advance(state_, k3, dt));
  Derivative sum;
  sum.velocity = (k1.velocity + 2.0 * k2.velocity + 2.0 * k3.velocity + k4.velocity) * (1.0 / 6);
  sum.acceleration = (k1.acceleration + 2.0 * k2.acceleration + 2.0 * k3.acceleration + k4.acceleration) * (1.0 / 6);
  sum.attitude_rate = {(k1.attitude_rate.w + 2 * k2.attitude_rate.w + 2 * k3.attitude_rate.w + k4.attitude_rate.w) / 6,
                       (k1.attitude_rate.x + 2 * k2.attitude_rate.x + 2 * k3.attitude_rate.x + k4.attitude_rate.x) / 6,
                       (k1.attitude_rate.y + 2 * k2.attitude_rate.y + 2 * k3.attitude_rate.y + k4.attitude_rate.y) / 6,
                       (k1.attitude_rate.z + 2 * k2.attitude_rate.z + 2 * k3.attitude_rate.z + k4.attitude_rate.z) / 6};
  sum.angular_acceleration = (k1.angular_acceleration + 2.0 * k2.angular_acceleration + 2.0 * k3.angular_acceleration +
                              k4.angular_acceleration) *
                             (1.0 / 6);
  for (size_t i = 0; i < kRotorCount; ++i) {
    sum.rotor_acceleration[i] = (k1.rotor_acceleration[i] + 2 * k2.rotor_acceleration[i] +
                                 2 * k3.rotor_acceleration[i] + k4.rotor_acceleration[i]) /
                                6;
  }
  state_ = advance(state_, sum, dt);
  state_.attitude = normalized(state_.attitude);

  // A spinning-down rotor approaches zero; it never reverses.
  constexpr double kTwoPi = 2 * std::numbers::pi;
  for (size_t i = 0; i < kRotorCount; ++i) {
    state_.rotor_speed[i] = std::max(0.0, state_.rotor_speed[i]);
    // Less than a turn per step: one exact subtraction (Sterbenz) gives fmod's result, bit for bit.
    const double phase = phase_[i] + 0.5 * (speed_before[i] + state_.rotor_speed[i]) * dt;
    phase_[i] = phase < kTwoPi ? phase : phase < 2 * kTwoPi ? phase - kTwoPi : std::fmod(phase, kTwoPi);
  }

  current_ = current_draw(state_.rotor_speed, volts_);
  battery_.drain(current_, dt);
  volts_ = battery_.terminal_volts(current_);
}

Vec3 Quadrotor::specific_force() const {
  Vec3 out;
  evaluate(state_, &out);
  return out;
}

double Quadrotor::deepest_contact() const {
  return ground_.at(state_.position, state_.velocity, state_.attitude, state_.rate).deepest_m;
}

bool Quadrotor::clear_of_ground_for(double seconds) const {
  // Sinking at today's speed plus a 100 m/s² (10 g) push for the whole time, and a millimetre.
  constexpr double kWorstAcceleration = 100, kMargin = 1e-3;
  const double sink = std::max(0.0, state_.velocity.z) * seconds + 0.5 * kWorstAcceleration * seconds * seconds;
  return state_.position.z + ground_.reach() + sink + kMargin < 0;
}

double Quadrotor::steady_command(double w) const {
  const std::array<double, kRotorCount> speeds{w, w, w, w};
  // Fixed point of volts -> current -> volts; converges in a few rounds (the sag is small).
  double volts = battery_.open_circuit_volts();
  for (int round = 0; round < 8; ++round) volts = battery_.terminal_volts(current_draw(speeds, volts));
  return 1000 * w / (vehicle_.speed_per_volt() * volts);
}

}  // namespace sim
