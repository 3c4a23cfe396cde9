// The MPU-6050 at register level: the chip a firmware driver talks to over I2C, with the plant's
// IMU reading (sim/imu.hpp: the truth through the part's bias, scale error, vibration and noise,
// in physical units) behind its data registers.
//
// Sources, cited by register number (stable across revisions, where section numbers are not):
//   [RM]  InvenSense RM-MPU-6000A-00, "MPU-6000 and MPU-6050 Register Map and Descriptions".
//         Rev. 4.2 is the one to cite; the text quoted here was read in rev. 4.0 (03/09/2012).
//   [PS]  InvenSense PS-MPU-6000A-00, "MPU-6000 and MPU-6050 Product Specification" rev. 3.4.
//
// What it does, and where each behaviour comes from:
// - Register file and reset values: [RM] section 3, "The reset value is 0x00 for all registers
//   other than the registers below. Register 107: 0x40. Register 117: 0x68." (kMpu6050Registers).
//   Read-only registers ignore writes; bits the map marks reserved read 0; SIGNAL_PATH_RESET is
//   write-only and reads 0; an address the map does not list reads 0 and ignores writes.
// - Asleep after reset: [RM] section 4, "Note: The device will come up in sleep mode upon
//   power-up", and register 107's reset value 0x40 (SLEEP). Asleep, nothing is sampled, so the
//   data registers keep their reset value: every byte of 59..72 reads 0 until SLEEP is cleared
//   and the first sample is taken.
// - Time before it answers: [PS] section 6.3, "Start-Up Time for Register Read/Write", 20 ms
//   typical, 100 ms max. The model takes the maximum, and does not acknowledge its address until
//   then. [RM] register 107 says only that DEVICE_RESET "automatically clears to 0 once the reset
//   is done"; the model takes the same 100 ms for it (our reading: the reset is a power-up).
// - Sample rate: [RM] register 25, "Sample Rate = Gyroscope Output Rate / (1 + SMPLRT_DIV) where
//   Gyroscope Output Rate = 8kHz when the DLPF is disabled (DLPF_CFG = 0 or 7), and 1kHz when the
//   DLPF is enabled". The chip's sample clock starts when it is woken.
// - Data registers 59..72, big-endian two's complement, accel xyz, temperature, gyro xyz:
//   [RM] registers 59 to 72. Counts = the sensed value x the sensitivity of the full scale chosen
//   (FS_SEL: 131, 65.5, 32.8, 16.4 LSB per °/s; AFS_SEL: 16384, 8192, 4096, 2048 LSB per g),
//   rounded to the nearest count and saturated at int16 (sim::to_counts, the same conversion
//   sim::Imu::sample makes: at FS_SEL = 1 and AFS_SEL = 1 the model gives the very counts of the
//   present path). Temperature: [RM] registers 65 and 66, "Temperature in degrees C = (TEMP_OUT
//   Register Value as a signed quantity)/340 + 36.53", inverted. A burst read reads one sampling
//   instant ([RM] registers 59 to 64: the user-facing set is copied while the interface is idle).
// - Burst access: the register address increments after each byte, except at FIFO_R_W (116),
//   where a burst reads successive FIFO bytes.
// - INT_STATUS: [RM] register 58, "Each bit will clear after the register is read"; with
//   INT_PIN_CFG's INT_RD_CLEAR, "cleared on any read operation" (register 55). A status bit is set
//   only when its source is enabled in INT_ENABLE (register 56 "enables the Data Ready interrupt";
//   register 58's bit "sets to 1 when a Data Ready interrupt is generated": our reading).
// - The FIFO, 1024 bytes: [RM] register 116, "Data is written to the FIFO in order of register
//   number", so a record is accel (6 bytes), temperature (2), gyro x, y, z (2 each), each as its
//   FIFO_EN bit (register 35) says; "When the FIFO buffer has overflowed, the oldest data will be
//   lost and new data will be written to the FIFO" and FIFO_OFLOW_INT is set; "If the FIFO buffer
//   is empty, reading this register will return the last byte that was previously read". Register
//   106: FIFO_EN, "The FIFO buffer cannot be written to or read from while disabled"; FIFO_RESET
//   "resets the FIFO buffer when set to 1 while FIFO_EN equals 0" (the FIFO_EN bit of the same
//   write: 0x44 resets nothing). Registers 114 and 115: "Both registers are loaded with the
//   current sample count when FIFO_COUNT_H (Register 72) is read".
// - SIG_COND_RESET (register 106) clears the data registers; SIGNAL_PATH_RESET (104) does not.
// - Self-test: [RM] registers 13 to 16 hold the part's factory trim codes (XG_TEST.. bits 4:0,
//   XA_TEST.. split between bits 7:5 and register 16), which the map lists at reset value 0 but a
//   real part reads as programmed at the factory: the model's Mpu6050Trim, kept by a reset (our
//   reading). With an axis' self-test bit set ([RM] registers 27 and 28, bits 7:5) its output
//   shifts by the factory trim of its code, [RM] register 13's formulas (gyro 25 * 131 *
//   1.046^(code - 1) counts at ±250 °/s, negative on Y; accel 4096 * 0.34 * (0.92 / 0.34)^((code -
//   1) / 30) counts at ±8 g): the response of a part that matches its trim exactly, the noise and
//   vibration of the reading on top. Taken at the chip's sample instants like the rest of the
//   reading, in physical units, so it scales with whatever full scale is set. A fault scales an
//   axis' response (Mpu6050Faults).
//
// Its clock is the world's: sample() is told what the part senses each time the world samples
// (a control period). The data registers take that reading when at least one of the chip's own
// sample instants has passed since the last call (so SMPLRT_DIV slows them down), and the FIFO gets
// one record per sample instant passed, all of them that reading (held between the world's
// samples: at 8 kHz and a 1 kHz world, eight equal records a period).
//
// Not modelled: the DLPF's filtering and delay (the noise bandwidth is the vehicle file's
// imu_bandwidth_hz; the self-test's response steps in at the next sample), cycle mode and standby
// axes (PWR_MGMT_2), TEMP_DIS beyond holding the temperature, the clock source, motion detection,
// the auxiliary I2C master and its external sensor data, the DMP, the INT pin, the gyro's 30 ms
// settling after waking.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <optional>

