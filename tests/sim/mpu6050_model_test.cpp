// The MPU-6050 register-level model (sim/mpu6050_model.hpp) through its I2C door, as a driver sees
// it: reset values, the start-up time, asleep until woken, burst access, the full scales, the
// counts a truth gives (the same as sim::Imu's at the default scales), the temperature, the sample
// rate and DATA_RDY, the FIFO and its overflow, the self-test, and the faults.
#include <gtest/gtest.h>

#include <stdint.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <sim/imu.hpp>
#include <sim/mpu6050_model.hpp>
#include <sim/random.hpp>
#include <sim/vehicle.hpp>

namespace {

using namespace sim::mpu6050;
using sim::I2cAck;
using sim::Mpu6050Model;

constexpr double kG = sim::kStandardGravity;
constexpr double kRadPerDeg = std::numbers::pi / 180;
constexpr double kAwake = Mpu6050Model::kStartupS;  // the first instant it answers after power-on at 0

uint8_t read_reg(Mpu6050Model& mpu, uint8_t reg, double t) {
  const uint8_t address = reg;
  EXPECT_EQ(mpu.write(&address, 1, t), I2cAck::ack);
  uint8_t value = 0;
  EXPECT_EQ(mpu.read(&value, 1, t), I2cAck::ack);
  return value;
}

std::vector<uint8_t> read_burst(Mpu6050Model& mpu, uint8_t reg, size_t n, double t) {
  const uint8_t address = reg;
  EXPECT_EQ(mpu.write(&address, 1, t), I2cAck::ack);
  std::vector<uint8_t> out(n);
  EXPECT_EQ(mpu.read(out.data(), n, t), I2cAck::ack);
  return out;
}

void write_reg(Mpu6050Model& mpu, uint8_t reg, uint8_t value, double t) {
  const uint8_t bytes[] = {reg, value};
  EXPECT_EQ(mpu.write(bytes, 2, t), I2cAck::ack);
}

int16_t int16_at(const std::vector<uint8_t>& bytes, size_t at) {
  return static_cast<int16_t>(static_cast<uint16_t>(bytes[at] << 8 | bytes[at + 1]));
}

struct Counts {
  int16_t accel[3], temperature, gyro[3];
};

Counts read_data(Mpu6050Model& mpu, double t) {
  const std::vector<uint8_t> b = read_burst(mpu, kAccelXoutH, kDataBytes, t);
  return {{int16_at(b, 0), int16_at(b, 2), int16_at(b, 4)},
          int16_at(b, 6),
          {int16_at(b, 8), int16_at(b, 10), int16_at(b, 12)}};
}

// Level at rest, 1 g up in specific force (z down: -g), no rotation.
const sim::ImuSense kLevelAtRest{{0, 0, 0}, {0, 0, -kG}};

// Powered at 0, answering at kAwake, woken then (PLL on the x gyro), sampling at 1 kHz
// (DLPF_CFG = 1, SMPLRT_DIV = 0).
Mpu6050Model awake_at_1khz() {
  Mpu6050Model mpu;
  write_reg(mpu, kConfig, 0x01, kAwake);
  write_reg(mpu, kPwrMgmt1, 0x01, kAwake);
  return mpu;
}

TEST(Mpu6050Model, EveryRegisterHasItsResetValue) {
  Mpu6050Model mpu;
  for (const Register& r : kRegisters) {
    if (r.address >= kSelfTestX && r.address < kSelfTestX + 4) continue;  // the factory trim: below
    const uint8_t expected = r.access == Access::write_only ? 0 : r.reset;
    EXPECT_EQ(read_reg(mpu, r.address, kAwake), expected) << r.name;
  }
  // [RM] section 3: 0x00 everywhere but PWR_MGMT_1 (asleep) and WHO_AM_I.
  EXPECT_EQ(read_reg(mpu, kPwrMgmt1, kAwake), 0x40);
  EXPECT_EQ(read_reg(mpu, kWhoAmI, kAwake), 0x68);
  // Addresses the map does not list read 0.
  for (const uint8_t unlisted : std::vector<uint8_t>{0x00, 0x0C, 0x11, 0x1D, 0x39, 0x61, 0x6D, 0x76, 0xFF}) {
    EXPECT_EQ(find_register(unlisted), nullptr);
    EXPECT_EQ(read_reg(mpu, unlisted, kAwake), 0) << int{unlisted};
  }
}

TEST(Mpu6050Model, AnswersOnlyAfterItsStartUpTimeAndAfterADeviceReset) {
  Mpu6050Model mpu(Mpu6050Model::kAddressAd0Low, 0.5);
  EXPECT_EQ(mpu.address(), 0x68);
  const uint8_t who = kWhoAmI;
  uint8_t value = 0;
  EXPECT_EQ(mpu.write(&who, 1, 0.5 + 0.099), I2cAck::address_nack);
  EXPECT_EQ(mpu.write(nullptr, 0, 0.5 + 0.099), I2cAck::address_nack) << "an address probe";
  EXPECT_EQ(mpu.read(&value, 1, 0.5 + 0.099), I2cAck::address_nack);
  EXPECT_EQ(value, 0xFF) << "nobody drives the line";
  EXPECT_EQ(mpu.write(nullptr, 0, 0.61), I2cAck::ack);
  EXPECT_EQ(read_reg(mpu, kWhoAmI, 0.61), 0x68);

  // DEVICE_RESET: every register back to its reset value, and 100 ms without an answer.
  write_reg(mpu, kSmplrtDiv, 7, 1.0);
  write_reg(mpu, kPwrMgmt1, 0x01, 1.0);
  EXPECT_FALSE(mpu.asleep());
  write_reg(mpu, kPwrMgmt1, kDeviceReset, 2.0);
  EXPECT_TRUE(mpu.asleep());
  EXPECT_EQ(mpu.write(&who, 1, 2.099), I2cAck::address_nack);
  EXPECT_EQ(read_reg(mpu, kSmplrtDiv, 2.11), 0);
  EXPECT_EQ(read_reg(mpu, kPwrMgmt1, 2.11), 0x40) << "DEVICE_RESET cleared itself, asleep again";
  // Bytes after the reset in the same write find it resetting.
  const uint8_t reset_then_more[] = {kPwrMgmt1, kDeviceReset, 0x01};
  EXPECT_EQ(mpu.write(reset_then_more, 3, 3.0), I2cAck::data_nack);

  Mpu6050Model other(Mpu6050Model::kAddressAd0High);
  EXPECT_EQ(other.address(), 0x69);
  EXPECT_EQ(read_reg(other, kWhoAmI, kAwake), 0x68) << "AD0 is not reflected in WHO_AM_I";
}

TEST(Mpu6050Model, AsleepTheDataRegistersReadZeroUntilItIsWoken) {
  Mpu6050Model mpu;
  for (int i = 0; i < 50; ++i) mpu.sample(kAwake + i * 1e-3, kLevelAtRest, 25.0);
  EXPECT_EQ(read_burst(mpu, kAccelXoutH, kDataBytes, 0.2), std::vector<uint8_t>(kDataBytes, 0));

  write_reg(mpu, kPwrMgmt1, 0x01, 0.2);  // SLEEP cleared; 8 kHz (DLPF off), first sample 125 us on
  mpu.sample(0.2 + 100e-6, kLevelAtRest, 25.0);
  EXPECT_EQ(read_data(mpu, 0.2001).accel[2], 0) << "no sample instant yet";
  mpu.sample(0.201, kLevelAtRest, 25.0);
  EXPECT_EQ(read_data(mpu, 0.201).accel[2], -16384) << "1 g at AFS_SEL = 0";

  // Asleep again, it holds what it had.
  write_reg(mpu, kPwrMgmt1, 0x41, 0.3);
  mpu.sample(0.301, sim::ImuSense{{0, 0, 0}, {0, 0, -2 * kG}}, 25.0);
  EXPECT_EQ(read_data(mpu, 0.301).accel[2], -16384);
}

TEST(Mpu6050Model, BurstsAutoIncrementTheRegisterAddress) {
  Mpu6050Model mpu = awake_at_1khz();
  // One write of four registers from SMPLRT_DIV, one read of them back.
  const uint8_t config[] = {kSmplrtDiv, 0x03, 0x02, 0x08, 0x10};
  EXPECT_EQ(mpu.write(config, sizeof config, 0.2), I2cAck::ack);
  EXPECT_EQ(read_burst(mpu, kSmplrtDiv, 4, 0.2), (std::vector<uint8_t>{0x03, 0x02, 0x08, 0x10}));
  EXPECT_EQ(read_reg(mpu, kGyroConfig, 0.2), 0x08);

  mpu.sample(0.25, sim::ImuSense{{0.1, -0.2, 0.3}, {1.0, -2.0, -kG}}, 30.0);
  const std::vector<uint8_t> burst = read_burst(mpu, kAccelXoutH, kDataBytes, 0.25);
  for (uint8_t i = 0; i < kDataBytes; ++i)
    EXPECT_EQ(read_reg(mpu, static_cast<uint8_t>(kAccelXoutH + i), 0.25), burst[i]);
  // A read continues from where the last one stopped.
  read_burst(mpu, kAccelXoutH, 6, 0.25);
  std::vector<uint8_t> temperature(2);
  EXPECT_EQ(mpu.read(temperature.data(), 2, 0.25), I2cAck::ack);
  EXPECT_EQ(temperature[0], burst[6]);
  EXPECT_EQ(temperature[1], burst[7]);
  // Reserved bits and read-only registers keep their values.
  write_reg(mpu, kGyroConfig, 0xFF, 0.3);
  EXPECT_EQ(read_reg(mpu, kGyroConfig, 0.3), 0xF8);
  write_reg(mpu, kWhoAmI, 0x00, 0.3);
  write_reg(mpu, kAccelXoutH, 0x12, 0.3);
  EXPECT_EQ(read_reg(mpu, kWhoAmI, 0.3), 0x68);
  EXPECT_EQ(read_reg(mpu, kAccelXoutH, 0.3), burst[0]);
}

TEST(Mpu6050Model, OneGOnZAtRestGivesTheCountTheSensitivitySays) {
  for (uint8_t afs = 0; afs < 4; ++afs) {
    Mpu6050Model mpu = awake_at_1khz();
    write_reg(mpu, kAccelConfig, static_cast<uint8_t>(afs << 3), 0.2);
    mpu.sample(0.21, kLevelAtRest, 25.0);
    const Counts c = read_data(mpu, 0.21);
    EXPECT_EQ(c.accel[2], -static_cast<int>(kAccelLsbPerG[afs])) << "AFS_SEL " << int{afs};
    EXPECT_EQ(c.accel[0], 0);
    EXPECT_EQ(c.accel[1], 0);
    EXPECT_EQ(c.gyro[0], 0);
  }
  // 1 °/s about x reads the gyro's sensitivity, rounded.
  for (uint8_t fs = 0; fs < 4; ++fs) {
    Mpu6050Model mpu = awake_at_1khz();
    write_reg(mpu, kGyroConfig, static_cast<uint8_t>(fs << 3), 0.2);
    mpu.sample(0.21, sim::ImuSense{{100 * kRadPerDeg, 0, 0}, {0, 0, -kG}}, 25.0);
    EXPECT_EQ(read_data(mpu, 0.21).gyro[0], static_cast<int>(std::lround(100 * kGyroLsbPerDps[fs])))
        << "FS_SEL " << int{fs};
  }
}

TEST(Mpu6050Model, TheFullScaleChangesTheCountsByItsFactorAndSaturates) {
  const sim::ImuSense truth{{0.7, -1.3, 2.9}, {3.1, -4.2, -9.5}};
  std::vector<Counts> at;
  for (uint8_t scale = 0; scale < 4; ++scale) {
    Mpu6050Model mpu = awake_at_1khz();
    write_reg(mpu, kGyroConfig, static_cast<uint8_t>(scale << 3), 0.2);
    write_reg(mpu, kAccelConfig, static_cast<uint8_t>(scale << 3), 0.2);
    mpu.sample(0.21, truth, 25.0);
    at.push_back(read_data(mpu, 0.21));
  }
  for (size_t scale = 1; scale < 4; ++scale) {
    for (int axis = 0; axis < 3; ++axis) {
      // Each step halves the accelerometer's counts exactly (within the rounding), the gyro's by
      // the ratio of the sensitivities (65.5 / 131, 32.8 / 65.5, 16.4 / 32.8).
      EXPECT_NEAR(at[scale].accel[axis], at[scale - 1].accel[axis] / 2.0, 1.0);
      EXPECT_NEAR(at[scale].gyro[axis], at[scale - 1].gyro[axis] * kGyroLsbPerDps[scale] / kGyroLsbPerDps[scale - 1],
                  1.0);
    }
  }
  // Beyond the full scale: int16's ends. At ±4 g (AFS_SEL = 1), 5 g saturates; ±2000 °/s holds 30 rad/s.
  Mpu6050Model mpu = awake_at_1khz();
  write_reg(mpu, kAccelConfig, 0x08, 0.2);
  mpu.sample(0.21, sim::ImuSense{{30, -30, 0}, {5 * kG, -5 * kG, 0}}, 25.0);
  Counts c = read_data(mpu, 0.21);
  EXPECT_EQ(c.accel[0], 32767);
  EXPECT_EQ(c.accel[1], -32768);
  EXPECT_EQ(c.gyro[0], 32767);
  EXPECT_EQ(c.gyro[1], -32768);
  write_reg(mpu, kGyroConfig, 0x18, 0.3);
  mpu.sample(0.31, sim::ImuSense{{30, -30, 0}, {0, 0, 0}}, 25.0);
  c = read_data(mpu, 0.31);
  EXPECT_EQ(c.gyro[0], std::lround(30 / kRadPerDeg * 16.4));
}

// The model fed Imu::sense() at FS_SEL = 1 and AFS_SEL = 1 reads what Imu::sample() gives today,
// count for count: the same part (bias, scale error), the same noise draws, the same rounding.
TEST(Mpu6050Model, AtTheDefaultFullScalesItGivesTheCountsOfTheImuPath) {
  EXPECT_EQ(kGyroLsbPerDps[1], sim::kGyroCountsPerDps);
  EXPECT_EQ(kAccelLsbPerG[1], sim::kAccelCountsPerG);
  const sim::VehicleParams v = sim::default_vehicle();
  sim::Imu today(v, sim::Random(7).stream(1));
  sim::Imu through_model(v, sim::Random(7).stream(1));
  Mpu6050Model mpu = awake_at_1khz();
  write_reg(mpu, kGyroConfig, 0x08, kAwake);
  write_reg(mpu, kAccelConfig, 0x08, kAwake);
  const sim::VibrationSample vibration{{0.3, 0.1, -0.2}, {0.01, -0.02, 0.005}};
  for (int k = 1; k <= 2000; ++k) {
    const double t = kAwake + k * 1e-3;
    const sim::Vec3 rate{std::sin(0.01 * k), 2 * std::cos(0.013 * k), 0.5 * std::sin(0.007 * k)};
    const sim::Vec3 force{3 * std::sin(0.02 * k), -2 * std::cos(0.011 * k), -kG + std::sin(0.05 * k)};
    const sim::ImuReading expected = today.sample(rate, force, vibration);
    mpu.sample(t, through_model.sense(rate, force, vibration), 25.0);
    const Counts c = read_data(mpu, t);
    for (size_t axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(c.gyro[axis], expected.gyro[axis]) << k << " " << axis;
      ASSERT_EQ(c.accel[axis], expected.accel[axis]) << k << " " << axis;
    }
  }
}

TEST(Mpu6050Model, TheTemperatureRegisterByTheRegisterMapsFormula) {
  Mpu6050Model mpu = awake_at_1khz();
  double t = 0.2;
  for (const double celsius : {-20.0, 0.0, 25.0, 36.53, 60.0}) {
    t += 0.01;
    mpu.sample(t, kLevelAtRest, celsius);
    const int16_t raw = read_data(mpu, t).temperature;
    EXPECT_EQ(raw, std::lround((celsius - 36.53) * 340)) << celsius;
    EXPECT_NEAR(raw / 340.0 + 36.53, celsius, 0.5 / 340) << celsius;
  }
  // TEMP_DIS holds it.
  write_reg(mpu, kPwrMgmt1, 0x01 | kTempDis, 0.5);
  mpu.sample(0.51, kLevelAtRest, 80.0);
  EXPECT_EQ(read_data(mpu, 0.51).temperature, std::lround((60.0 - 36.53) * 340));
}

TEST(Mpu6050Model, TheDataRegistersFollowTheSampleRateAndDataReadyTellsEachSample) {
  Mpu6050Model mpu = awake_at_1khz();
  EXPECT_DOUBLE_EQ(mpu.sample_rate_hz(), 1000.0);
  write_reg(mpu, kSmplrtDiv, 9, kAwake);  // 1 kHz / 10
  EXPECT_DOUBLE_EQ(mpu.sample_rate_hz(), 100.0);
  write_reg(mpu, kConfig, 0x00, kAwake);  // DLPF off: 8 kHz / 10
  EXPECT_DOUBLE_EQ(mpu.sample_rate_hz(), 800.0);
  write_reg(mpu, kConfig, 0x01, kAwake);

  // Without DATA_RDY_EN the status bit stays clear (our reading of registers 56 and 58).
  mpu.sample(0.2, kLevelAtRest, 25.0);
  EXPECT_EQ(read_reg(mpu, kIntStatus, 0.2), 0);

  write_reg(mpu, kIntEnable, kDataRdyInt, 0.2);
  int updates = 0, ready = 0;
  int16_t last = read_data(mpu, 0.2).accel[0];
  for (int k = 1; k <= 100; ++k) {
    const double t = 0.2 + k * 1e-3;
    mpu.sample(t, sim::ImuSense{{0, 0, 0}, {0.001 * k, 0, -kG}}, 25.0);
    const int16_t now = read_data(mpu, t).accel[0];
    if (now != last) ++updates;
    last = now;
    if (read_reg(mpu, kIntStatus, t) == kDataRdyInt) ++ready;
    EXPECT_EQ(read_reg(mpu, kIntStatus, t), 0) << "cleared by the read";
  }
  EXPECT_EQ(updates, 10) << "100 Hz in 100 ms";
  EXPECT_EQ(ready, 10);

  // INT_RD_CLEAR: any read clears it.
  write_reg(mpu, kIntPinCfg, kIntRdClear, 0.4);
  mpu.sample(0.42, kLevelAtRest, 25.0);
  EXPECT_EQ(mpu.peek(kIntStatus), kDataRdyInt);
  read_reg(mpu, kWhoAmI, 0.42);
  EXPECT_EQ(mpu.peek(kIntStatus), 0);
}

// FIFO with accel and gyro (12-byte records) at 1 kHz.
Mpu6050Model fifo_at_1khz() {
  Mpu6050Model mpu = awake_at_1khz();
  write_reg(mpu, kFifoEn, kAccelFifo | kXgFifo | kYgFifo | kZgFifo, kAwake);
  write_reg(mpu, kIntEnable, kFifoOflowInt, kAwake);
  write_reg(mpu, kUserCtrl, kUserFifoEn, kAwake);
  return mpu;
}

uint16_t fifo_count(Mpu6050Model& mpu, double t) {
  const std::vector<uint8_t> b = read_burst(mpu, kFifoCountH, 2, t);
  return static_cast<uint16_t>(b[0] << 8 | b[1]);
}

TEST(Mpu6050Model, TheFifoHoldsRecordsInRegisterOrderAndABurstReadsThemOneAfterAnother) {
  Mpu6050Model mpu = fifo_at_1khz();
  std::vector<std::vector<uint8_t>> records;
  for (int k = 1; k <= 5; ++k) {
    const double t = kAwake + k * 1e-3;
    mpu.sample(t, sim::ImuSense{{0.01 * k, 0.02 * k, 0.03 * k}, {0.1 * k, 0.2 * k, -kG}}, 25.0);
    const std::vector<uint8_t> data = read_burst(mpu, kAccelXoutH, kDataBytes, t);
    std::vector<uint8_t> record(data.begin(), data.begin() + 6);  // accel, no temperature
    record.insert(record.end(), data.begin() + 8, data.end());    // gyro x y z
    records.push_back(record);
  }
  EXPECT_EQ(fifo_count(mpu, 0.2), 60);
  // FIFO_COUNT_L alone is the value latched by the last FIFO_COUNT_H read.
  const std::vector<uint8_t> first_two = read_burst(mpu, kFifoRW, 24, 0.2);
  EXPECT_EQ(read_reg(mpu, kFifoCountL, 0.2), 60);
  EXPECT_EQ(fifo_count(mpu, 0.2), 36);
  EXPECT_EQ(std::vector<uint8_t>(first_two.begin(), first_two.begin() + 12), records[0]);
  EXPECT_EQ(std::vector<uint8_t>(first_two.begin() + 12, first_two.end()), records[1]);
  const std::vector<uint8_t> rest = read_burst(mpu, kFifoRW, 36, 0.2);
  EXPECT_EQ(std::vector<uint8_t>(rest.begin() + 24, rest.end()), records[4]);
  // Empty: the last byte read, again.
  EXPECT_EQ(read_burst(mpu, kFifoRW, 3, 0.2), std::vector<uint8_t>(3, records[4].back()));

  // At 8 kHz a 1 ms world sample brings eight records. (The chip sampled on while the world was
  // away: the FIFO is emptied after the first sample at the new rate.)
  write_reg(mpu, kConfig, 0x00, 0.3);
  mpu.sample(0.3, kLevelAtRest, 25.0);
  write_reg(mpu, kUserCtrl, kFifoReset, 0.3);
  write_reg(mpu, kUserCtrl, kUserFifoEn, 0.3);
  EXPECT_EQ(fifo_count(mpu, 0.3), 0);
  mpu.sample(0.301, kLevelAtRest, 25.0);
  EXPECT_EQ(fifo_count(mpu, 0.301), 8 * 12);

  // FIFO_RESET acts only with FIFO_EN cleared.
  write_reg(mpu, kUserCtrl, kUserFifoEn | kFifoReset, 0.31);
  EXPECT_EQ(fifo_count(mpu, 0.31), 8 * 12);
  EXPECT_EQ(read_reg(mpu, kUserCtrl, 0.31), kUserFifoEn) << "the reset bit clears itself";
  write_reg(mpu, kUserCtrl, kFifoReset, 0.31);
  EXPECT_EQ(fifo_count(mpu, 0.31), 0);
}

TEST(Mpu6050Model, AFifoNotReadInTimeOverflowsLosingTheOldestBytes) {
  Mpu6050Model mpu = fifo_at_1khz();
  // Records that differ: the gyro's y and z grow with k.
  const auto truth = [](int k) { return sim::ImuSense{{0, 0.5 + 0.01 * k, -0.5 - 0.01 * k}, {0, 0, -kG}}; };
  // 85 records of 12 bytes are 1020 bytes; the 86th makes 1032, and the 8 oldest are lost.
  mpu.sample(kAwake + 1e-3, truth(1), 25.0);
  const std::vector<uint8_t> first = read_burst(mpu, kAccelXoutH, kDataBytes, kAwake + 1e-3);
  ASSERT_EQ(first.size(), size_t{kDataBytes});
  for (int k = 2; k <= 85; ++k) mpu.sample(kAwake + k * 1e-3, truth(k), 25.0);
  EXPECT_EQ(fifo_count(mpu, 0.19), 1020);
  EXPECT_EQ(read_reg(mpu, kIntStatus, 0.19), 0);
  mpu.sample(kAwake + 0.086, truth(86), 25.0);
  EXPECT_EQ(fifo_count(mpu, 0.19), 1024) << "full, not more";
  EXPECT_EQ(read_reg(mpu, kIntStatus, 0.19), kFifoOflowInt);
  EXPECT_EQ(read_reg(mpu, kIntStatus, 0.19), 0) << "cleared by the read";
  // What is left starts at byte 8 of the first record (its gyro y, data registers 0x45 on), out
  // of step with the records from here on.
  const std::vector<uint8_t> head = read_burst(mpu, kFifoRW, 4, 0.19);
  EXPECT_EQ(head, (std::vector<uint8_t>{first[10], first[11], first[12], first[13]}));
  EXPECT_NE(first[10], 0);
}

TEST(Mpu6050Model, FaultsAWrongIdentityStuckDataAndAnOverflow) {
  Mpu6050Model mpu = fifo_at_1khz();
  sim::Mpu6050Faults wrong_part;
  wrong_part.who_am_i = 0x70;  // an MPU-6500
  mpu.set_faults(wrong_part);
  EXPECT_EQ(read_reg(mpu, kWhoAmI, 0.2), 0x70);
  mpu.set_faults({});
  EXPECT_EQ(read_reg(mpu, kWhoAmI, 0.2), 0x68);

  write_reg(mpu, kIntEnable, kFifoOflowInt | kDataRdyInt, 0.2);
  mpu.sample(0.201, kLevelAtRest, 25.0);
  const Counts before = read_data(mpu, 0.201);
  sim::Mpu6050Faults frozen;
  frozen.stuck_data = true;
  mpu.set_faults(frozen);
  mpu.sample(0.202, sim::ImuSense{{1, 2, 3}, {4, 5, 6}}, 40.0);
  const Counts stuck = read_data(mpu, 0.202);
  EXPECT_EQ(stuck.accel[2], before.accel[2]);
  EXPECT_EQ(stuck.gyro[0], before.gyro[0]);
  EXPECT_EQ(stuck.temperature, before.temperature);
  EXPECT_EQ(read_reg(mpu, kIntStatus, 0.202) & kDataRdyInt, kDataRdyInt) << "data ready still comes";
  mpu.set_faults({});
  mpu.sample(0.203, sim::ImuSense{{1, 2, 3}, {4, 5, 6}}, 40.0);
  EXPECT_NE(read_data(mpu, 0.203).gyro[0], before.gyro[0]);

  EXPECT_TRUE(mpu.overflow_fifo());
  EXPECT_EQ(fifo_count(mpu, 0.21), 1024);
  EXPECT_EQ(read_reg(mpu, kIntStatus, 0.21) & kFifoOflowInt, kFifoOflowInt);
  write_reg(mpu, kUserCtrl, 0x00, 0.22);
  EXPECT_FALSE(mpu.overflow_fifo()) << "a disabled FIFO cannot overflow";
}

// The factory trim in SELF_TEST_X..A as [RM] register 13 lays it out (the default part: gyro
// codes 12, 17, 14, accelerometer 18, 13, 15), kept by a reset; another part's when set.
TEST(Mpu6050Model, TheTrimRegistersHoldThePartsCodes) {
  Mpu6050Model mpu = awake_at_1khz();
  const std::vector<uint8_t> expected = {4 << 5 | 12, 3 << 5 | 17, 3 << 5 | 14, 2 << 4 | 1 << 2 | 3};
  EXPECT_EQ(read_burst(mpu, kSelfTestX, 4, 0.2), expected);
  write_reg(mpu, kPwrMgmt1, 0x80, 0.2);
  EXPECT_EQ(read_burst(mpu, kSelfTestX, 4, 0.31), expected) << "a reset keeps the factory's trim";
  mpu.set_trim({{31, 1, 0}, {31, 1, 0}});
  EXPECT_EQ(read_burst(mpu, kSelfTestX, 4, 0.31), (std::vector<uint8_t>{0xFF, 0x01, 0x00, 0x30 | 0x04}));
  // [RM] register 13's formulas at the ends of the codes: 25 °/s and 0.34 g at 1, 0.92 g at 31.
  EXPECT_DOUBLE_EQ(gyro_factory_trim(1), 3275.0);
  EXPECT_DOUBLE_EQ(accel_factory_trim(1), 4096 * 0.34);
  EXPECT_NEAR(accel_factory_trim(31), 4096 * 0.92, 1e-9);
  EXPECT_EQ(gyro_factory_trim(0), 0.0);
  EXPECT_EQ(accel_factory_trim(0), 0.0);
}

// The self-test bits shift each axis by its factory trim: at the self-test's full scales
// (±250 °/s, ±8 g) by the trim in counts (to the count: the rounding), the gyroscope's Y axis
// negative; at ±500 °/s by half as many counts (the response is physical). A fault's scale on an
// axis scales its response, that axis alone.
TEST(Mpu6050Model, TheSelfTestBitsShiftEachAxisByItsFactoryTrim) {
  Mpu6050Model mpu = awake_at_1khz();
  const sim::ImuSense still{{0.001, -0.002, 0.003}, {0.1, -0.2, -kG}};
  const auto response = [&](uint8_t gyro_config, uint8_t accel_config, double t) {
    write_reg(mpu, kGyroConfig, gyro_config, t);
    write_reg(mpu, kAccelConfig, accel_config, t);
    mpu.sample(t + 0.001, still, 25.0);
    const Counts off = read_data(mpu, t + 0.001);
    write_reg(mpu, kGyroConfig, gyro_config | kSelfTestBits, t + 0.001);
    write_reg(mpu, kAccelConfig, accel_config | kSelfTestBits, t + 0.001);
    mpu.sample(t + 0.002, still, 25.0);
    const Counts on = read_data(mpu, t + 0.002);
    std::array<int, 6> d{};
    for (size_t a = 0; a < 3; ++a) {
      d[a] = on.accel[a] - off.accel[a];
      d[3 + a] = on.gyro[a] - off.gyro[a];
    }
    return d;
  };
  const std::array<int, 6> st = response(0x00, 0x10, 0.2);
  const double trim[6] = {accel_factory_trim(18), accel_factory_trim(13), accel_factory_trim(15),
                          gyro_factory_trim(12),  -gyro_factory_trim(17), gyro_factory_trim(14)};
  for (size_t a = 0; a < 6; ++a) EXPECT_NEAR(st[a], trim[a], 1.0) << "axis " << a;
  EXPECT_LT(st[4], -4000);

  const std::array<int, 6> half = response(0x08, 0x08, 0.21);  // ±500 °/s, ±4 g
  for (size_t a = 0; a < 3; ++a)
    EXPECT_NEAR(half[a], 2 * trim[a], 2.0) << "axis " << a << ": ±4 g has twice the counts";
  for (size_t a = 3; a < 6; ++a) EXPECT_NEAR(half[a], trim[a] * 65.5 / 131, 1.0) << "axis " << a;

  sim::Mpu6050Faults broken;
  broken.gyro_self_test_scale = {0.5, 1, 1};
  mpu.set_faults(broken);
  const std::array<int, 6> bad = response(0x00, 0x10, 0.22);
  EXPECT_NEAR(bad[3], trim[3] / 2, 1.0);
  for (size_t a : {0u, 1u, 2u, 4u, 5u}) EXPECT_NEAR(bad[a], trim[a], 1.0) << "axis " << a;
}

TEST(Mpu6050Model, SignalConditionResetClearsTheDataRegisters) {
  Mpu6050Model mpu = awake_at_1khz();
  mpu.sample(0.21, kLevelAtRest, 25.0);
  EXPECT_NE(read_data(mpu, 0.21).accel[2], 0);
  write_reg(mpu, kSignalPathReset, 0x07, 0.22);
  EXPECT_NE(read_data(mpu, 0.22).accel[2], 0) << "SIGNAL_PATH_RESET does not clear the sensor registers";
  write_reg(mpu, kUserCtrl, kSigCondReset, 0.23);
  EXPECT_EQ(read_burst(mpu, kAccelXoutH, kDataBytes, 0.23), std::vector<uint8_t>(kDataBytes, 0));
}

}  // namespace
