// Everything that describes one vehicle: airframe, rotors and motors, battery, landing gear,
// vibration and the IMU on its board. Values come from a parameter file (sim/vehicles/*.txt,
// one `name = value` a line, `#` comments citing where each value comes from); every parameter
// must be given, so a file describes its vehicle completely and a typo is an error, not a default.
#pragma once

#include <numbers>
#include <string>

#include <sim/vec3.hpp>
#include <sim/wiring.hpp>

namespace sim {

struct VehicleParams {
  // Airframe
  double mass_kg = 0;
  Vec3 inertia_kgm2;        // principal moments about body x, y, z
  double arm_m = 0;         // centre to rotor hub
  double hub_height_m = 0;  // rotor plane above the centre of mass (positive up)
  Vec3 body_drag_area_m2;   // Cd·A seen along body x, y, z

  // Rotors and motors. Engine command e (0..1000) sets the motor's speed target to
  // e/1000 · speed_per_volt · battery voltage; the rotor follows with a first-order lag.
  double thrust_coeff = 0;      // k_f: thrust = k_f ω², N/(rad/s)²
  double torque_coeff = 0;      // k_m: reaction torque = k_m ω², N·m/(rad/s)²
  double rotor_inertia = 0;     // rotor + motor bell, kg·m²
  double rotor_drag_coeff = 0;  // in-plane drag per rotor = coeff · ω · in-plane air speed, N/((rad/s)·(m/s))
  double motor_kv_rpm_per_v = 0;
  double motor_load_factor = 0;      // full-throttle speed with the prop / no-load speed
  double motor_tau_up_s = 0;         // spin-up time constant
  double motor_tau_down_s = 0;       // spin-down time constant (no active braking: slower)
  double powertrain_efficiency = 0;  // shaft power / battery power, motor and ESC together

  // Battery (lithium-polymer cells in series)
  double battery_cells = 0;
  double battery_capacity_mah = 0;
  double battery_resistance_ohm = 0;  // whole pack, cells + wiring
  double battery_initial_soc = 0;     // state of charge at start, 0..1
  double avionics_current_a = 0;      // flight computer, receiver, LEDs

  // Landing gear and ground
  double foot_radius_m = 0;      // feet sit under the arms at this distance from the centre
  double foot_depth_m = 0;       // feet below the centre of mass
  double top_height_m = 0;       // highest point (battery) above the centre of mass
  double contact_stiffness = 0;  // N/m per contact point
  double contact_damping = 0;    // N·s/m per contact point
  double ground_friction = 0;    // Coulomb coefficient

  // Vibration at the IMU, per rotor, at the reference rotor speed; scales with speed squared
  // (imbalance force m·r·ω²). Harmonics 1, 2, 3 of the rotation frequency.
  double vibration_ref_speed = 0;      // rad/s
  Vec3 vibration_accel_g;              // amplitude of harmonics 1, 2, 3 in the rotor plane, g
  double vibration_accel_z_ratio = 0;  // along z, relative to the in-plane amplitude
  Vec3 vibration_gyro_dps;             // amplitude of harmonics 1, 2, 3, °/s, about each axis

  // IMU (MPU-6050 class)
  double gyro_noise_dps_rthz = 0;  // rate noise spectral density, °/s/√Hz
  double accel_noise_ug_rthz = 0;  // accelerometer noise density, µg/√Hz
  double imu_bandwidth_hz = 0;     // digital low-pass setting: noise bandwidth
  double gyro_bias_dps = 0;        // turn-on zero-rate offset tolerance (3σ), °/s
  double accel_bias_xy_mg = 0;     // zero-g offset tolerance x, y (3σ), mg
  double accel_bias_z_mg = 0;      // zero-g offset tolerance z (3σ), mg
  double scale_error = 0;          // sensitivity tolerance (3σ), fraction

  // Battery voltage sensor
  double battery_sense_noise_mv = 0;
  double battery_sense_lsb_mv = 0;

  // Barometer (MS5611 class, sim/barometer.hpp). Optional in a file: a file written before the
  // barometer existed gets these defaults (the datasheet's noise at OSR 4096, our drift estimate).
  double baro_noise_pa = 1.2;             // RMS noise of one reading (0.012 mbar at OSR 4096)
  double baro_temp_coeff_pa_per_k = 0.5;  // residual pressure error per kelvin of warming
  double baro_warmup_k = 5.0;             // the board's warming after power-up
  double baro_warmup_tau_s = 120.0;       // ... and its time constant

  // How it is put together (sim/wiring.hpp): optional rows, the right wiring when absent.
  Wiring wiring;

  // Derived
  // rad/s per volt at full command
  double speed_per_volt() const { return motor_kv_rpm_per_v * motor_load_factor * 2 * std::numbers::pi / 60; }
  double hover_speed() const;  // rad/s per rotor for thrust = weight
};

// The default vehicle, an IN4073-class quadrotor (sim/vehicles/in4073.txt, compiled in).
const char* default_vehicle_text();
const char* default_vehicle_name();

// Parses a parameter file's text. On failure returns false and says why in `error`
// (unknown name, missing name, bad number, line number).
bool parse_vehicle(const std::string& text, VehicleParams& out, std::string& error);
bool load_vehicle_file(const std::string& path, VehicleParams& out, std::string& error);
VehicleParams default_vehicle();

}  // namespace sim