#include <sim/i2c_device.hpp>
#include <sim/imu.hpp>

namespace sim {

namespace mpu6050 {

// Register addresses, [RM] section 3.
inline constexpr uint8_t kSmplrtDiv = 0x19;
inline constexpr uint8_t kConfig = 0x1A;
inline constexpr uint8_t kGyroConfig = 0x1B;
inline constexpr uint8_t kAccelConfig = 0x1C;
inline constexpr uint8_t kFifoEn = 0x23;
inline constexpr uint8_t kIntPinCfg = 0x37;
inline constexpr uint8_t kIntEnable = 0x38;
inline constexpr uint8_t kIntStatus = 0x3A;
inline constexpr uint8_t kAccelXoutH = 0x3B;  // 14 data bytes to GYRO_ZOUT_L, 0x48
inline constexpr uint8_t kTempOutH = 0x41;
inline constexpr uint8_t kGyroXoutH = 0x43;
inline constexpr uint8_t kSignalPathReset = 0x68;
inline constexpr uint8_t kUserCtrl = 0x6A;
inline constexpr uint8_t kPwrMgmt1 = 0x6B;
inline constexpr uint8_t kPwrMgmt2 = 0x6C;
inline constexpr uint8_t kFifoCountH = 0x72;
inline constexpr uint8_t kFifoCountL = 0x73;
inline constexpr uint8_t kFifoRW = 0x74;
inline constexpr uint8_t kWhoAmI = 0x75;
inline constexpr uint8_t kDataBytes = 14;

// Bits.
inline constexpr uint8_t kDeviceReset = 0x80, kSleep = 0x40, kTempDis = 0x08;  // PWR_MGMT_1
inline constexpr uint8_t kUserFifoEn = 0x40, kFifoReset = 0x04, kI2cMstReset = 0x02,
                         kSigCondReset = 0x01;                      // USER_CTRL
inline constexpr uint8_t kFifoOflowInt = 0x10, kDataRdyInt = 0x01;  // INT_ENABLE, INT_STATUS
inline constexpr uint8_t kIntRdClear = 0x10;                        // INT_PIN_CFG
inline constexpr uint8_t kTempFifo = 0x80, kXgFifo = 0x40, kYgFifo = 0x20, kZgFifo = 0x10,
                         kAccelFifo = 0x08;  // FIFO_EN

// Sensitivity per full-scale setting: [RM] registers 27 and 28 (and 59..72); [PS] 6.1, 6.2.
inline constexpr std::array<double, 4> kGyroLsbPerDps = {131.0, 65.5, 32.8, 16.4};         // FS_SEL 0..3
inline constexpr std::array<double, 4> kAccelLsbPerG = {16384.0, 8192.0, 4096.0, 2048.0};  // AFS_SEL 0..3
// [RM] registers 65 and 66: °C = TEMP_OUT / 340 + 36.53.
inline constexpr double kTempLsbPerC = 340.0;
inline constexpr double kTempOffsetC = 36.53;

enum class Access : uint8_t { read_write, read_only, write_only };

// One row per register of [RM] section 3: reset value, the bits a write can set (the rest are
// reserved, or read-only), and access.
struct Register {
  uint8_t address;
  const char* name;
  uint8_t reset;
  uint8_t writable;
  Access access;
};

inline constexpr Register kRegisters[] = {
    {0x0D, "SELF_TEST_X", 0x00, 0xFF, Access::read_write},  // the factory trim (Mpu6050Trim) in 0x0D..0x10
    {0x0E, "SELF_TEST_Y", 0x00, 0xFF, Access::read_write},
    {0x0F, "SELF_TEST_Z", 0x00, 0xFF, Access::read_write},
    {0x10, "SELF_TEST_A", 0x00, 0x3F, Access::read_write},
    {0x19, "SMPLRT_DIV", 0x00, 0xFF, Access::read_write},
    {0x1A, "CONFIG", 0x00, 0x3F, Access::read_write},        // EXT_SYNC_SET, DLPF_CFG
    {0x1B, "GYRO_CONFIG", 0x00, 0xF8, Access::read_write},   // XG_ST YG_ST ZG_ST, FS_SEL
    {0x1C, "ACCEL_CONFIG", 0x00, 0xF8, Access::read_write},  // XA_ST YA_ST ZA_ST, AFS_SEL
    {0x1F, "MOT_THR", 0x00, 0xFF, Access::read_write},
    {0x23, "FIFO_EN", 0x00, 0xFF, Access::read_write},
    {0x24, "I2C_MST_CTRL", 0x00, 0xFF, Access::read_write},
    {0x25, "I2C_SLV0_ADDR", 0x00, 0xFF, Access::read_write},
    {0x26, "I2C_SLV0_REG", 0x00, 0xFF, Access::read_write},
    {0x27, "I2C_SLV0_CTRL", 0x00, 0xFF, Access::read_write},
    {0x28, "I2C_SLV1_ADDR", 0x00, 0xFF, Access::read_write},
    {0x29, "I2C_SLV1_REG", 0x00, 0xFF, Access::read_write},
    {0x2A, "I2C_SLV1_CTRL", 0x00, 0xFF, Access::read_write},
    {0x2B, "I2C_SLV2_ADDR", 0x00, 0xFF, Access::read_write},
    {0x2C, "I2C_SLV2_REG", 0x00, 0xFF, Access::read_write},
    {0x2D, "I2C_SLV2_CTRL", 0x00, 0xFF, Access::read_write},
    {0x2E, "I2C_SLV3_ADDR", 0x00, 0xFF, Access::read_write},
    {0x2F, "I2C_SLV3_REG", 0x00, 0xFF, Access::read_write},
    {0x30, "I2C_SLV3_CTRL", 0x00, 0xFF, Access::read_write},
    {0x31, "I2C_SLV4_ADDR", 0x00, 0xFF, Access::read_write},
    {0x32, "I2C_SLV4_REG", 0x00, 0xFF, Access::read_write},
    {0x33, "I2C_SLV4_DO", 0x00, 0xFF, Access::read_write},
    {0x34, "I2C_SLV4_CTRL", 0x00, 0xFF, Access::read_write},
    {0x35, "I2C_SLV4_DI", 0x00, 0x00, Access::read_only},
    {0x36, "I2C_MST_STATUS", 0x00, 0x00, Access::read_only},
    {0x37, "INT_PIN_CFG", 0x00, 0xFE, Access::read_write},
    {0x38, "INT_ENABLE", 0x00, 0x59, Access::read_write},  // MOT_EN, FIFO_OFLOW_EN, I2C_MST_INT_EN, DATA_RDY_EN
    {0x3A, "INT_STATUS", 0x00, 0x00, Access::read_only},
    {0x3B, "ACCEL_XOUT_H", 0x00, 0x00, Access::read_only},
    {0x3C, "ACCEL_XOUT_L", 0x00, 0x00, Access::read_only},
    {0x3D, "ACCEL_YOUT_H", 0x00, 0x00, Access::read_only},
    {0x3E, "ACCEL_YOUT_L", 0x00, 0x00, Access::read_only},
    {0x3F, "ACCEL_ZOUT_H", 0x00, 0x00, Access::read_only},
    {0x40, "ACCEL_ZOUT_L", 0x00, 0x00, Access::read_only},
    {0x41, "TEMP_OUT_H", 0x00, 0x00, Access::read_only},
    {0x42, "TEMP_OUT_L", 0x00, 0x00, Access::read_only},
    {0x43, "GYRO_XOUT_H", 0x00, 0x00, Access::read_only},
    {0x44, "GYRO_XOUT_L", 0x00, 0x00, Access::read_only},
    {0x45, "GYRO_YOUT_H", 0x00, 0x00, Access::read_only},
    {0x46, "GYRO_YOUT_L", 0x00, 0x00, Access::read_only},
    {0x47, "GYRO_ZOUT_H", 0x00, 0x00, Access::read_only},
    {0x48, "GYRO_ZOUT_L", 0x00, 0x00, Access::read_only},
    {0x49, "EXT_SENS_DATA_00", 0x00, 0x00, Access::read_only},
    {0x4A, "EXT_SENS_DATA_01", 0x00, 0x00, Access::read_only},
    {0x4B, "EXT_SENS_DATA_02", 0x00, 0x00, Access::read_only},
    {0x4C, "EXT_SENS_DATA_03", 0x00, 0x00, Access::read_only},
    {0x4D, "EXT_SENS_DATA_04", 0x00, 0x00, Access::read_only},
    {0x4E, "EXT_SENS_DATA_05", 0x00, 0x00, Access::read_only},
    {0x4F, "EXT_SENS_DATA_06", 0x00, 0x00, Access::read_only},
    {0x50, "EXT_SENS_DATA_07", 0x00, 0x00, Access::read_only},
    {0x51, "EXT_SENS_DATA_08", 0x00, 0x00, Access::read_only},
    {0x52, "EXT_SENS_DATA_09", 0x00, 0x00, Access::read_only},
    {0x53, "EXT_SENS_DATA_10", 0x00, 0x00, Access::read_only},
    {0x54, "EXT_SENS_DATA_11", 0x00, 0x00, Access::read_only},
    {0x55, "EXT_SENS_DATA_12", 0x00, 0x00, Access::read_only},
    {0x56, "EXT_SENS_DATA_13", 0x00, 0x00, Access::read_only},
    {0x57, "EXT_SENS_DATA_14", 0x00, 0x00, Access::read_only},
    {0x58, "EXT_SENS_DATA_15", 0x00, 0x00, Access::read_only},
    {0x59, "EXT_SENS_DATA_16", 0x00, 0x00, Access::read_only},
    {0x5A, "EXT_SENS_DATA_17", 0x00, 0x00, Access::read_only},
    {0x5B, "EXT_SENS_DATA_18", 0x00, 0x00, Access::read_only},
    {0x5C, "EXT_SENS_DATA_19", 0x00, 0x00, Access::read_only},
    {0x5D, "EXT_SENS_DATA_20", 0x00, 0x00, Access::read_only},
    {0x5E, "EXT_SENS_DATA_21", 0x00, 0x00, Access::read_only},
    {0x5F, "EXT_SENS_DATA_22", 0x00, 0x00, Access::read_only},
    {0x60, "EXT_SENS_DATA_23", 0x00, 0x00, Access::read_only},
    {0x63, "I2C_SLV0_DO", 0x00, 0xFF, Access::read_write},
    {0x64, "I2C_SLV1_DO", 0x00, 0xFF, Access::read_write},
    {0x65, "I2C_SLV2_DO", 0x00, 0xFF, Access::read_write},
    {0x66, "I2C_SLV3_DO", 0x00, 0xFF, Access::read_write},
    {0x67, "I2C_MST_DELAY_CTRL", 0x00, 0x9F, Access::read_write},
    {0x68, "SIGNAL_PATH_RESET", 0x00, 0x07, Access::write_only},
    {0x69, "MOT_DETECT_CTRL", 0x00, 0x30, Access::read_write},
    {0x6A, "USER_CTRL", 0x00, 0x70,
     Access::read_write},  // FIFO_EN, I2C_MST_EN, I2C_IF_DIS; the resets clear themselves
    {0x6B, "PWR_MGMT_1", 0x40, 0x6F, Access::read_write},  // SLEEP, CYCLE, TEMP_DIS, CLKSEL; DEVICE_RESET clears itself
    {0x6C, "PWR_MGMT_2", 0x00, 0xFF, Access::read_write},
    {0x72, "FIFO_COUNTH", 0x00, 0x00, Access::read_only},
    {0x73, "FIFO_COUNTL", 0x00, 0x00, Access::read_only},
    {0x74, "FIFO_R_W", 0x00, 0xFF, Access::read_write},
    {0x75, "WHO_AM_I", 0x68, 0x00, Access::read_only},
};

// The row of `address`, or null for an address the map does not list.
const Register* find_register(uint8_t address);

inline constexpr uint8_t kSelfTestX = 0x0D;     // to SELF_TEST_A, 0x10
inline constexpr uint8_t kSelfTestBits = 0xE0;  // X_ST, Y_ST, Z_ST of GYRO_CONFIG and ACCEL_CONFIG

// The factory trim of a code (1..31; 0: none recorded, 0), [RM] register 13's formulas: counts at
// ±250 °/s (the gyro's, without the Y axis' minus) and at ±8 g.
double gyro_factory_trim(uint8_t code);
double accel_factory_trim(uint8_t code);

}  // namespace mpu6050

// A part's factory trim codes, 1..31 (5 bits; 0 is none recorded), by axis x, y, z. The default is
// a part of mid-range codes.
struct Mpu6050Trim {
  std::array<uint8_t, 3> gyro = {12, 17, 14};
  std::array<uint8_t, 3> accel = {18, 13, 15};
};

// Faults the chip can be told to show (the bus' own faults, NACK bursts and a stuck SDA, are the
// sim board's).
struct Mpu6050Faults {
  // WHO_AM_I reads this instead of 0x68: another part fitted (an MPU-6500 reads 0x70).
  std::optional<uint8_t> who_am_i;
  // The signal path freezes: the data registers stop updating (the FIFO repeats them, DATA_RDY
  // still comes), the failure a driver sees only as a signal that does not move.
  bool stuck_data = false;
  // Each axis' self-test response times this (1: as its trim says; 0: an axis that does not move;
  // a part that fails its self-test).
  std::array<double, 3> gyro_self_test_scale = {1, 1, 1};
  std::array<double, 3> accel_self_test_scale = {1, 1, 1};
};

class Mpu6050Model final : public I2cDevice {
 public:
  static constexpr uint8_t kAddressAd0Low = 0x68;   // AD0 low (the GY-86's)
  static constexpr uint8_t kAddressAd0High = 0x69;  // AD0 high
  static constexpr uint8_t kIdentity = 0x68;        // WHO_AM_I, whatever AD0 is
  static constexpr double kStartupS = 0.100;        // [PS] 6.3, maximum
  static constexpr size_t kFifoBytes = 1024;

