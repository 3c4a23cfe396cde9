// The sim board with its sensors on the I2C bus (qrsim --sensors drivers): the firmware's drivers
// (qr/core/sensor_stage.hpp) read the register-level chips (sim/mpu6050_model.hpp, ms5611_model.hpp)
// over the board's bus (qr/boards/sim/sim_i2c_bus.hpp), the wire's time in simulated time.
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include <qr/boards/sim/sim_qr.hpp>

namespace {

// Two QRs on the ground in safe, the same seed: one read directly, one through the drivers. The
// IMU takes the same random draws either way (Imu::sense), so the drivers' gyro and accelerometer
// are the direct sample of the tick before, count for count, the chip's mounting undone by the
// driver; the MS5611's pressure is its own conversion of the same atmosphere.
TEST(SimI2c, TheDriversReadThePlantsSampleOneTickLate) {
  qrsim::SimQr direct(sim::default_vehicle(), {});
  qrsim::SimQr drivers(sim::default_vehicle(), {});
  drivers.board.use_sensor_drivers();
  std::vector<qr::SensorSample> direct_seen, drivers_seen;
  for (int i = 0; i < 2000; ++i) {
    direct.tick();
    drivers.tick();
    direct_seen.push_back(direct.firmware.sample());
    drivers_seen.push_back(drivers.firmware.sample());
  }
  const auto& stage = drivers.scheduler.sensor_stage();
  // The MPU answers nothing for its first 100 ms: the driver's first reset is not acknowledged
  // (one fault) and it starts again 100 ms later; it streams from about 0.24 s.
  EXPECT_TRUE(stage.imu().healthy());
  EXPECT_EQ(stage.imu().total_faults(), 1u);
  EXPECT_EQ(stage.imu().fault_count(drivers::Mpu6050Fault::address_nack), 1u);
  EXPECT_EQ(drivers_seen[200].accel[2], 0) << "not streaming yet at 0.2 s";
  size_t first = 0;
  while (drivers_seen[first].accel[2] == 0) ++first;
  EXPECT_LT(first, 300u) << "streaming before the pilot's 0.3 s of settling";
  for (size_t i = first + 1; i < drivers_seen.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      ASSERT_EQ(drivers_seen[i].gyro[a], direct_seen[i - 1].gyro[a]) << "tick " << i << " axis " << a;
      ASSERT_EQ(drivers_seen[i].accel[a], direct_seen[i - 1].accel[a]) << "tick " << i << " axis " << a;
    }
    ASSERT_EQ(drivers_seen[i].battery_mv, direct_seen[i].battery_mv) << "the board's battery, this tick's";
  }

  // The barometer reads from its first 30 ms on, about 66 times a second, within a few pascals of
  // the direct path (both 1.2 Pa RMS of noise).
  EXPECT_EQ(stage.barometer().state(), drivers::Ms5611State::measuring);
  EXPECT_EQ(stage.barometer().total_faults(), 0u);
  EXPECT_GE(stage.barometer().readings(), 125u);
  EXPECT_NE(drivers_seen[50].pressure_pa, 0);
  for (size_t i = 100; i < drivers_seen.size(); ++i) {
    ASSERT_LE(std::abs(drivers_seen[i].pressure_pa - direct_seen[i].pressure_pa), 8) << "tick " << i;
  }

  // The wire: the MPU's burst each tick (390 us) and the MS5611's transfers, back to back.
  const qrsim::SimI2cBus& bus = drivers.board.i2c();
  EXPECT_NEAR(static_cast<double>(bus.busy_ns()) / 2e9, 0.39 * 0.88 + 0.014, 0.02);
  EXPECT_EQ(drivers.board.i2c().address_nacks(), 1u);
}

// Without use_sensor_drivers the board is what it was: the plant's sample, the bus untouched.
TEST(SimI2c, DirectTheBusIsNotTouched) {
  qrsim::SimQr direct(sim::default_vehicle(), {});
  for (int i = 0; i < 100; ++i) direct.tick();
  EXPECT_EQ(direct.board.i2c().transfers(), 0u);
  EXPECT_EQ(direct.scheduler.sensor_stage().stats().count, 0u);
  EXPECT_NE(direct.firmware.sample().accel[2], 0);
}

}  // namespace
