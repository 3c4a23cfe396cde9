#include <common/drivers/mpu6050.hpp>

namespace drivers {
namespace {

constexpr uint8_t kResetBytes[1] = {mpu6050::kDeviceReset};
constexpr uint8_t kIdentityBytes[1] = {mpu6050::kIdentity};
constexpr uint8_t kRunBytes[1] = {mpu6050::kPwrMgmt1Run};
// GYRO_CONFIG and ACCEL_CONFIG at the self-test's full scales (RM 4.1), without and with the bits.
constexpr uint8_t kSelfTestOffBytes[2] = {mpu6050::kSelfTestGyroFullScale << mpu6050::kFullScaleShift,
                                          mpu6050::kSelfTestAccelFullScale << mpu6050::kFullScaleShift};
constexpr uint8_t kSelfTestOnBytes[2] = {kSelfTestOffBytes[0] | mpu6050::kSelfTestBits,
                                         kSelfTestOffBytes[1] | mpu6050::kSelfTestBits};

// Wrap-safe "now is at or past the deadline" for a microsecond clock that wraps every 71 minutes.
constexpr bool due(uint32_t now_us, uint32_t deadline_us) { return static_cast<int32_t>(now_us - deadline_us) >= 0; }

constexpr int16_t big_endian(uint8_t high, uint8_t low) {
  return static_cast<int16_t>(static_cast<uint16_t>((uint32_t{high} << 8) | low));
}

constexpr int16_t negated(int16_t v) { return v == INT16_MIN ? INT16_MAX : static_cast<int16_t>(-v); }

// A burst no chip sends: the bus read nothing (all ones, SDA left to its pull-up) or a chip that
// holds SDA low for the whole read (all zeros). A real sensor never reads exactly zero, or exactly
// -1, on all seven values at once: the accelerometer alone feels 1 g.
bool all_bytes_equal(const uint8_t* bytes, uint8_t count, uint8_t value) {
  for (uint8_t i = 0; i < count; ++i) {
    if (bytes[i] != value) return false;
  }
  return true;
}

// A burst a chip can send (see all_bytes_equal), and a temperature it is specified at: the checks
// of every burst, the flight's and the self-test's.
bool plausible_bytes(const I2cReply& reply) {
  return reply.count == mpu6050::kDataBytes && !all_bytes_equal(reply.data, mpu6050::kDataBytes, 0x00) &&
         !all_bytes_equal(reply.data, mpu6050::kDataBytes, 0xFF);
}

Mpu6050Raw decode_reply(const I2cReply& reply) {
  uint8_t bytes[mpu6050::kDataBytes];
  for (uint8_t i = 0; i < mpu6050::kDataBytes; ++i) bytes[i] = reply.data[i];
  return decode_mpu6050_data(bytes);
}

bool plausible_temperature(const Mpu6050Raw& raw) {
  return raw.temperature >= mpu6050::kTempMinCounts && raw.temperature <= mpu6050::kTempMaxCounts;
}

// A permutation of three axes and its signs is a rotation when (its parity) x (the product of the
// signs) is +1.
bool is_rotation(const ChipToBody& map) {
  bool seen[3] = {false, false, false};
  int product = 1;
  for (int i = 0; i < 3; ++i) {
    const uint8_t a = map.chip_axis[i];
    if (a > 2 || seen[a]) return false;
    seen[a] = true;
    if (map.sign[i] != 1 && map.sign[i] != -1) return false;
    product *= map.sign[i];
  }
  int inversions = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) inversions += map.chip_axis[i] > map.chip_axis[j] ? 1 : 0;
  }
  return (inversions % 2 == 0 ? product : -product) == 1;
}

}  // namespace

bool valid(const Mpu6050Config& config) {
  return (config.address == mpu6050::kAddressAd0Low || config.address == mpu6050::kAddressAd0High) &&
         config.dlpf < mpu6050::kDlpfReserved && config.gyro_full_scale <= 3 && config.accel_full_scale <= 3 &&
         is_rotation(config.chip_to_body);
}

