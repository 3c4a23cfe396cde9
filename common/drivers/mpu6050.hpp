// The MPU-6050 (gyroscope and accelerometer) on an I2C bus (i2c.hpp), stepped once per tick and
// never waiting on the wire: each step collects the transfer the step before began and begins the
// next one.
//
// Start-up, one transfer a tick (kMpu6050Startup below, in order; [p]: at power-up only, see the
// self-test below):
//
//   write PWR_MGMT_1 = DEVICE_RESET          every register to its reset value
//   wait 100 ms                              the chip answers again (PS 6.3, see kResetWaitUs)
//   read WHO_AM_I, expect 0x68               else "wrong identity", and start over
//   write PWR_MGMT_1 = CLKSEL 1              out of sleep, clocked by the PLL on the X gyro
//   write SMPLRT_DIV, CONFIG, GYRO_CONFIG, ACCEL_CONFIG   one write, the address auto-increments
//   read the four back                       a register that did not keep its value: start over
//   [p] read SELF_TEST_X..A                  the factory trim (mpu6050_self_test.hpp)
//   [p] write GYRO_CONFIG, ACCEL_CONFIG = ±250 °/s, ±8 g, self-test off
//   read PWR_MGMT_1 back, wait 30 ms         the gyros settle (PS 6.1, see kGyroSettleUs)
//   [p] read the data, 8 ms of samples       self-test off
//   [p] write GYRO_CONFIG, ACCEL_CONFIG with every axis' self-test bit, wait for the filter
//   [p] read the data, 8 ms of samples       self-test on: each axis' response judged
//   [p] write GYRO_CONFIG, ACCEL_CONFIG as configured, read them back, wait for the filter
//
// then every tick the 14 data bytes, ACCEL_XOUT_H (0x3B) .. GYRO_ZOUT_L (0x48), in one burst read:
// accelerometer x, y, z, temperature, gyroscope x, y, z, each a big-endian two's complement
// 16-bit value. The chip copies its internal registers to the ones the bus reads only while the
// bus is idle, so one burst is one sampling instant (RM 4.17, 4.19). The burst a tick begins is
// collected by the next tick: a sample is one tick old when the flight sees it (`read_at_us`
// says when it was read). The chip samples on its own clock (1 kHz / (1 + SMPLRT_DIV) with the
// low-pass filter on), not on the tick's: with both at 1 kHz a read now and then finds the sample
// the read before found, or one newer than the next; the flight sees a rate held one tick.
//
// The self-test (RM 4.1; PS 6.1, 6.2; the arithmetic in mpu6050_self_test.hpp): each axis' output
// with its self-test bit set, less its output without, is the self-test response, and it must be
// within 14 % of the factory trim the part recorded. It needs the vehicle still: the response is
// a shift of 25 °/s or 0.34 g at the least, and a vehicle that turns or is shaken while its
// samples are taken shifts them as much. So it runs only in the start-up from power-up, on the
// ground with the engines off, and in that start-up's tries again after a bad answer; once the
// driver has streamed, a start-up (a sensor lost, perhaps in the air) skips its rows [p].
//
// 8 ms of samples each way (self_test_samples: 8 at 1 kHz, 4 at the 500 Hz build's rate, where a
// row's tick is 2 ms and eight made the IMU stream after the pilot's calibration at 0.3 s,
// docs/simulator.md section 6.1). The accelerometer's noise at DLPF_CFG 1 (400 µg/√Hz over
// 184 Hz, PS 6.2) is about 5.4 mg, 22 counts at ±8 g, and the mean of eight on less the mean of
// eight off has 11 (22 √(2/8)), 0.8 % of the smallest trim (1393 counts, code 1) against the
// 14 % allowed (of four: 16, 1.1 %); the gyroscope's (0.005 °/s/√Hz over 188 Hz, PS 6.1: 9 counts
// at ±250 °/s) is smaller still against 3275. A vehicle bumped while it self-tests is what no
// count averages away, and each more sample costs a tick before the IMU streams.
//
// Its scales are set while the gyros settle, so the samples without need no wait of their own;
// with the bits set, and again once the configured scales are back, the filter's output settles
// before a sample is taken (mpu6050::filter_settle_us: 9.8 ms at DLPF_CFG 1), or the flight's
// first samples would carry the response. A response out of bounds is a `self_test` fault: the
// start-up starts over after kRetryDelayUs, as for a wrong identity, and the IMU never becomes
// healthy. At 1 kHz the self-test adds 41 ticks, 41 ms, to the start-up (the first burst at tick
// 177 after the first reset, not 136): 20 transfers and two waits for the filter.
//
// Why the burst read and not the FIFO: the control loop takes one sample a tick and the sample
// rate equals the control rate, so there is nothing to buffer; the FIFO would cost a FIFO_COUNT
// read before each data read (two transfers a tick) and an overflow to handle, for samples the
// loop does not use. The FIFO (FIFO_EN 0x23, USER_CTRL 0x6A, FIFO_COUNT 0x72, FIFO_R_W 0x74,
// FIFO_OFLOW_INT in INT_STATUS) is for a loop slower than the sample rate; not done here, and so
// no FIFO overflow can happen.
//
// The data-ready interrupt (DATA_RDY_EN, bit 0 of INT_ENABLE 0x38; DATA_RDY_INT, bit 0 of
// INT_STATUS 0x3A) is left off, INT_ENABLE at its reset value 0: no board has the INT pin wired.
// A board that has one would write DATA_RDY_EN and begin the burst on the pin's edge, which also
// ends the beat between the two clocks.
//
// Bad answers are counted by kind (Mpu6050Fault) for the console, and the flight reads healthy():
//   - at start-up any bad answer starts over from the reset after kRetryDelayUs (so a missing chip
//     costs one 29-bit write, 73 us, each 100 ms, not one every tick);
//   - streaming, a failed read leaves the last sample in place, not fresh, and healthy() false;
//     kLostAfterFailures failed reads in a row and the sensor is lost: counted, and the driver
//     starts over from the reset at once (without the self-test).
// The bus is assumed to be the driver's alone: poll() answers for the transfer this driver began.
// Two devices on one wire: each driver is given its own channel of a shared bus (I2cChannel, i2c.hpp).
//
// Sources (facts only, no code): InvenSense "MPU-6000 and MPU-6050 Register Map and Descriptions"
// RM-MPU-6000A-00 rev. 4.2 (RM): section 3 (the register map; reset values 0x00 but PWR_MGMT_1 0x40
// and WHO_AM_I 0x68), 4.1 (SELF_TEST_X..A: the trim codes, the self-test's full scales, the
// factory trim's formulas), 4.2 (SMPLRT_DIV, sample rate = gyro output rate / (1 + SMPLRT_DIV), the
// gyro output rate 8 kHz with DLPF_CFG 0 or 7, else 1 kHz; accelerometer 1 kHz), 4.3 (CONFIG,
// DLPF_CFG bits 2:0, 7 reserved; each setting's bandwidth and delay), 4.4 (GYRO_CONFIG, XG_ST..ZG_ST
// bits 7:5, FS_SEL bits 4:3), 4.5 (ACCEL_CONFIG, XA_ST..ZA_ST bits 7:5, AFS_SEL bits 4:3), 4.15,
// 4.16 (INT_ENABLE, INT_STATUS: DATA_RDY bit 0, FIFO_OFLOW bit 4), 4.17-4.19 (the data registers,
// their sensitivities per full scale, TEMP_OUT / 340 + 36.53 °C), 4.28 (PWR_MGMT_1: DEVICE_RESET
// bit 7, clears itself; SLEEP bit 6; CLKSEL bits 2:0, 1 = PLL with the X gyro as reference, "highly
// recommended" over the internal oscillator), 4.32 (WHO_AM_I: bits 6:1 of the address, 0x68
// whatever AD0). "MPU-6000 and MPU-6050 Product Specification" PS-MPU-6000A-00 rev. 3.4 (PS): 6.1
// (gyro sensitivity 131, 65.5, 32.8, 16.4 LSB/(°/s); start-up time, zero-rate output settled to
// ±1 °/s, 30 ms; self-test response within ±14 % of the factory trim; rate noise 0.005 °/s/√Hz),
// 6.2 (accelerometer 16384, 8192, 4096, 2048 LSB/g; self-test response likewise; noise 400
// µg/√Hz), 6.3 (temperature sensor range -40 to +85 °C; start-up time for register read/write
// 20 ms typical, 100 ms at most), 6.4 (I2C address 1101000 with AD0 low, 1101001 high; 400 kHz),
// 7.8 (flat on a surface the accelerometer reads +1 g on Z), 9.3 (a write of several bytes
// continues at the next register; a burst read likewise).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/drivers/i2c.hpp>
#include <common/drivers/mpu6050_self_test.hpp>

