// CRC-24/OPENPGP (RFC 4880, section 6.1): polynomial 0x864CFB, init 0xB704CE, not reflected, no
// final XOR; its catalogue check value over "123456789" is 0x21CF02. The commanding requests'
// guard (frame.hpp, docs/protocol.md section 2): a second check, independent of the frame's
// CRC-8, so that noise needs 32 bits of luck, not 8, to make the QR change what it does.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace wire {

inline constexpr uint32_t kCrc24Polynomial = 0x864CFB;
inline constexpr uint32_t kCrc24Init = 0xB704CE;

// Bitwise (crc24.cpp): it runs only for the few frames that carry a guard, never per received
// byte, and a table would cost the QR's image 1 KiB.
uint32_t crc24(const uint8_t* data, size_t length);

}  // namespace wire
