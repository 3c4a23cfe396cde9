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
  // (one fault) and it starts again 100 ms later; it self-tests the model (a part that matches its
  // trim, with the plant's noise) and streams from about 0.28 s.
  EXPECT_TRUE(stage.imu().healthy());
  EXPECT_EQ(stage.imu().self_tests(), 1u);
  EXPECT_EQ(stage.imu().self_test_failures(), 0u);
  EXPECT_EQ(stage.imu().total_faults(), 1u);
  EXPECT_EQ(stage.imu().fault_count(drivers::Mpu6050Fault::address_nack), 1u);
  EXPECT_EQ(drivers_seen[200].accel[2], 0) << "not streaming yet at 0.2 s";
  size_t first = 0;
  while (drivers_seen[first].accel[2] == 0) ++first;
  EXPECT_EQ(first, 279u) << "the self-test's 41 ms after 0.238 s";
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

// ---- Faults on the wire and in the chips (docs/drivers.md section 7, "Faults") ----

struct FaultRig {
  qrsim::SimQr qr{sim::default_vehicle(), {}};
  FaultRig() {
    qr.board.use_sensor_drivers();
    run(1000);  // streaming since about 0.28 s, the barometer measuring
  }
  void run(int ticks) {
    for (int i = 0; i < ticks; ++i) qr.tick();
  }
  const qr::SensorStage<qrsim::SimBoard>& stage() const { return qr.scheduler.sensor_stage(); }
  uint64_t now_us() const { return qr.world.now_us(); }
};

// A NACK burst shorter than the driver's 10 failed reads: each tick's read fails and the last good
// sample is held (the same counts), the faults counted, the IMU still healthy for the flight; the
// next burst after it is fresh.
TEST(SimI2c, ANackBurstShorterThanTheLostThresholdHoldsTheLastSample) {
  FaultRig rig;
  ASSERT_TRUE(rig.stage().health().imu);
  const uint32_t faults_before = rig.stage().imu().total_faults();
  // The bursts that start on the wire in the next 5 ms: four, begun by the ticks after this one's.
  rig.qr.board.i2c().nack_address(drivers::mpu6050::kAddressAd0Low, rig.now_us(), rig.now_us() + 5000);
  rig.run(1);  // the burst begun before the window is collected good
  const qr::SensorSample held = rig.qr.firmware.sample();
  for (int i = 0; i < 4; ++i) {
    rig.run(1);
    const qr::SensorSample s = rig.qr.firmware.sample();
    EXPECT_TRUE(s.health.imu) << "tick " << i;
    for (int a = 0; a < 3; ++a) EXPECT_EQ(s.gyro[a], held.gyro[a]) << "held, tick " << i;
  }
  rig.run(100);
  EXPECT_EQ(rig.stage().imu().fault_count(drivers::Mpu6050Fault::address_nack) - 1, 4u);
  EXPECT_EQ(rig.stage().imu().total_faults() - faults_before, 4u);
  EXPECT_EQ(rig.stage().imu().lost_count(), 0u);
  EXPECT_TRUE(rig.stage().imu().healthy());
  EXPECT_EQ(rig.qr.firmware.sample().health.imu_faults, faults_before + 4);
  EXPECT_EQ(rig.qr.firmware.sample().health.imu_fault, static_cast<uint8_t>(drivers::Mpu6050Fault::address_nack));
}

// A NACK burst longer than the threshold: lost after 10 failed reads (the health false from then),
// the driver starts over and streams again about a quarter of a second after the chip answers.
TEST(SimI2c, ANackBurstLongerThanTheThresholdLosesTheImuUntilItStartsOver) {
  FaultRig rig;
  rig.qr.board.i2c().nack_address(drivers::mpu6050::kAddressAd0Low, rig.now_us(), rig.now_us() + 50000);
  rig.run(1);
  int healthy_ticks = 0;
  while (rig.qr.firmware.sample().health.imu && healthy_ticks < 100) {
    rig.run(1);
    ++healthy_ticks;
  }
  // Healthy through the first 9 failed reads, lost at the 10th (collected the tick after).
  EXPECT_EQ(healthy_ticks, drivers::mpu6050::kLostAfterFailures) << "lost at its 10th failed read";
  EXPECT_EQ(rig.stage().imu().lost_count(), 1u);
  rig.run(40);
  EXPECT_FALSE(rig.qr.firmware.sample().health.imu);
  rig.run(400);
  EXPECT_TRUE(rig.qr.firmware.sample().health.imu) << "the chip answers again: the driver streams";
}

// A stuck SDA: every transfer on the bus answers bus_stuck, the IMU's and the barometer's; for ever
// neither recovers.
TEST(SimI2c, AStuckSdaFailsEveryTransferUntilItIsFreed) {
  FaultRig rig;
  rig.qr.board.i2c().stick_sda(rig.now_us(), qrsim::SimI2cBus::kForever);
  rig.run(2000);
  EXPECT_GT(rig.stage().imu().fault_count(drivers::Mpu6050Fault::bus_stuck), 10u);
  EXPECT_GT(rig.stage().barometer().faults(drivers::Ms5611Fault::bus_stuck), 8u);
  const qr::SensorHealth h = rig.qr.firmware.sample().health;
  EXPECT_FALSE(h.imu);
  EXPECT_FALSE(h.barometer);
  EXPECT_GT(rig.qr.board.i2c().fault_answers(), 0u);
}