namespace drivers {

namespace mpu6050 {

inline constexpr uint8_t kAddressAd0Low = 0x68;   // PS 6.4
inline constexpr uint8_t kAddressAd0High = 0x69;  // AD0 tied high

// Registers (RM section 3).
inline constexpr uint8_t kSmplrtDiv = 0x19;    // 25
inline constexpr uint8_t kConfig = 0x1A;       // 26, DLPF_CFG bits 2:0
inline constexpr uint8_t kGyroConfig = 0x1B;   // 27, FS_SEL bits 4:3
inline constexpr uint8_t kAccelConfig = 0x1C;  // 28, AFS_SEL bits 4:3
inline constexpr uint8_t kIntEnable = 0x38;    // 56 (left at 0: no data-ready pin, see the head)
inline constexpr uint8_t kIntStatus = 0x3A;    // 58
inline constexpr uint8_t kAccelXoutH = 0x3B;   // 59, first of the 14 data bytes
inline constexpr uint8_t kTempOutH = 0x41;     // 65
inline constexpr uint8_t kGyroXoutH = 0x43;    // 67
inline constexpr uint8_t kGyroZoutL = 0x48;    // 72, last of the 14
inline constexpr uint8_t kPwrMgmt1 = 0x6B;     // 107
inline constexpr uint8_t kWhoAmI = 0x75;       // 117

// Bits and values.
inline constexpr uint8_t kDeviceReset = 0x80;      // PWR_MGMT_1 bit 7
inline constexpr uint8_t kSleep = 0x40;            // PWR_MGMT_1 bit 6, set by a reset
inline constexpr uint8_t kClkselPllXGyro = 0x01;   // PWR_MGMT_1 CLKSEL = 1
inline constexpr uint8_t kPwrMgmt1Reset = 0x40;    // its value after a reset: asleep, 8 MHz clock
inline constexpr uint8_t kIdentity = 0x68;         // WHO_AM_I
inline constexpr uint8_t kFullScaleShift = 3;      // FS_SEL, AFS_SEL: bits 4:3
inline constexpr uint8_t kDlpfReserved = 7;        // DLPF_CFG 7 is reserved
inline constexpr uint8_t kDataReadyInt = 0x01;     // INT_ENABLE DATA_RDY_EN, INT_STATUS DATA_RDY_INT
inline constexpr uint8_t kFifoOverflowInt = 0x10;  // INT_ENABLE FIFO_OFLOW_EN, INT_STATUS FIFO_OFLOW_INT
inline constexpr uint8_t kDataBytes = 14;
static_assert(kGyroZoutL - kAccelXoutH + 1 == kDataBytes);
static_assert(kDataBytes <= kI2cMaxRead);

// The running value of PWR_MGMT_1: awake (SLEEP 0, CYCLE 0), temperature sensor on (TEMP_DIS 0),
// clocked by the PLL on the X gyro.
inline constexpr uint8_t kPwrMgmt1Run = kClkselPllXGyro;

// Sensitivities by FS_SEL and AFS_SEL (PS 6.1, 6.2); the gyro's in tenths of a count per °/s.
inline constexpr uint16_t kGyroCountsPerDpsX10[4] = {1310, 655, 328, 164};
inline constexpr uint16_t kAccelCountsPerG[4] = {16384, 8192, 4096, 2048};

// The temperature sensor: °C = TEMP_OUT / 340 + 36.53 (RM 4.18), specified from -40 to +85 °C
// (PS 6.3). A reading outside that range is counted as a value that cannot be: the chip is not
// specified to work there, so its other readings cannot be trusted either. The bounds in counts,
// -26020.2 and 16479.8, rounded inwards.
inline constexpr int32_t kTempCountsPerDegree = 340;
inline constexpr int32_t kTempOffsetCentiDegrees = 3653;
inline constexpr int32_t kTempMinCentiDegrees = -4000;
inline constexpr int32_t kTempMaxCentiDegrees = 8500;
inline constexpr int16_t kTempMinCounts = static_cast<int16_t>((kTempMinCentiDegrees - kTempOffsetCentiDegrees) *
                                                               kTempCountsPerDegree / 100);
inline constexpr int16_t kTempMaxCounts = static_cast<int16_t>((kTempMaxCentiDegrees - kTempOffsetCentiDegrees) *
                                                               kTempCountsPerDegree / 100);
static_assert(kTempMinCounts == -26020 && kTempMaxCounts == 16479);

constexpr int32_t temperature_centi_degrees(int16_t counts) {
  return counts * 100 / kTempCountsPerDegree + kTempOffsetCentiDegrees;
}

// Times. After DEVICE_RESET the documents give the chip no time of its own; the start-up time for
// register access is 20 ms typical, 100 ms at most (PS 6.3), and we wait the most. The gyros' zero
// rate settles within 30 ms of start-up (PS 6.1), counted from the read-back of the power register.
inline constexpr uint32_t kResetWaitUs = 100000;
inline constexpr uint32_t kGyroSettleUs = 30000;
// After a bad answer at start-up, the reset is tried again this much later.
inline constexpr uint32_t kRetryDelayUs = 100000;

// The self-test's samples each way span this much, at most this many (see the head: the noise of
// their mean against the 14 %, and the time before the IMU streams).
inline constexpr uint32_t kSelfTestSpanUs = 8000;
inline constexpr uint8_t kSelfTestMaxSamples = 8;

// The low-pass filter by DLPF_CFG (RM 4.3): the narrower bandwidth of the accelerometer's and the
// gyroscope's, Hz, and the longer delay, us.
struct LowPassFilter {
  uint16_t bandwidth_hz;
  uint16_t delay_us;
};
inline constexpr LowPassFilter kLowPassFilters[7] = {{256, 980}, {184, 2000}, {94, 3000}, {42, 4900},
                                                     {20, 8500}, {10, 13800}, {5, 19000}};

// Time for the filter's output to follow a step (a self-test bit set or cleared, a full scale
// changed): its delay and nine time constants of a first-order filter at its bandwidth, 9 / (2 pi
// bandwidth) = 1 432 395 us·Hz / bandwidth (our model of a filter the documents give only these
// two figures of). e^-9 is 1.2e-4: the largest response, 12 623 counts, is left a count or two.
constexpr uint32_t filter_settle_us(uint8_t dlpf) {
  const LowPassFilter& f = kLowPassFilters[dlpf < 7 ? dlpf : 0];
  return f.delay_us + 1432395u / f.bandwidth_hz;
}
static_assert(filter_settle_us(1) == 9784);

// Failed reads in a row before the sensor is declared lost and started over: 10 ticks, 10 ms at the
// default 1 kHz control rate, 20 ms at 500 Hz. Fewer would restart the chip, which costs at least
// 130 ms without samples (the reset wait and the gyros' settling), for a glitch the estimator rides
// through on its last rates: one NACK or one stuck transfer is a single tick. More would fly on
// rates held too long: at 500 °/s (FS_SEL 1's full scale) 10 ms held is 5° of attitude.
inline constexpr uint8_t kLostAfterFailures = 10;

}  // namespace mpu6050

// The chip's axes to the body's (x forward, y right, z down; docs/conventions.md): body axis i is
// `sign[i]` times chip axis `chip_axis[i]`, the same for the gyroscope and the accelerometer. A
// rotation only (a permutation with signs whose determinant is +1): a mirror is a wiring mistake
// and is refused. The orientation parameter of issue 33 fills this in; until then the table below.
struct ChipToBody {
  uint8_t chip_axis[3] = {0, 1, 2};
  int8_t sign[3] = {1, 1, 1};
};

// The chip flat, component side up, its X arrow forward: chip y points left and chip z up, so body
// (x, y, z) = (chip x, -chip y, -chip z). Flat and still it reads +1 g on chip Z (PS 7.8), -1 g on
// body z, as docs/conventions.md wants at rest. (A half turn about x: its own inverse.)
inline constexpr ChipToBody kChipFlatXForward = {{0, 1, 2}, {1, -1, -1}};

struct Mpu6050Config {
  uint8_t address = mpu6050::kAddressAd0Low;
  // Sample rate = 1 kHz / (1 + divider) with the low-pass filter on (DLPF_CFG 1..6), 8 kHz / (1 +
  // divider) with it off (0). 0: 1 kHz, the default control rate; 1 for a 500 Hz loop.
  uint8_t sample_rate_divider = 0;
  // DLPF_CFG (RM 4.3), 0..6: 1 is 184 Hz accelerometer, 188 Hz gyro bandwidth, about 2 ms of delay,
  // under the Nyquist frequency of both a 1 kHz and a 500 Hz sample rate.
  uint8_t dlpf = 1;
  // FS_SEL and AFS_SEL, 0..3: ±500 °/s and ±4 g, the scales qr/core/sensor_scale.hpp assumes.
  uint8_t gyro_full_scale = 1;
  uint8_t accel_full_scale = 1;
  ChipToBody chip_to_body = kChipFlatXForward;
};

// A configuration the chip can take: its address, DLPF_CFG not reserved, full scales 0..3, and the
// axis table a rotation.
bool valid(const Mpu6050Config& config);

// Samples per second the chip makes with this configuration.
constexpr uint32_t mpu6050_sample_rate_hz(const Mpu6050Config& config) {
  const uint32_t output = (config.dlpf == 0 || config.dlpf == mpu6050::kDlpfReserved) ? 8000u : 1000u;
  return output / (1u + config.sample_rate_divider);
}

// The self-test's samples each way: those the chip makes in kSelfTestSpanUs (a burst a tick, and
// a sample a tick: the sample rate is the control rate), 1 to kSelfTestMaxSamples.
constexpr uint8_t self_test_samples(const Mpu6050Config& config) {
  const uint32_t n = mpu6050_sample_rate_hz(config) * mpu6050::kSelfTestSpanUs / 1000000u;
  if (n < 1u) return 1;
  if (n > mpu6050::kSelfTestMaxSamples) return mpu6050::kSelfTestMaxSamples;
  return static_cast<uint8_t>(n);
}

// The 14 data bytes decoded, in the chip's axes.
struct Mpu6050Raw {
  int16_t accel[3] = {0, 0, 0};
  int16_t temperature = 0;
  int16_t gyro[3] = {0, 0, 0};
};

Mpu6050Raw decode_mpu6050_data(const uint8_t (&bytes)[mpu6050::kDataBytes]);

// A chip vector in body axes. Negating -32768 saturates to 32767.
void chip_to_body(const ChipToBody& map, const int16_t (&chip)[3], int16_t (&body)[3]);

// One sample in body axes, counts at the configured full scales.
struct Mpu6050Sample {
  int16_t accel[3] = {0, 0, 0};
  int16_t gyro[3] = {0, 0, 0};
  int16_t temperature = 0;  // counts: temperature_centi_degrees() converts
  uint32_t read_at_us = 0;  // when the burst was begun: one tick before it was collected
};

enum class Mpu6050Fault : uint8_t {
  wrong_identity,     // WHO_AM_I did not read 0x68: another chip, or none that answers right
  address_nack,       // nobody acknowledged the address
  data_nack,          // a byte written was refused
  bus_stuck,          // SDA held low: the transfer could not start or finish
  readback_mismatch,  // a configuration register read back other than written
  impossible_value,   // a burst of all 0x00 or all 0xFF, a temperature outside -40..85 °C, or a
                      // reply of another length than asked
  bus_refused,        // begin() refused: the bus was busy with another transfer
  no_answer,          // the transfer still on the wire at the next tick, or forgotten by the bus
  self_test,          // an axis' self-test response not within 14 % of its factory trim (or no trim)
  count_,
};
inline constexpr size_t kMpu6050FaultKinds = static_cast<size_t>(Mpu6050Fault::count_);
inline constexpr const char* kMpu6050FaultNames[] = {
    "wrong identity",   "address NACK", "data NACK", "bus stuck", "config readback",
    "impossible value", "bus refused",  "no answer", "self-test",
};
static_assert(sizeof(kMpu6050FaultNames) / sizeof(kMpu6050FaultNames[0]) == kMpu6050FaultKinds);

// The start-up sequence, one transfer a row, in order; each row's transfer is begun by one tick and
// collected by the next. A write sends the row's bytes from register `reg` on; a read reads
// `count` bytes from there and compares them with the row's bytes, or keeps them (the trim, the
// self-test's samples: their rows repeat, self_test_samples() transfers, a tick each).
enum class Mpu6050StartupBytes : uint8_t {
  reset,          // DEVICE_RESET
  identity,       // 0x68
  run,            // kPwrMgmt1Run
  configuration,  // SMPLRT_DIV, CONFIG, GYRO_CONFIG, ACCEL_CONFIG from the configuration
  scales,         // GYRO_CONFIG, ACCEL_CONFIG from the configuration
  self_test_off,  // GYRO_CONFIG, ACCEL_CONFIG at the self-test's full scales
  self_test_on,   // the same with every axis' self-test bit
  trim,           // read: SELF_TEST_X..A, kept
  samples_off,    // read: the 14 data bytes, subtracted from the self-test's sums
  samples_on,     // read: the 14 data bytes, added to them; the last one judges
};
enum class Mpu6050Wait : uint8_t {
  none,
  reset,   // kResetWaitUs
  settle,  // the gyros settle, and the filter's output with them: the longer of kGyroSettleUs and
           // filter_settle_us
  filter,  // filter_settle_us
};
struct Mpu6050StartupRow {
  uint8_t reg;
  uint8_t count;
  bool read;
  Mpu6050StartupBytes bytes;
  bool power_up_only;      // the self-test's: skipped once the driver has streamed
  Mpu6050Wait wait_after;  // before the next row (or the first burst)
};
inline constexpr Mpu6050StartupRow kMpu6050Startup[] = {
    {mpu6050::kPwrMgmt1, 1, false, Mpu6050StartupBytes::reset, false, Mpu6050Wait::reset},
    {mpu6050::kWhoAmI, 1, true, Mpu6050StartupBytes::identity, false, Mpu6050Wait::none},
    {mpu6050::kPwrMgmt1, 1, false, Mpu6050StartupBytes::run, false, Mpu6050Wait::none},
    {mpu6050::kSmplrtDiv, 4, false, Mpu6050StartupBytes::configuration, false, Mpu6050Wait::none},
    {mpu6050::kSmplrtDiv, 4, true, Mpu6050StartupBytes::configuration, false, Mpu6050Wait::none},
    {mpu6050::kSelfTestX, 4, true, Mpu6050StartupBytes::trim, true, Mpu6050Wait::none},
    {mpu6050::kGyroConfig, 2, false, Mpu6050StartupBytes::self_test_off, true, Mpu6050Wait::none},
    {mpu6050::kPwrMgmt1, 1, true, Mpu6050StartupBytes::run, false, Mpu6050Wait::settle},
    {mpu6050::kAccelXoutH, mpu6050::kDataBytes, true, Mpu6050StartupBytes::samples_off, true, Mpu6050Wait::none},
    {mpu6050::kGyroConfig, 2, false, Mpu6050StartupBytes::self_test_on, true, Mpu6050Wait::filter},
    {mpu6050::kAccelXoutH, mpu6050::kDataBytes, true, Mpu6050StartupBytes::samples_on, true, Mpu6050Wait::none},
    {mpu6050::kGyroConfig, 2, false, Mpu6050StartupBytes::scales, true, Mpu6050Wait::none},
    {mpu6050::kGyroConfig, 2, true, Mpu6050StartupBytes::scales, true, Mpu6050Wait::filter},
};
inline constexpr uint8_t kMpu6050StartupRows = sizeof(kMpu6050Startup) / sizeof(kMpu6050Startup[0]);
// The four configuration registers are consecutive, so one write and one read cover them; so are
// the two full scales, and the four trim registers.
static_assert(mpu6050::kAccelConfig - mpu6050::kSmplrtDiv + 1 == 4);
static_assert(mpu6050::kAccelConfig == mpu6050::kGyroConfig + 1);
static_assert(mpu6050::kSelfTestX + mpu6050::kTrimRegisters == 0x11);
// Streaming begins when a wait ends (Mpu6050::collect), so the last row waits; so does the last row
// that is not the self-test's, where a start-up without it ends.
static_assert(kMpu6050Startup[kMpu6050StartupRows - 1].wait_after != Mpu6050Wait::none);

enum class Mpu6050Phase : uint8_t {
  refused,    // the configuration is not valid(): the bus is never touched
  starting,   // the start-up sequence (or waiting to start it again)
  streaming,  // one burst read a tick
};

class Mpu6050 {
 public:
  explicit Mpu6050(const Mpu6050Config& config = {});

