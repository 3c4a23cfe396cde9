#include <common/crc8.hpp>

namespace wire {

uint8_t crc8(const uint8_t* data, size_t length) {
  uint8_t crc = 0;
  for (size_t i = 0; i < length; ++i) crc = crc8_update(crc, data[i]);
  return crc;
}

}  // namespace wire
