// CRC-8/DVB-S2: polynomial 0xD5 (x^8+x^7+x^6+x^4+x^2+1), init 0x00, not reflected, no final XOR.
// The same check CRSF and MSP v2 use; its catalogue check value over "123456789" is 0xBC.
//
// Why this polynomial: it has (x+1) as a factor, so every error flipping an odd number of bits is
// caught, and its remaining factor has period 93, so two flipped bits are caught as long as they are
// fewer than 93 bits apart. Every codeword we send (type + payload + check) is at most 88 bits, so
// every 1-, 2- and 3-bit error and every burst of up to 8 bits is caught (Hamming distance 4).
// That is why no payload is longer than 9 bytes (see frame.hpp and docs/protocol.md).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace wire {

inline constexpr uint8_t kCrc8Polynomial = 0xD5;

// One table lookup per byte instead of eight shift/XOR steps: the QR computes a check for every
// byte it receives and sends, and 256 bytes of flash are cheaper than its cycles. Inline, so a
// parser's per-byte loop keeps the running check in a register (common/drivers/crsf_parser.hpp).
struct Crc8Table {
  uint8_t entry[256];
};

constexpr Crc8Table make_crc8_table() {
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

inline constexpr Crc8Table kCrc8Table = make_crc8_table();

inline uint8_t crc8_update(uint8_t crc, uint8_t byte) { return kCrc8Table.entry[crc ^ byte]; }
uint8_t crc8(const uint8_t* data, size_t length);

}  // namespace wire
