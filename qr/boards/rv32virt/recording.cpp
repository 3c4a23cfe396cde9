#include <qr/boards/rv32virt/recording.hpp>

namespace rv32virt {
namespace {

uint16_t u16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
int16_t i16(const uint8_t* p) { return static_cast<int16_t>(u16(p)); }
uint32_t u32(const uint8_t* p) { return static_cast<uint32_t>(u16(p)) | (static_cast<uint32_t>(u16(p + 2)) << 16); }

}  // namespace

Recording::Recording(const uint8_t* bytes) {
  for (int i = 0; i < 4; ++i) {
    if (bytes[i] != kRecordingMagic[i]) return;
  }
  const uint16_t version = u16(bytes + 4), size = u16(bytes + 6);
  if (!(version == kRecordingVersion && size == kRecordBytes) && !(version == 1 && size == kRecordBytesVersion1))
    return;
  record_bytes_ = size;
  const uint32_t rate = u32(bytes + 12);
  if (rate == 0 || 1000000u % rate != 0) return;
  records_ = bytes + kRecordingHeaderBytes;
  count_ = u32(bytes + 8);
  rate_hz_ = rate;
  start_us_ = u32(bytes + 16);
}

RecordedTick Recording::at(uint32_t index) const {
  const uint8_t* r = records_ + static_cast<size_t>(index) * record_bytes_;
  RecordedTick t;
  for (int axis = 0; axis < 3; ++axis) {
    t.sample.gyro[axis] = i16(r + 2 * axis);
    t.sample.accel[axis] = i16(r + 6 + 2 * axis);
  }
  t.sample.battery_mv = u16(r + 12);
  t.sticks.lift = u16(r + 14);
  t.sticks.roll = i16(r + 16);
  t.sticks.pitch = i16(r + 18);
  t.sticks.yaw = i16(r + 20);
  t.sample.pressure_pa = record_bytes_ == kRecordBytes ? static_cast<int32_t>(u32(r + 24)) : 0;
  return t;
}

}  // namespace rv32virt
