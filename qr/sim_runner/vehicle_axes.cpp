// The derivation (the numbers are the default vehicle's, sim/vehicles/in4073.txt):
//   Hover: each rotor turns at w_h = sqrt(m g / (4 k_f)) = 415.6 rad/s. The pack at its initial
//   charge rests at 3 cells x 4.06 V; at hover it gives I = 4 k_m w_h^3 / (eta V) + I_avionics
//   = 8.1 A, so V = 12.19 - 8.1 x 0.030 = 11.95 V.
//   Engine 1000 sets the motor's target speed w_max = KV x load x 2 pi / 60 x V = 783 rad/s: one
//   engine at full speed lifts T_full = k_f w_max^2 = 8.7 N. Thrust goes with speed squared and the
//   command with speed, and the mixer's per-engine thrust is w = ae^2 / 1000 (engine_mixer.hpp):
//   one thrust unit is T_full / 1000 = 8.7 mN (hover 281 units, engine 530: the file's "about 530").
//   Roll: L = w3 - w1 thrust units, the two rotors arm_m from the centre: a torque of
//   arm x T_full / 1000 = 1.96 mN m per unit, over I_xx: gain 0.178 rad/s^2 per thrust unit
//   (pitch the same over I_yy).
//   Yaw: the drag torque k_m w^2 changes by (k_m / k_f) x the thrust's change, N = w1 + w3 - w0 - w2:
//   gain (k_m / k_f) T_full / (1000 I_zz) = 6.9e-3. A rotor sped up by dw also twists the airframe
//   by J_r dw/dt while it accelerates, J_r / (2 k_m w_h) = 0.23 s of lead on the drag's 2 k_m w_h dw;
//   and a turning airframe meets the rotors' in-plane drag c w_h v at each hub, v = r arm:
//   damping 4 c w_h arm^2 / I_zz = 0.80 1/s.
//   Motor lag: the speed follows its target with tau_up rising and tau_down falling; a moment
//   speeds one motor up as it slows the opposite one, so for small moments the lag is the mean of
//   the two: 40 ms.
//   Delay 0: the simulator's engines take a tick's command at that tick and the gyro is sampled at
//   the next (qr/boards/sim/sim_board.hpp); the hold and the low-pass are the model's own.
#include <qr/sim_runner/vehicle_axes.hpp>

#include <cmath>

#include <sim/battery.hpp>
#include <sim/rotor.hpp>

namespace qrsim {

namespace {
constexpr double kGravity = 9.80665;
}

VehicleAxes axes_of(const sim::VehicleParams& v) {
  const double w_h = v.hover_speed();
  const double rest = v.battery_cells * sim::lipo_cell_volts(v.battery_initial_soc);
  double volts = rest;
  for (int n = 0; n < 4; ++n) {  // the current depends on the voltage it sags
    const double current = 4 * sim::rotor_shaft_power(v, w_h) / (v.powertrain_efficiency * volts) +
                           v.avionics_current_a;
    volts = rest - current * v.battery_resistance_ohm;
  }
  const double w_max = v.speed_per_volt() * volts;
  const double unit = v.thrust_coeff * w_max * w_max / 1000;
  const double tau = (v.motor_tau_up_s + v.motor_tau_down_s) / 2;
  VehicleAxes a;
  a.roll = {v.arm_m * unit / v.inertia_kgm2.x, tau, 0, 0, 0, 0};
  a.pitch = {v.arm_m * unit / v.inertia_kgm2.y, tau, 0, 0, 0, 0};
  a.yaw = {v.torque_coeff / v.thrust_coeff * unit / v.inertia_kgm2.z,
           tau,
           0,
           v.rotor_inertia / (2 * v.torque_coeff * w_h),
           4 * v.rotor_drag_coeff * w_h * v.arm_m * v.arm_m / v.inertia_kgm2.z,
           0};
  a.thrust_unit_n = unit;
  a.hover_engine = std::sqrt(1000 * v.mass_kg * kGravity / 4 / unit);
  return a;
}

}  // namespace qrsim
