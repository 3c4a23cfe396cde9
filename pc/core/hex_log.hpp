// rx.hex: every byte received from the QR, as hex, each read on a line with its time. The first
// thing to look at when the link misbehaves: it shows what really came down the wire, frames or not.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <string>

namespace qrterm {

// "  12.345  4D 88 2A ..." (seconds since start, then the bytes).
std::string hex_line(uint32_t time_ms, const uint8_t* bytes, size_t count);

}  // namespace qrterm
