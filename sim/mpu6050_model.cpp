#include <sim/mpu6050_model.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sim {
namespace mpu6050 {

const Register* find_register(uint8_t address) {
  for (const Register& r : kRegisters) {
    if (r.address == address) return &r;
  }
  return nullptr;
}

double gyro_factory_trim(uint8_t code) { return code == 0 ? 0.0 : 25.0 * 131.0 * std::pow(1.046, code - 1.0); }

double accel_factory_trim(uint8_t code) {
  return code == 0 ? 0.0 : 4096.0 * 0.34 * std::pow(0.92 / 0.34, (code - 1.0) / (32.0 - 2.0));
}

}  // namespace mpu6050

using namespace mpu6050;

namespace {

// A sample instant this close after the world's instant counts as reached: the two clocks are
// sums of different doubles, and an instant on the world's grid must not slip to the next call.
constexpr double kSampleInstantToleranceS = 1e-9;

void put_int16(std::array<uint8_t, 256>& regs, uint8_t at, int16_t value) {
  const uint16_t bits = static_cast<uint16_t>(value);
  regs[at] = static_cast<uint8_t>(bits >> 8);
  regs[static_cast<uint8_t>(at + 1)] = static_cast<uint8_t>(bits & 0xFF);
}

}  // namespace

Mpu6050Model::Mpu6050Model(uint8_t address, double power_on_s) : address_(address) { reset(power_on_s); }

void Mpu6050Model::reset(double t_s) {
  regs_.fill(0);
  for (const Register& r : kRegisters) regs_[r.address] = r.reset;
  put_trim();
  pointer_ = 0;
  ready_s_ = t_s + kStartupS;
  fifo_head_ = fifo_size_ = 0;
  fifo_last_read_ = 0;
  fifo_count_latch_ = 0;
}

void Mpu6050Model::set_trim(const Mpu6050Trim& trim) {
  trim_ = trim;
  put_trim();
}

// [RM] register 13: XA_TEST[4:2] in bits 7:5 of SELF_TEST_X (Y, Z alike), XG_TEST in its bits 4:0;
// XA_TEST[1:0] in bits 5:4 of SELF_TEST_A, YA_TEST[1:0] in 3:2, ZA_TEST[1:0] in 1:0.
void Mpu6050Model::put_trim() {
  regs_[kSelfTestX + 3] = 0;
  for (size_t axis = 0; axis < 3; ++axis) {
    const uint8_t accel = trim_.accel[axis] & 0x1F;
    regs_[kSelfTestX + axis] = static_cast<uint8_t>((accel >> 2) << 5 | (trim_.gyro[axis] & 0x1F));
    regs_[kSelfTestX + 3] |= static_cast<uint8_t>((accel & 0x03) << (4 - 2 * axis));
  }
}

ImuSense Mpu6050Model::with_self_test(const ImuSense& sensed) const {
  constexpr double kRadPerDeg = std::numbers::pi / 180;
  std::array<double, 3> rate{}, force{};  // rad/s, m/s²
  for (size_t axis = 0; axis < 3; ++axis) {
    const uint8_t bit = static_cast<uint8_t>(0x80u >> axis);
    if ((regs_[kGyroConfig] & bit) != 0) {
      const double sign = axis == 1 ? -1.0 : 1.0;  // FT[Yg] is negative
      const double dps = sign * gyro_factory_trim(trim_.gyro[axis]) / kGyroLsbPerDps[0];
      rate[axis] = faults_.gyro_self_test_scale[axis] * dps * kRadPerDeg;
    }
    if ((regs_[kAccelConfig] & bit) != 0) {
      const double g = accel_factory_trim(trim_.accel[axis]) / kAccelLsbPerG[2];
      force[axis] = faults_.accel_self_test_scale[axis] * g * kStandardGravity;
    }
  }
  ImuSense out = sensed;
  out.rate += Vec3{rate[0], rate[1], rate[2]};
  out.specific_force += Vec3{force[0], force[1], force[2]};
  return out;
}

double Mpu6050Model::sample_rate_hz() const {
  const uint8_t dlpf = regs_[kConfig] & 0x07;
  const double gyro_output_hz = (dlpf == 0 || dlpf == 7) ? 8000.0 : 1000.0;
  return gyro_output_hz / (1.0 + regs_[kSmplrtDiv]);
}

