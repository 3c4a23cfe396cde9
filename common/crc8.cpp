#include <common/crc8.hpp>

namespace wire {
namespace {

// One table lookup per byte instead of eight shift/XOR steps: the QR computes a check for every
// byte it receives and sends, and 256 bytes of flash are cheaper than its cycles.
struct Crc8Table {
  uint8_t entry[256];
};

constexpr Crc8Table make_table() {
  Crc8Table table{};
  for (unsigned value = 0; value < 256; ++value) {
    unsigned crc = value;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x80u) != 0 ? (crc << 1) ^ kCrc8Polynomial : crc << 1;
    }
    table.entry[value] = static_cast<uint8_t>(crc);
  }
  return table;
}

constexpr Crc8Table kTable = make_table();

}  // namespace

uint8_t crc8_update(uint8_t crc, uint8_t byte) { return kTable.entry[crc ^ byte]; }

uint8_t crc8(const uint8_t* data, size_t length) {
  uint8_t crc = 0;
  for (size_t i = 0; i < length; ++i) crc = crc8_update(crc, data[i]);
  return crc;
}

}  // namespace wire
