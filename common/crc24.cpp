#include <common/crc24.hpp>

namespace wire {

uint32_t crc24(const uint8_t* data, size_t length) {
  uint32_t crc = kCrc24Init;
  for (size_t i = 0; i < length; ++i) {
    crc ^= static_cast<uint32_t>(data[i]) << 16;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x800000u) != 0 ? (crc << 1) ^ kCrc24Polynomial : crc << 1;
    }
  }
  return crc & 0xFFFFFFu;
}

}  // namespace wire
