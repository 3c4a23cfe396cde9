// What the core needs from hardware, and the data that crosses that line.
//
// A board is any class with these members (checked by the `Board` concept below); the scheduler
// is a template over it, so nothing hardware-shaped is reached through virtual calls:
//
//   uint32_t wait_kick(uint32_t seen)  blocks until the kick counter differs from `seen`,
//                                      returns the counter (the timer kick, one per period)
//   uint32_t kicks()                   kick counter now (to notice overruns)
//   uint32_t now_us()                  monotonic time in µs (wraps after 71 minutes)
//   uint32_t cycles()                  cycle or instruction counter, for task statistics
//   SensorSample read_sensors()        the latest raw sample
//   void set_engines(EngineCommand)    engine outputs, each 0..1000
//   bool serial_read(uint8_t&)         one received byte if there is one
//   bool serial_write(uint8_t)         queue one byte; false when the transmitter is full
//   void set_leds(uint8_t)             one bit per LED
//   LogArea log_area()                 memory the loggers may fill
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/units.hpp>

namespace qr {

// Raw MPU-6050-style sample: 16-bit gyro and accelerometer counts in body axes x (forward),
// y (right), z (down); the accelerometer reads specific force, so (0, 0, -1 g) at rest and
// level. Scales in sensor_scale.hpp, signs in docs/conventions.md. Battery in mV. The
// barometer is optional (0 when absent).
//
// `health`: what the sensors' drivers say of themselves, on a board whose sensors are on a bus the
// core drives (sensor_stage.hpp). A board that hands over finished samples has no drivers to
// doubt and reports its sensors healthy. The safety machine reads it (docs/safety.md rule 20).
inline constexpr uint8_t kNoSensorFault = 0xFF;  // no fault seen yet (a fault kind's place)

struct SensorHealth {
  // The IMU streams: its driver has its burst each tick, or holds the last good one for fewer
  // failed reads in a row than it takes to call the chip lost (mpu6050.hpp kLostAfterFailures).
  bool imu = true;
  // The barometer measures: its PROM passed its CRC and the driver is not starting over.
  bool barometer = true;
  // The last fault's kind (drivers::Mpu6050Fault, drivers::Ms5611Fault), kNoSensorFault before
  // the first, and the faults counted since power-up: what the console is told.
  uint8_t imu_fault = kNoSensorFault;
  uint8_t barometer_fault = kNoSensorFault;
  uint32_t imu_faults = 0;
  uint32_t barometer_faults = 0;
};

struct SensorSample {
  int16_t gyro[3] = {0, 0, 0};
  int16_t accel[3] = {0, 0, 0};
  uint16_t battery_mv = 0;
  int32_t pressure_pa = 0;
  SensorHealth health;
};

using wire::kEngineMax;  // engine commands 0..kEngineMax (common/units.hpp)

// Engine order: 0 front, 1 right, 2 back, 3 left (the IN4073 "+" layout).
struct EngineCommand {
  uint16_t value[4] = {0, 0, 0, 0};

  bool all_zero() const { return (value[0] | value[1] | value[2] | value[3]) == 0; }
};

struct LogArea {
  uint8_t* data = nullptr;
  size_t size = 0;
};

template <class B>
concept Board = requires(B& b, uint8_t& byte, EngineCommand engines) {
  {b.wait_kick(uint32_t{})};
  {b.kicks()};
  {b.now_us()};
  {b.cycles()};
  {b.read_sensors()};
  b.set_engines(engines);
  {b.serial_read(byte)};
  {b.serial_write(uint8_t{})};
  b.set_leds(uint8_t{});
  {b.log_area()};
};

// Optional: the sensors on an I2C bus the core drives itself (common/drivers/i2c.hpp), an MPU-6050
// and an MS5611 sharing it, read by sensor_stage.hpp in place of read_sensors().
//   using I2cBus = ...                 the shared bus' type (drivers::I2cSharedBus, 2 channels)
//   I2cBus& i2c()                      the bus
//   bool sensors_on_i2c() const        false: read_sensors() gives the sample after all (the
//                                      simulator's --sensors direct)
//   uint16_t battery_mv()              the battery's reading (its ADC is not on the bus)
template <class B>
concept I2cBoard = requires(B& b, const B& cb) {
  typename B::I2cBus;
  {b.i2c()};
  {cb.sensors_on_i2c()};
  {b.battery_mv()};
};

// Optional: a radio receiver on a second serial line (CRSF, common/drivers/crsf.hpp).
//   bool radio_read(uint8_t&)          one received byte if there is one
template <class B>
concept RadioBoard = requires(B& b, uint8_t& byte) {
  {b.radio_read(byte)};
};

// The raw answers of bidirectional DShot ESCs (common/drivers/erpm.hpp), 21 bits each as sampled
// from the line; `fresh` bit i: engine i answered since the last call.
struct EscAnswers {
  uint32_t raw[4] = {0, 0, 0, 0};
  uint8_t fresh = 0;
};

// Optional: ESCs that answer (bidirectional DShot).
//   bool esc_answers(EscAnswers&)      the answers since the last call; false: none
template <class B>
concept EscAnswerBoard = requires(B& b, EscAnswers& answers) {
  {b.esc_answers(answers)};
};

// Optional: a serial receiver that counts the bytes it had no room for.
//   uint32_t rx_overruns() const       since start
template <class B>
concept OverrunCountingBoard = requires(const B& b) {
  {b.rx_overruns()};
};

// Optional: DShot ESCs that take special commands (common/drivers/dshot_commands.hpp), sent in
// place of the throttle frames while an engine is stopped, a frame a control period.
//   bool esc_command(uint8_t command, uint8_t engines)   to the engines of the mask (bit i: engine
//                                       i); false: refused (no such ESCs, or one of them turns)
struct EscCommand {
  uint8_t command = 0;  // 0: none
  uint8_t engines = 0;  // bit i: engine i
};
inline constexpr uint8_t kEveryEngine = 0x0F;

template <class B>
concept EscCommandBoard = requires(B& b, uint8_t command, uint8_t engines) {
  {b.esc_command(command, engines)};
};

}  // namespace qr