Mpu6050Raw decode_mpu6050_data(const uint8_t (&bytes)[mpu6050::kDataBytes]) {
  Mpu6050Raw raw;
  for (int axis = 0; axis < 3; ++axis) {
    raw.accel[axis] = big_endian(bytes[2 * axis], bytes[2 * axis + 1]);
    raw.gyro[axis] = big_endian(bytes[8 + 2 * axis], bytes[8 + 2 * axis + 1]);
  }
  raw.temperature = big_endian(bytes[6], bytes[7]);
  return raw;
}

void chip_to_body(const ChipToBody& map, const int16_t (&chip)[3], int16_t (&body)[3]) {
  for (int i = 0; i < 3; ++i) {
    const int16_t v = chip[map.chip_axis[i] < 3 ? map.chip_axis[i] : 0];
    body[i] = map.sign[i] < 0 ? negated(v) : v;
  }
}

Mpu6050::Mpu6050(const Mpu6050Config& config) : config_(config) {
  configuration_[0] = config.sample_rate_divider;
  configuration_[1] = config.dlpf;
  configuration_[2] = static_cast<uint8_t>(config.gyro_full_scale << mpu6050::kFullScaleShift);
  configuration_[3] = static_cast<uint8_t>(config.accel_full_scale << mpu6050::kFullScaleShift);
  self_test_samples_ = self_test_samples(config);
  if (valid(config)) phase_ = Mpu6050Phase::starting;
}

const uint8_t* Mpu6050::startup_bytes(uint8_t row) const {
  switch (kMpu6050Startup[row].bytes) {
    case Mpu6050StartupBytes::reset: return kResetBytes;
    case Mpu6050StartupBytes::identity: return kIdentityBytes;
    case Mpu6050StartupBytes::run: return kRunBytes;
    case Mpu6050StartupBytes::configuration: return configuration_;
    case Mpu6050StartupBytes::scales: return configuration_ + 2;
    case Mpu6050StartupBytes::self_test_off: return kSelfTestOffBytes;
    case Mpu6050StartupBytes::self_test_on: return kSelfTestOnBytes;
    case Mpu6050StartupBytes::trim:  // reads that are kept, not compared
    case Mpu6050StartupBytes::samples_off:
    case Mpu6050StartupBytes::samples_on: break;
  }
  return kResetBytes;
}

uint8_t Mpu6050::transfers_of(const Mpu6050StartupRow& row) const {
  const bool samples = row.bytes == Mpu6050StartupBytes::samples_off || row.bytes == Mpu6050StartupBytes::samples_on;
  return samples ? self_test_samples_ : 1;
}

uint32_t Mpu6050::wait_us(Mpu6050Wait wait) const {
  const uint32_t filter = mpu6050::filter_settle_us(config_.dlpf);
  switch (wait) {
    case Mpu6050Wait::none: return 0;
    case Mpu6050Wait::reset: return mpu6050::kResetWaitUs;
    case Mpu6050Wait::settle: return filter > mpu6050::kGyroSettleUs ? filter : mpu6050::kGyroSettleUs;
    case Mpu6050Wait::filter: return filter;
  }
  return 0;
}

void Mpu6050::collect(I2cResult result, const I2cReply& reply, uint32_t now_us) {
  tick_bits_ = 0;
  fresh_ = false;
  if (phase_ == Mpu6050Phase::refused) return;
  if (waiting_ && due(now_us, not_before_us_)) {
    waiting_ = false;
    // The last row's wait was the settling: from now on, one burst a tick.
    if (row_ == kMpu6050StartupRows) {
      phase_ = Mpu6050Phase::streaming;
      streamed_ = true;
    }
  }
  if (in_flight_ == InFlight::none) return;  // whatever the bus says, it is not about ours
  if (result == I2cResult::pending) {
    fail(Mpu6050Fault::no_answer, now_us);
    return;
  }
  const bool stale = in_flight_ == InFlight::stale;
  in_flight_ = InFlight::none;
  if (stale) return;  // begun before a restart: its answer means nothing now
  switch (result) {
    case I2cResult::ok:
      if (phase_ == Mpu6050Phase::streaming) {
        collect_burst(reply, now_us);
      } else {
        collect_startup(reply, now_us);
      }
      return;
    case I2cResult::address_nack: fail(Mpu6050Fault::address_nack, now_us); return;
    case I2cResult::data_nack: fail(Mpu6050Fault::data_nack, now_us); return;
    case I2cResult::bus_stuck: fail(Mpu6050Fault::bus_stuck, now_us); return;
    case I2cResult::idle:     // the bus forgot the transfer
    case I2cResult::pending:  // (handled above)
      fail(Mpu6050Fault::no_answer, now_us);
      return;
  }
  fail(Mpu6050Fault::no_answer, now_us);  // a result outside the enumeration
}