double Mpu6050Model::gyro_counts_per_rad_s() const {
  // The same expression as imu.cpp's kGyroCountsPerRadS, so that FS_SEL = 1 gives the same double.
  constexpr double kRadPerDeg = std::numbers::pi / 180;
  return kGyroLsbPerDps[static_cast<size_t>((regs_[kGyroConfig] >> 3) & 0x03)] / kRadPerDeg;
}

double Mpu6050Model::accel_counts_per_m_s2() const {
  return kAccelLsbPerG[static_cast<size_t>((regs_[kAccelConfig] >> 3) & 0x03)] / kStandardGravity;
}

I2cAck Mpu6050Model::write(const uint8_t* bytes, size_t n, double t_s) {
  if (!answers(t_s)) return I2cAck::address_nack;
  if (n == 0) return I2cAck::ack;
  pointer_ = bytes[0];
  for (size_t i = 1; i < n; ++i) {
    // A byte after DEVICE_RESET finds the chip resetting: refused.
    if (!write_register(pointer_, bytes[i], t_s)) return i + 1 < n ? I2cAck::data_nack : I2cAck::ack;
    advance_pointer();
  }
  return I2cAck::ack;
}

I2cAck Mpu6050Model::read(uint8_t* out, size_t n, double t_s) {
  if (!answers(t_s)) {
    std::fill(out, out + n, static_cast<uint8_t>(0xFF));
    return I2cAck::address_nack;
  }
  for (size_t i = 0; i < n; ++i) {
    out[i] = read_register(pointer_);
    advance_pointer();
  }
  if (n > 0 && (regs_[kIntPinCfg] & kIntRdClear) != 0) regs_[kIntStatus] = 0;
  return I2cAck::ack;
}

void Mpu6050Model::advance_pointer() {
  if (pointer_ != kFifoRW) pointer_ = static_cast<uint8_t>(pointer_ + 1);
}

bool Mpu6050Model::write_register(uint8_t reg, uint8_t value, double t_s) {
  const Register* row = find_register(reg);
  if (row == nullptr || row->access == Access::read_only) return true;
  const uint8_t bits = static_cast<uint8_t>(value & row->writable);
  switch (reg) {
    case kPwrMgmt1: {
      if ((value & kDeviceReset) != 0) {
        reset(t_s);
        return false;
      }
      const bool was_asleep = asleep();
      regs_[reg] = bits;
      // The sample clock starts when the chip wakes: its first sample one period later.
      if (was_asleep && !asleep()) next_sample_s_ = t_s + 1.0 / sample_rate_hz();
      return true;
    }
    case kUserCtrl:
      if ((value & kFifoReset) != 0 && (value & kUserFifoEn) == 0) fifo_head_ = fifo_size_ = 0;
      if ((value & kSigCondReset) != 0) std::fill_n(regs_.begin() + kAccelXoutH, kDataBytes, uint8_t{0});
      regs_[reg] = bits;
      return true;
    case kSignalPathReset:  // resets the signal paths, "does not clear the sensor registers"; reads 0
      return true;
    case kFifoRW:
      if ((regs_[kUserCtrl] & kUserFifoEn) != 0) push_fifo(value);
      return true;
    default: regs_[reg] = bits; return true;
  }
}

uint8_t Mpu6050Model::read_register(uint8_t reg) {
  const Register* row = find_register(reg);
  if (row == nullptr || row->access == Access::write_only) return 0;
  switch (reg) {
    case kIntStatus: {
      const uint8_t status = regs_[reg];
      regs_[reg] = 0;
      return status;
    }
    case kFifoCountH:
      fifo_count_latch_ = static_cast<uint16_t>(fifo_size_);
      return static_cast<uint8_t>(fifo_count_latch_ >> 8);
    case kFifoCountL: return static_cast<uint8_t>(fifo_count_latch_ & 0xFF);
    case kFifoRW:
      if ((regs_[kUserCtrl] & kUserFifoEn) != 0 && fifo_size_ > 0) {
        fifo_last_read_ = fifo_[fifo_head_];
        fifo_head_ = (fifo_head_ + 1) % kFifoBytes;
        --fifo_size_;
      }
      return fifo_last_read_;
    case kWhoAmI: return faults_.who_am_i.value_or(regs_[reg]);
    default: return regs_[reg];
  }
}

