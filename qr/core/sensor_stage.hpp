// The sample the core reads at the start of a tick, from a board whose sensors are on an I2C bus
// the core drives itself (`I2cBoard`, board.hpp): the MPU-6050 on channel 0 and the MS5611 on
// channel 1 of one shared bus (common/drivers/i2c.hpp), each driver stepped once a tick, never
// waiting on the wire (common/drivers/mpu6050.hpp, ms5611.hpp). A board without such a bus hands
// the core a finished sample (`board.read_sensors()`) and this stage keeps nothing.
//
// The sample it composes, in the units the chain expects (sensor_scale.hpp):
//   gyro, accel   the MPU's last good burst, body axes, counts at FS_SEL 1 and AFS_SEL 1 (checked
//                 below): one tick old (the burst a tick begins is collected by the next); zeros
//                 until the first, the last good one held after a failed read;
//   pressure_pa   the MS5611's last good reading, held between its conversions (about 67 a second
//                 at OSR 4096 and four pressures a temperature); 0 before the first;
//   battery_mv    the board's (its ADC is not on the bus).
//
// Why a stage of the scheduler's and not a task row: the sample is the input of every row of every
// mode, link included, and of test mode's replay, which has no bus; it must be whole before
// begin_tick, which precedes the first row. A row would be listed first in all eight task sets, and
// the flight (the context, which never sees the board) would have to own a bus of the board's type.
// Here the tick still reads as before, "the sample, then the rows", and the stage keeps its own
// cycle figure (stats()), as a row would (docs/architecture.md, "One tick").
#pragma once

#include <stdint.h>

#include <common/drivers/i2c.hpp>
#include <common/drivers/mpu6050.hpp>
#include <common/drivers/ms5611.hpp>
#include <qr/core/board.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/cycle_stats.hpp>
#include <qr/core/sensor_scale.hpp>

namespace qr {

// The MPU-6050 as the chain wants it: the full scales sensor_scale.hpp converts, one sample a
// control period (1 kHz / (1 + divider) with the low-pass filter on).
inline constexpr drivers::Mpu6050Config kSensorMpuConfig = [] {
  drivers::Mpu6050Config c;
  c.gyro_full_scale = 1;
  c.accel_full_scale = 1;
  c.sample_rate_divider = static_cast<uint8_t>(1000u / kControlHz - 1u);
  return c;
}();
static_assert(drivers::mpu6050::kGyroCountsPerDpsX10[kSensorMpuConfig.gyro_full_scale] ==
                  static_cast<uint16_t>(sensor::kGyroCountsPerDegPerSec * 10.0),
              "the MPU's gyro full scale is the one sensor_scale.hpp converts");
static_assert(drivers::mpu6050::kAccelCountsPerG[kSensorMpuConfig.accel_full_scale] ==
                  static_cast<uint16_t>(sensor::kAccelCountsPerG),
              "the MPU's accelerometer full scale is the one sensor_scale.hpp converts");
static_assert(drivers::mpu6050_sample_rate_hz(kSensorMpuConfig) == kControlHz, "a sample a control period");

inline constexpr uint8_t kImuChannel = 0;
inline constexpr uint8_t kBarometerChannel = 1;

// What the drivers have counted since power-up, and their verdicts: the figures a flight is
// judged on beside the truth (qrsim's imu_samples, imu_lost, ...), in a form a board can send.
struct SensorCounts {
  enum Count : uint8_t { imu_samples, imu_faults, imu_lost, baro_readings, baro_faults, baro_adc_zero, kCounts };
  static constexpr uint8_t kImuHealthy = 1, kBarometerHealthy = 2;
  uint32_t value[kCounts] = {};
  uint8_t healthy = 0;  // kImuHealthy | kBarometerHealthy
};

// A board without a sensor bus: nothing to keep.
template <class B>
class SensorStage {};

template <I2cBoard B>
class SensorStage<B> {
 public:
  using Bus = typename B::I2cBus;
  static_assert(drivers::I2cSharedBus<Bus> && Bus::kChannels >= 2, "a channel for each chip");

