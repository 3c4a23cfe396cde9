// How a vehicle is put together, right or wrong: which rotor each engine output drives, which way
// each motor turns, how the IMU's board is mounted and whether a sensor axis reads backwards.
// The mistakes a first build makes (issue 33: the IN4073 report's team flew with a sign error),
// so that the bench checks and the firmware's sign check are tested against the faults they exist
// for. The default is the vehicle as docs/conventions.md draws it.
#pragma once

#include <array>
#include <string>

#include <sim/vec3.hpp>

namespace sim {

struct Wiring {
  // Engine output i drives rotor rotor_of_output[i] (rotors as docs/conventions.md numbers them:
  // 0 front, 1 right, 2 back, 3 left). A permutation of 0..3.
  std::array<int, 4> rotor_of_output{0, 1, 2, 3};
  // 1: that rotor's motor turns the wrong way (two of its three phase wires swapped) with the
  // right propeller on it: the blades meet the air backwards. Its reaction torque and gyroscopic
  // moment change sign, and its thrust points down at kReversedThrustShare of the forward thrust
  // (our assumption, not a measurement: a cambered blade run backwards lifts poorly).
  std::array<int, 4> reversed{0, 0, 0, 0};
  // The IMU's board turned about body z by this many degrees (0, 90, 180, 270; clockwise seen
  // from above, as a positive yaw), then, with imu_upside_down, turned over about its own x axis.
  int imu_yaw_deg = 0;
  int imu_upside_down = 0;
  // +1 or -1 per body axis: -1 reads that gyro or accelerometer axis backwards (a driver's or a
  // board's sign mistake), after the mounting.
  std::array<int, 3> gyro_signs{1, 1, 1};
  std::array<int, 3> accel_signs{1, 1, 1};

  bool operator==(const Wiring&) const = default;
};

inline constexpr double kReversedThrustShare = 0.5;

// The wiring's words, the same in a vehicle file (`motor_outputs = 1 0 2 3`) and a scenario
// (`motor_outputs: 1 0 2 3`): motor_outputs, motor_reversed (four 0/1), imu_mount_yaw_deg,
// imu_upside_down (0/1), gyro_signs, accel_signs (three +1/-1).
bool is_wiring_name(const std::string& name);
// Reads one of them into `wiring`; on a mistake returns false and says why in `error`.
bool parse_wiring_row(const std::string& name, const std::string& values, Wiring& wiring, std::string& error);
// The rows that differ from the right wiring, one `name = values` a line ("" when right).
std::string wiring_text(const Wiring& wiring);

// A body-axes vector as the IMU's axes read it (the mounting, then the signs): what a rightly
// mounted sensor would report for the vehicle, for the sensor as it is mounted.
Vec3 imu_gyro_axes(const Wiring& wiring, const Vec3& body);
Vec3 imu_accel_axes(const Wiring& wiring, const Vec3& body);

}  // namespace sim
