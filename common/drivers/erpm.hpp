// The answer of a bidirectional DShot ESC: its electrical revolution period, on the same wire,
// about 30 us after each frame (dshot.hpp). Decoding it gives the engine's RPM.
//
// On the wire 21 bits at 5/4 of the DShot bit rate, most significant first. A level change marks
// a 1 (so the line's polarity does not matter): gcr = raw ^ (raw >> 1) gives 20 bits, four 5-bit
// GCR groups, each one nibble by the table below (every group has at most two zeros in a row, so
// the line changes often enough for the receiver to keep its clock). The 16 bits are
//
//   bits 15..13 shift, bits 12..4 mantissa: period_us = mantissa << shift (0xFFF: motor stopped)
//   bits 3..0   check: the XOR of the other three nibbles, inverted (all four XOR to 0xF)
//
// eRPM = 60 000 000 / period_us; RPM = eRPM / pole pairs (a 14-pole motor turns once per 7
// electrical revolutions). Sources (facts): "DSHOT - the missing Handbook" (brushlesswhoop.com),
// the GCR table of Betaflight's bidirectional DShot (PR 8554) and the Bluejay ESC firmware.
#pragma once

#include <stdint.h>

namespace drivers {

inline constexpr uint32_t kErpmAnswerBits = 21;
inline constexpr uint16_t kErpmStopped = 0x0FFF;  // the 12-bit period code of a stopped motor
inline constexpr uint32_t kMicrosPerMinute = 60000000u;

// Nibble -> 5-bit GCR group.
inline constexpr uint8_t kGcrOfNibble[16] = {0x19, 0x1B, 0x12, 0x13, 0x1D, 0x15, 0x16, 0x17,
                                             0x1A, 0x09, 0x0A, 0x0B, 0x1E, 0x0D, 0x0E, 0x0F};

struct ErpmReading {
  bool valid = false;      // false: a GCR group outside the table or a wrong check (keep the last)
  uint32_t period_us = 0;  // electrical period; 0 when the motor is stopped
};

// The 21 bits as received (bit 20 first on the wire) to the period.
ErpmReading decode_erpm_answer(uint32_t raw);

// eRPM from a period (0: stopped).
constexpr uint32_t erpm_of_period(uint32_t period_us) { return period_us == 0 ? 0 : kMicrosPerMinute / period_us; }

// Mechanical RPM: eRPM over the motor's pole pairs (at least 1).
constexpr uint32_t rpm_of_period(uint32_t period_us, uint8_t pole_pairs) {
  return erpm_of_period(period_us) / (pole_pairs == 0 ? 1u : pole_pairs);
}

// The 12-bit period code an ESC sends for a period: the smallest shift that fits the mantissa in
// 9 bits; a period too long for the code (or 0) is "stopped".
constexpr uint16_t erpm_period_code(uint32_t period_us) {
  if (period_us == 0) return kErpmStopped;
  uint32_t shift = 0;
  while ((period_us >> shift) > 0x1FFu) {
    if (++shift > 7) return kErpmStopped;
  }
  const uint16_t code = static_cast<uint16_t>((shift << 9) | (period_us >> shift));
  return code == kErpmStopped ? kErpmStopped : code;
}

// What an ESC puts on the wire for a period code (the simulator's ESC, the tests). `start_high`
// picks the line's polarity; the decoder reads changes, so either decodes alike.
uint32_t encode_erpm_answer(uint16_t period_code, bool start_high = false);

}  // namespace drivers