// Another part at the MPU's address from power-up (WHO_AM_I 0x70): the start-up finds the wrong
// identity every 200 ms (the retry's 100 ms and the reset's 100 ms) and never streams; the health
// says so for the flight.
TEST(SimI2c, AWrongIdentityNeverStreams) {
  qrsim::SimQr qr(sim::default_vehicle(), {});
  qr.board.use_sensor_drivers();
  sim::Mpu6050Faults faults;
  faults.who_am_i = 0x70;
  qr.board.mpu6050_chip().set_faults(faults);
  for (int i = 0; i < 2000; ++i) qr.tick();
  const auto& imu = qr.scheduler.sensor_stage().imu();
  EXPECT_GE(imu.fault_count(drivers::Mpu6050Fault::wrong_identity), 8u);
  EXPECT_EQ(imu.samples(), 0u);
  EXPECT_FALSE(qr.firmware.sample().health.imu);
  EXPECT_EQ(qr.firmware.sample().health.imu_fault, static_cast<uint8_t>(drivers::Mpu6050Fault::wrong_identity));
  EXPECT_TRUE(qr.firmware.sample().health.barometer);
}

// A part whose gyroscope x responds to its self-test at half its trim (Mpu6050Faults'
// gyro_self_test_scale), from power-up: the driver's self-test fails that axis alone, the start-up
// starts over and fails again, and the IMU never streams; the health says why. The same fault
// set once the IMU streams changes nothing: a lost chip's start-up does not self-test.
TEST(SimI2c, ABrokenSelfTestResponseNeverStreamsUnlessItCameAfterPowerUp) {
  sim::Mpu6050Faults broken;
  broken.gyro_self_test_scale = {0.5, 1, 1};
  {
    qrsim::SimQr qr(sim::default_vehicle(), {});
    qr.board.use_sensor_drivers();
    qr.board.mpu6050_chip().set_faults(broken);
    for (int i = 0; i < 2000; ++i) qr.tick();
    const auto& imu = qr.scheduler.sensor_stage().imu();
    EXPECT_GE(imu.fault_count(drivers::Mpu6050Fault::self_test), 5u);
    EXPECT_EQ(imu.self_tests(), imu.fault_count(drivers::Mpu6050Fault::self_test));
    EXPECT_EQ(imu.self_test_failures(), 1u << 3) << "gyroscope x alone";
    EXPECT_EQ(imu.samples(), 0u);
    EXPECT_FALSE(qr.firmware.sample().health.imu);
    EXPECT_EQ(qr.firmware.sample().health.imu_fault, static_cast<uint8_t>(drivers::Mpu6050Fault::self_test));
  }
  FaultRig rig;
  rig.qr.board.mpu6050_chip().set_faults(broken);
  rig.qr.board.i2c().nack_address(drivers::mpu6050::kAddressAd0Low, rig.now_us(), rig.now_us() + 50000);
  rig.run(1000);
  EXPECT_EQ(rig.stage().imu().lost_count(), 1u);
  EXPECT_TRUE(rig.stage().imu().healthy());
  EXPECT_EQ(rig.stage().imu().self_tests(), 1u);
  EXPECT_EQ(rig.stage().imu().fault_count(drivers::Mpu6050Fault::self_test), 0u);
}

// A PROM with a bad CRC: the driver refuses it and the barometer is unhealthy (a new try a second).
TEST(SimI2c, ABadPromCrcLeavesTheBarometerUnhealthy) {
  qrsim::SimQr qr(sim::default_vehicle(), {});
  qr.board.use_sensor_drivers();
  sim::Ms5611Faults faults;
  faults.bad_prom_crc = true;
  qr.board.ms5611_chip().set_faults(faults);
  for (int i = 0; i < 2500; ++i) qr.tick();
  const auto& baro = qr.scheduler.sensor_stage().barometer();
  EXPECT_EQ(baro.state(), drivers::Ms5611State::prom_bad);
  EXPECT_GE(baro.faults(drivers::Ms5611Fault::prom_crc), 2u);
  EXPECT_EQ(baro.readings(), 0u);
  EXPECT_FALSE(qr.firmware.sample().health.barometer);
  EXPECT_TRUE(qr.firmware.sample().health.imu);
}

// A conversion slower than the datasheet's time: the driver's read comes too early and the chip
// answers 0; the reading is discarded and counted, the last pressure held, and the barometer stays
// healthy (fewer than 8 in a row) and reads again once the conversions are on time.
TEST(SimI2c, AReadTooEarlyIsDiscardedAndCounted) {
  FaultRig rig;
  const uint32_t readings = rig.stage().barometer().readings();
  sim::Ms5611Faults slow;
  slow.slow_conversion_s = 0.005;
  rig.qr.board.ms5611_chip().set_faults(slow);
  rig.run(50);
  rig.qr.board.ms5611_chip().set_faults({});
  EXPECT_GE(rig.stage().barometer().faults(drivers::Ms5611Fault::adc_zero), 1u);
  EXPECT_TRUE(rig.qr.firmware.sample().health.barometer);
  rig.run(500);
  EXPECT_TRUE(rig.stage().barometer().healthy());
  EXPECT_GT(rig.stage().barometer().readings(), readings + 20);
  EXPECT_NE(rig.qr.firmware.sample().pressure_pa, 0);
}

// The FIFO: the driver reads the burst and never enables it, so the chip has nothing to overflow
// (overflow_fifo says so), and the samples go on as before, no fault counted.
TEST(SimI2c, AFifoOverflowChangesNothingTheDriverReadsTheBurst) {
  FaultRig rig;
  const uint32_t faults = rig.stage().imu().total_faults();
  const uint32_t samples = rig.stage().imu().samples();
  EXPECT_FALSE(rig.qr.board.mpu6050_chip().overflow_fifo());
  EXPECT_EQ(rig.qr.board.mpu6050().fifo_count(), 0u);
  rig.run(100);
  EXPECT_EQ(rig.stage().imu().total_faults(), faults);
  EXPECT_EQ(rig.stage().imu().samples(), samples + 100);
}
