// The world the host firmware flies in: the plant, its sensors and a clock in whole
// microseconds. Time only moves through advance_to(), in physics steps chosen from the state
// alone, so the same seed and the same engine commands at the same times give the same flight,
// bit for bit.
#pragma once

#include <stdint.h>

#include <optional>
#include <string>
#include <variant>

#include <sim/barometer.hpp>
#include <sim/battery_sensor.hpp>
#include <sim/hand_tilt.hpp>
#include <sim/hand_turn.hpp>
#include <sim/imu.hpp>
#include <sim/mpu6050_model.hpp>
#include <sim/ms5611_model.hpp>
#include <sim/quadrotor.hpp>
#include <sim/vibration.hpp>

namespace sim {

struct WorldConfig {
  uint64_t seed = 1;
  uint32_t step_us = 125;  // 8 kHz; must divide the control period
  // The step in free flight, where no contact point can reach the ground within it: the contact
  // (the plant's only stiff part) is zero there, and the slowest-to-fastest dynamics left are the
  // motor lag (30 ms) and the body's rates. 0: always step_us. Shortened so that it stays within
  // kMotorLagPerStep of the vehicle's faster motor time constant (docs/simulator.md section 1).
  uint32_t free_flight_step_us = 500;
};

struct SensorReading {
  ImuReading imu;
  uint16_t battery_mv = 0;
  int32_t pressure_pa = 0;  // the barometer's last reading (0 before its first)
};

class World {
 public:
  World(const VehicleParams& vehicle, const WorldConfig& config);

  // Runs whole physics steps until the clock reaches `time_us` (rounded down to a step).
  void advance_to(uint64_t time_us);
  uint64_t now_us() const { return now_us_; }
  uint32_t step_us() const { return step_us_; }
  uint32_t free_flight_step_us() const { return free_flight_step_us_; }
  // Physics steps taken so far, fine and coarse (for the benchmark and the tests).
  uint64_t steps_taken() const { return steps_taken_; }

  // A hand takes the vehicle now and turns it (hand_turn.hpp); while it holds, the physics does
  // not move the body and the IMU reads the turn. Refused (the reason returned, nothing done)
  // while an engine command is not zero, a hand in the rotors, or while the hand holds it already
  // ("a turn is under way", "a tilt is under way"); empty once the turn has begun. The spec must
  // keep hand_turn_problem's limits.
  std::string start_hand_turn(const HandTurnSpec& spec);
  // The same hand tilting it to an angle and back (hand_tilt.hpp), refused as a turn is. The spec
  // must keep hand_tilt_problem's limits.
  std::string start_hand_tilt(const HandTiltSpec& spec);
  bool held() const { return hand_.has_value(); }
  // Why a hand may not take the vehicle now (the reasons above), or empty.
  std::string hand_refused() const;

  // What the sensors read at this instant. In chip mode (use_chips) the IMU's reading goes to the
  // MPU-6050 model's registers instead, and the reading's imu and pressure_pa stay zero.
  SensorReading sample();

  // Chip mode: the plant's sensors behind register-level chips that a firmware's drivers read over
  // I2C (the sim board's --sensors drivers). From now on sample() feeds the MPU-6050 model what
  // the IMU senses (Imu::sense, the very draws Imu::sample takes) in the chip's axes: it is mounted
  // flat, component side up, its X arrow forward, so chip (x, y, z) is body (x, -y, -z), the
  // firmware driver's default (common/drivers/mpu6050.hpp, kChipFlatXForward); its die at the
  // board's temperature. The MS5611 model senses the pressure (Barometer::sense_pa, at its
  // conversion's noise scale) at the middle of each conversion its driver starts, instead of the
  // barometer's own 20 ms cycle (Barometer::step is not called). The chips must outlive the world.
  void use_chips(Mpu6050Model& mpu, Ms5611Model& ms5611) {
    mpu_ = &mpu;
    ms5611_ = &ms5611;
  }
  bool chip_mode() const { return mpu_ != nullptr; }
  // The vibration the IMU would add now (for tests and plots).
  VibrationSample vibration() const;

  Quadrotor& plant() { return plant_; }
  const Quadrotor& plant() const { return plant_; }
  const Imu& imu() const { return imu_; }
  const Barometer& barometer() const { return barometer_; }
  // The board's altitude above the (ISA sea-level) ground, m: what the barometer measures.
  double altitude_m() const { return -plant_.state().position.z; }

 private:
  Quadrotor plant_;
  Vibration vibration_;
  Imu imu_;
  BatterySensor battery_sensor_;
  Barometer barometer_;
  std::optional<std::variant<HandTurn, HandTilt>> hand_;
  Mpu6050Model* mpu_ = nullptr;
  Ms5611Model* ms5611_ = nullptr;
  // Chip mode: the barometer's instant, the middle of the MS5611 model's conversion (in whole
  // microseconds, rounded up), or none.
  std::optional<uint64_t> chip_pressure_instant_us() const;
  void sense_pressure();
  Vec3 held_position_;
  // The step that may be taken from now towards `time_us`.
  uint32_t next_step_us(uint64_t time_us) const;
  // The hand takes the vehicle where it is.
  void take(const std::variant<HandTurn, HandTilt>& hand);
  // The hand's pose over what the step made of the body; the hand lets go at the motion's end.
  void hold();

  uint32_t step_us_;
  uint32_t free_flight_step_us_;
  uint64_t now_us_ = 0;
  uint64_t steps_taken_ = 0;
};

}  // namespace sim