  // Powered at `power_on_s`: it answers from power_on_s + kStartupS.
  explicit Mpu6050Model(uint8_t address = kAddressAd0Low, double power_on_s = 0);

  uint8_t address() const override { return address_; }
  I2cAck write(const uint8_t* bytes, size_t n, double t_s) override;
  I2cAck read(uint8_t* out, size_t n, double t_s) override;

  // What the part senses at `t_s` (Imu::sense: rates in rad/s, specific force in m/s²) and the
  // die's temperature, °C. Called each time the world samples; ignored while asleep or starting.
  void sample(double t_s, const ImuSense& sensed, double temperature_c);

  void set_faults(const Mpu6050Faults& faults) { faults_ = faults; }
  // The part's factory trim, in its registers from now on and after every reset.
  void set_trim(const Mpu6050Trim& trim);
  const Mpu6050Trim& trim() const { return trim_; }
  // Fills the FIFO past its 1024 bytes now with records of the present data (the oldest bytes
  // are lost, FIFO_OFLOW_INT is set if enabled), as a driver too slow to read it would find it.
  // False when the FIFO is not enabled or no data is selected for it (nothing can overflow).
  bool overflow_fifo();

  // Inspection for tests and the board, without the side effects of a read.
  bool answers(double t_s) const { return t_s >= ready_s_; }
  bool asleep() const { return (regs_[mpu6050::kPwrMgmt1] & mpu6050::kSleep) != 0; }
  uint8_t peek(uint8_t reg) const { return regs_[reg]; }
  size_t fifo_count() const { return fifo_size_; }
  double sample_rate_hz() const;
  double gyro_counts_per_rad_s() const;
  double accel_counts_per_m_s2() const;

 private:
  void reset(double t_s);
  // One byte written at the register pointer; false when the chip reset itself on it.
  bool write_register(uint8_t reg, uint8_t value, double t_s);
  uint8_t read_register(uint8_t reg);
  void advance_pointer();
  void take_sample(const ImuSense& sensed, double temperature_c);
  void put_trim();
  // What the part senses with the self-test bits as they are set: the response added.
  ImuSense with_self_test(const ImuSense& sensed) const;
  size_t fifo_record_bytes() const;
  void push_fifo_record();
  void push_fifo(uint8_t byte);
  void raise(uint8_t status_bit);

  uint8_t address_;
  std::array<uint8_t, 256> regs_{};
  uint8_t pointer_ = 0;
  double ready_s_ = 0;
  double next_sample_s_ = 0;  // the chip's next sample instant, while awake
  std::array<uint8_t, kFifoBytes> fifo_{};
  size_t fifo_head_ = 0;  // oldest byte
  size_t fifo_size_ = 0;
  uint8_t fifo_last_read_ = 0;
  uint16_t fifo_count_latch_ = 0;
  Mpu6050Faults faults_;
  Mpu6050Trim trim_;
};

}  // namespace sim