  // One tick: collect what the last tick began, begin the next transfer if one is due.
  template <I2cBus Bus>
  void step(Bus& bus, uint32_t now_us) {
    I2cReply reply;
    const I2cResult result = bus.poll(reply);
    collect(result, reply, now_us);
    I2cTransfer transfer;
    if (next_transfer(now_us, transfer)) began(transfer, bus.begin(transfer), now_us);
  }

  // The step's three parts, in this order each tick (step() calls them; tests may too).
  void collect(I2cResult result, const I2cReply& reply, uint32_t now_us);
  bool next_transfer(uint32_t now_us, I2cTransfer& transfer) const;
  void began(const I2cTransfer& transfer, bool accepted, uint32_t now_us);

  Mpu6050Phase phase() const { return phase_; }
  // Streaming and this tick's read was good: the sample is fresh (and one tick old).
  bool healthy() const { return phase_ == Mpu6050Phase::streaming && fresh_; }
  bool fresh() const { return fresh_; }
  // The last good sample (zeros before the first).
  const Mpu6050Sample& sample() const { return sample_; }

  uint32_t fault_count(Mpu6050Fault kind) const { return faults_[static_cast<size_t>(kind)]; }
  uint32_t total_faults() const;
  Mpu6050Fault last_fault() const { return last_fault_; }
  bool any_fault() const { return total_faults() > 0; }
  uint8_t consecutive_failures() const { return consecutive_failures_; }
  // Times a streaming sensor was declared lost; times the start-up began again for any reason.
  uint32_t lost_count() const { return lost_; }
  uint32_t restart_count() const { return restarts_; }
  uint32_t samples() const { return samples_; }
  // Self-tests judged, and the axes the last one failed (mpu6050::self_test_failures: bit 0
  // accelerometer x .. bit 5 gyroscope z; 0 when it passed).
  uint32_t self_tests() const { return self_tests_; }
  uint8_t self_test_failures() const { return self_test_failures_; }