  SensorSample read(B& board, uint32_t now_us) {
    if (!board.sensors_on_i2c()) return board.read_sensors();
    const uint32_t before = board.cycles();
    Bus& bus = board.i2c();
    // The IMU first: its burst is the one the loop runs on, so it goes on the wire first.
    drivers::I2cChannel<Bus> imu(bus, kImuChannel);
    drivers::I2cChannel<Bus> barometer(bus, kBarometerChannel);
    if (!powered_) {
      powered_ = true;
      powered_at_us_ = now_us;
    }
    imu_.step(imu, now_us);
    // The MS5611 loads its PROM for 2.8 ms after power-up and answers nothing meanwhile; its driver
    // waits a whole second after a start that found no chip, so it is not started before.
    if (now_us - powered_at_us_ >= drivers::kMs5611ResetTimeUs) barometer_.step(barometer, now_us);
    drivers::Ms5611Reading reading;
    if (barometer_.take(reading)) pressure_pa_ = reading.pressure_pa;

    SensorSample s;
    const drivers::Mpu6050Sample& m = imu_.sample();
    for (int axis = 0; axis < 3; ++axis) {
      s.gyro[axis] = m.gyro[axis];
      s.accel[axis] = m.accel[axis];
    }
    s.battery_mv = board.battery_mv();
    s.pressure_pa = pressure_pa_;
    s.health = health();
    stats_.add(board.cycles() - before);
    return s;
  }

  // What the drivers say of themselves (board.hpp's SensorHealth). The IMU is healthy while it
  // streams: a failed read holds the last sample and counts, and only the driver's verdict (lost
  // after kLostAfterFailures in a row, then starting over) ends it. So the address NACK of the
  // MPU's first 100 ms, counted before it ever streamed, is a start-up like any other, no fault
  // the flight reacts to: the IMU is simply not healthy yet, as it is not until its first burst.
  SensorHealth health() const {
    SensorHealth h;
    h.imu = imu_.phase() == drivers::Mpu6050Phase::streaming;
    h.barometer = barometer_.healthy();
    h.imu_faults = imu_.total_faults();
    h.barometer_faults = barometer_.total_faults();
    if (h.imu_faults > 0) h.imu_fault = static_cast<uint8_t>(imu_.last_fault());
    if (h.barometer_faults > 0) h.barometer_fault = static_cast<uint8_t>(barometer_.last_fault());
    return h;
  }

  // The drivers' counts as a board reports them (the devboard's sensor link, EngineFrame).
  SensorCounts counts() const {
    SensorCounts c;
    c.value[SensorCounts::imu_samples] = imu_.samples();
    c.value[SensorCounts::imu_faults] = imu_.total_faults();
    c.value[SensorCounts::imu_lost] = imu_.lost_count();
    c.value[SensorCounts::baro_readings] = barometer_.readings();
    c.value[SensorCounts::baro_faults] = barometer_.total_faults();
    c.value[SensorCounts::baro_adc_zero] = barometer_.faults(drivers::Ms5611Fault::adc_zero);
    const SensorHealth h = health();
    c.healthy = static_cast<uint8_t>((h.imu ? SensorCounts::kImuHealthy : 0) |
                                     (h.barometer ? SensorCounts::kBarometerHealthy : 0));
    return c;
  }

  const drivers::Mpu6050& imu() const { return imu_; }
  const drivers::Ms5611& barometer() const { return barometer_; }
  // Cycles per tick the stage took (the drivers' steps and the sample), as a task row's.
  const CycleStats& stats() const { return stats_; }

 private:
  drivers::Mpu6050 imu_{kSensorMpuConfig};
  drivers::Ms5611 barometer_;
  int32_t pressure_pa_ = 0;
  bool powered_ = false;
  uint32_t powered_at_us_ = 0;  // the first tick's time: the board's power-up, as the stage sees it
  CycleStats stats_;
};

}  // namespace qr