void Mpu6050::collect_startup(const I2cReply& reply, uint32_t now_us) {
  const Mpu6050StartupRow& row = kMpu6050Startup[row_];
  if (row.read && !take_startup_read(row, reply, now_us)) return;  // counted, and started over
  consecutive_failures_ = 0;
  if (++repeat_ < transfers_of(row)) return;
  next_row(row, now_us);
}

// A start-up read: kept (the trim, the self-test's samples) or compared with what it must be.
// False when it was a fault (counted).
bool Mpu6050::take_startup_read(const Mpu6050StartupRow& row, const I2cReply& reply, uint32_t now_us) {
  if (reply.count != row.count) {
    fail(Mpu6050Fault::impossible_value, now_us);
    return false;
  }
  if (row.bytes == Mpu6050StartupBytes::trim) {
    for (uint8_t i = 0; i < mpu6050::kTrimRegisters; ++i) trim_[i] = reply.data[i];
    return true;
  }
  if (row.bytes == Mpu6050StartupBytes::samples_off || row.bytes == Mpu6050StartupBytes::samples_on) {
    if (!plausible_bytes(reply)) {
      fail(Mpu6050Fault::impossible_value, now_us);
      return false;
    }
    const Mpu6050Raw raw = decode_reply(reply);
    if (!plausible_temperature(raw)) {
      fail(Mpu6050Fault::impossible_value, now_us);
      return false;
    }
    const bool on = row.bytes == Mpu6050StartupBytes::samples_on;
    return take_self_test_sample(raw, on ? 1 : -1, on && repeat_ + 1 == transfers_of(row), now_us);
  }
  const uint8_t* expected = startup_bytes(row_);
  for (uint8_t i = 0; i < row.count; ++i) {
    if (reply.data[i] == expected[i]) continue;
    fail(row.bytes == Mpu6050StartupBytes::identity ? Mpu6050Fault::wrong_identity : Mpu6050Fault::readback_mismatch,
         now_us);
    return false;
  }
  return true;
}

// A sample of the self-test, in the chip's axes (the trim is the chip's), into the sums; the last
// with the bits set judges them.
bool Mpu6050::take_self_test_sample(const Mpu6050Raw& raw, int32_t sign, bool last, uint32_t now_us) {
  for (uint8_t axis = 0; axis < 3; ++axis) {
    self_test_sums_[axis] += sign * raw.accel[axis];
    self_test_sums_[3 + axis] += sign * raw.gyro[axis];
  }
  if (!last) return true;
  ++self_tests_;
  self_test_failures_ = mpu6050::self_test_failures(self_test_sums_, self_test_samples_, trim_);
  if (self_test_failures_ == 0) return true;
  fail(Mpu6050Fault::self_test, now_us);
  return false;
}

// On to the next row that is due: the self-test's rows only until the driver first streams.
void Mpu6050::next_row(const Mpu6050StartupRow& done, uint32_t now_us) {
  repeat_ = 0;
  do {
    ++row_;
  } while (row_ < kMpu6050StartupRows && streamed_ && kMpu6050Startup[row_].power_up_only);
  const uint32_t wait = wait_us(done.wait_after);
  if (wait > 0) {
    waiting_ = true;
    not_before_us_ = now_us + wait;
  }
}