  // Bits and time on the wire of what this tick began (0 when nothing): i2c.hpp's count.
  uint32_t bus_bits_this_tick() const { return tick_bits_; }
  uint32_t bus_time_ns_this_tick(uint32_t bus_hz) const;

  const Mpu6050Config& config() const { return config_; }

 private:
  enum class InFlight : uint8_t { none, current, stale };

  void collect_startup(const I2cReply& reply, uint32_t now_us);
  bool take_startup_read(const Mpu6050StartupRow& row, const I2cReply& reply, uint32_t now_us);
  bool take_self_test_sample(const Mpu6050Raw& raw, int32_t sign, bool last, uint32_t now_us);
  void next_row(const Mpu6050StartupRow& done, uint32_t now_us);
  void collect_burst(const I2cReply& reply, uint32_t now_us);
  void fail(Mpu6050Fault kind, uint32_t now_us);
  void restart(uint32_t now_us, uint32_t delay_us);
  const uint8_t* startup_bytes(uint8_t row) const;
  uint32_t wait_us(Mpu6050Wait wait) const;
  uint8_t transfers_of(const Mpu6050StartupRow& row) const;

  Mpu6050Config config_;
  uint8_t configuration_[4] = {};  // SMPLRT_DIV, CONFIG, GYRO_CONFIG, ACCEL_CONFIG as written
  Mpu6050Phase phase_ = Mpu6050Phase::refused;
  uint8_t row_ = 0;  // the start-up row next or on the wire
  InFlight in_flight_ = InFlight::none;
  uint32_t begun_at_us_ = 0;
  uint32_t not_before_us_ = 0;
  bool waiting_ = false;  // not_before_us_ holds
  bool fresh_ = false;
  uint8_t consecutive_failures_ = 0;
  uint32_t tick_bits_ = 0;
  I2cTransfer last_begun_;
  Mpu6050Sample sample_;
  uint32_t faults_[kMpu6050FaultKinds] = {};
  Mpu6050Fault last_fault_ = Mpu6050Fault::count_;
  uint32_t lost_ = 0;
  uint32_t restarts_ = 0;
  uint32_t samples_ = 0;
  // The self-test's, after the rest (the streaming path's members keep their places).
  uint8_t self_test_samples_ = 1;  // self_test_samples(config_)
  uint8_t repeat_ = 0;             // the start-up row's transfers collected so far
  // Has streamed since power-up: from then on the vehicle may be in the air, and a start-up
  // skips the self-test.
  bool streamed_ = false;
  uint8_t trim_[mpu6050::kTrimRegisters] = {};
  int32_t self_test_sums_[mpu6050::kSelfTestAxes] = {};  // the samples on less the samples off
  uint32_t self_tests_ = 0;
  uint8_t self_test_failures_ = 0;
};

}  // namespace drivers