void Mpu6050Model::sample(double t_s, const ImuSense& sensed, double temperature_c) {
  if (!answers(t_s) || asleep()) return;
  if (next_sample_s_ > t_s + kSampleInstantToleranceS) return;
  const double period = 1.0 / sample_rate_hz();
  const double passed = std::floor((t_s + kSampleInstantToleranceS - next_sample_s_) / period) + 1.0;
  next_sample_s_ += passed * period;
  take_sample(sensed, temperature_c);
  if ((regs_[kUserCtrl] & kUserFifoEn) != 0 && fifo_record_bytes() > 0) {
    // Enough records to fill the FIFO is as many as matter.
    const double fill = static_cast<double>(kFifoBytes / fifo_record_bytes() + 1);
    const size_t records = static_cast<size_t>(std::min(passed, fill));
    for (size_t k = 0; k < records; ++k) push_fifo_record();
  }
  raise(kDataRdyInt);
}

void Mpu6050Model::take_sample(const ImuSense& part_senses, double temperature_c) {
  if (faults_.stuck_data) return;
  const ImuSense sensed = with_self_test(part_senses);
  const double accel = accel_counts_per_m_s2(), gyro = gyro_counts_per_rad_s();
  for (int axis = 0; axis < 3; ++axis) {
    const uint8_t offset = static_cast<uint8_t>(2 * axis);
    put_int16(regs_, static_cast<uint8_t>(kAccelXoutH + offset), to_counts(sensed.specific_force[axis], accel));
    put_int16(regs_, static_cast<uint8_t>(kGyroXoutH + offset), to_counts(sensed.rate[axis], gyro));
  }
  if ((regs_[kPwrMgmt1] & kTempDis) == 0) {
    put_int16(regs_, kTempOutH, to_counts(temperature_c - kTempOffsetC, kTempLsbPerC));
  }
}

size_t Mpu6050Model::fifo_record_bytes() const {
  const uint8_t en = regs_[kFifoEn];
  size_t bytes = 0;
  if ((en & kAccelFifo) != 0) bytes += 6;
  for (const uint8_t bit : {kTempFifo, kXgFifo, kYgFifo, kZgFifo}) {
    if ((en & bit) != 0) bytes += 2;
  }
  return bytes;
}

// In the order of the register numbers: accel (59..64), temperature (65, 66), gyro x, y, z.
void Mpu6050Model::push_fifo_record() {
  const uint8_t en = regs_[kFifoEn];
  const auto push = [this](uint8_t from, uint8_t count) {
    for (uint8_t i = 0; i < count; ++i) push_fifo(regs_[static_cast<uint8_t>(from + i)]);
  };
  if ((en & kAccelFifo) != 0) push(kAccelXoutH, 6);
  if ((en & kTempFifo) != 0) push(kTempOutH, 2);
  if ((en & kXgFifo) != 0) push(kGyroXoutH, 2);
  if ((en & kYgFifo) != 0) push(static_cast<uint8_t>(kGyroXoutH + 2), 2);
  if ((en & kZgFifo) != 0) push(static_cast<uint8_t>(kGyroXoutH + 4), 2);
}

void Mpu6050Model::push_fifo(uint8_t byte) {
  if (fifo_size_ == kFifoBytes) {
    fifo_head_ = (fifo_head_ + 1) % kFifoBytes;  // "the oldest data will be lost"
    --fifo_size_;
    raise(kFifoOflowInt);
  }
  fifo_[(fifo_head_ + fifo_size_) % kFifoBytes] = byte;
  ++fifo_size_;
}

bool Mpu6050Model::overflow_fifo() {
  if ((regs_[kUserCtrl] & kUserFifoEn) == 0 || fifo_record_bytes() == 0) return false;
  const size_t records = (kFifoBytes - fifo_size_) / fifo_record_bytes() + 1;
  for (size_t i = 0; i < records; ++i) push_fifo_record();
  return true;
}

void Mpu6050Model::raise(uint8_t status_bit) {
  if ((regs_[kIntEnable] & status_bit) != 0) regs_[kIntStatus] |= status_bit;
}

}  // namespace sim