void Mpu6050::collect_burst(const I2cReply& reply, uint32_t now_us) {
  if (!plausible_bytes(reply)) {
    fail(Mpu6050Fault::impossible_value, now_us);
    return;
  }
  const Mpu6050Raw raw = decode_reply(reply);
  if (!plausible_temperature(raw)) {
    fail(Mpu6050Fault::impossible_value, now_us);
    return;
  }
  chip_to_body(config_.chip_to_body, raw.accel, sample_.accel);
  chip_to_body(config_.chip_to_body, raw.gyro, sample_.gyro);
  sample_.temperature = raw.temperature;
  sample_.read_at_us = begun_at_us_;
  fresh_ = true;
  consecutive_failures_ = 0;
  ++samples_;
}

void Mpu6050::fail(Mpu6050Fault kind, uint32_t now_us) {
  ++faults_[static_cast<size_t>(kind)];
  last_fault_ = kind;
  if (consecutive_failures_ < UINT8_MAX) ++consecutive_failures_;
  const bool too_many = consecutive_failures_ >= mpu6050::kLostAfterFailures;
  if (phase_ == Mpu6050Phase::streaming) {
    // The last sample stays, not fresh; the sensor is lost after too many failed reads in a row.
    if (too_many) {
      ++lost_;
      restart(now_us, 0);
    }
    return;
  }
  // Starting: a wrong answer starts over (later, so a missing chip does not take every tick); a
  // transfer not yet answered or not begun is waited for, but not for ever.
  const bool wait_more = kind == Mpu6050Fault::no_answer || kind == Mpu6050Fault::bus_refused;
  if (!wait_more || too_many) restart(now_us, mpu6050::kRetryDelayUs);
}

void Mpu6050::restart(uint32_t now_us, uint32_t delay_us) {
  ++restarts_;
  phase_ = Mpu6050Phase::starting;
  row_ = 0;
  repeat_ = 0;
  for (int32_t& sum : self_test_sums_) sum = 0;
  consecutive_failures_ = 0;
  waiting_ = true;
  not_before_us_ = now_us + delay_us;
  if (in_flight_ == InFlight::current) in_flight_ = InFlight::stale;
}

bool Mpu6050::next_transfer(uint32_t now_us, I2cTransfer& transfer) const {
  if (phase_ == Mpu6050Phase::refused || in_flight_ != InFlight::none) return false;
  if (waiting_ && !due(now_us, not_before_us_)) return false;
  if (phase_ == Mpu6050Phase::streaming) {
    transfer = read_registers(config_.address, mpu6050::kAccelXoutH, mpu6050::kDataBytes);
    return true;
  }
  if (row_ >= kMpu6050StartupRows) return false;  // settling
  const Mpu6050StartupRow& row = kMpu6050Startup[row_];
  if (row.read) {
    transfer = read_registers(config_.address, row.reg, row.count);
    return true;
  }
  transfer = I2cTransfer{};
  transfer.address = config_.address;
  transfer.write[0] = row.reg;
  const uint8_t* bytes = startup_bytes(row_);
  for (uint8_t i = 0; i < row.count; ++i) transfer.write[1 + i] = bytes[i];
  transfer.write_count = static_cast<uint8_t>(1 + row.count);
  return true;
}

void Mpu6050::began(const I2cTransfer& transfer, bool accepted, uint32_t now_us) {
  if (!accepted) {
    fail(Mpu6050Fault::bus_refused, now_us);
    return;
  }
  in_flight_ = InFlight::current;
  begun_at_us_ = now_us;
  last_begun_ = transfer;
  tick_bits_ = transfer_bits(transfer);
}

uint32_t Mpu6050::total_faults() const {
  uint32_t total = 0;
  for (uint32_t n : faults_) total += n;
  return total;
}

uint32_t Mpu6050::bus_time_ns_this_tick(uint32_t bus_hz) const {
  return (tick_bits_ == 0 || bus_hz == 0) ? 0u : transfer_time_ns(last_begun_, bus_hz);
}

}  // namespace drivers
