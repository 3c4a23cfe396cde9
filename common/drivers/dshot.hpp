// DShot, the digital engine protocol of hobby ESCs (BLHeli_32, Bluejay, AM32, KISS): what a board
// sends to each ESC every control period. A frame is 16 bits, sent most significant bit first:
//
//   bits 15..5  value: 0 motor stop, 1..47 special commands (dshot_commands.hpp), 48..2047 throttle
//   bit 4       telemetry request
//   bits 3..0   check: the XOR of the three nibbles of bits 15..4; bidirectional DShot sends it
//               inverted (that is how the ESC knows to answer with its eRPM, erpm.hpp)
//
// Sources (facts, see docs/drivers.md): "DSHOT - the missing Handbook" (brushlesswhoop.com) and
// the BLHeli_32 "Dshotprog spec"; the worked example 1046 -> 0x82C6 is the Handbook's.
#pragma once

#include <stdint.h>

namespace drivers {

inline constexpr uint16_t kDshotValueMax = 2047;
inline constexpr uint16_t kDshotThrottleMin = 48;  // below: the special commands
inline constexpr uint16_t kDshotEngineMax = 1000;  // the core's engine scale (common/units.hpp)

// Whether the ESC answers on the same wire (bidirectional DShot): the check is sent inverted.
enum class DshotLine : uint8_t { unidirectional, bidirectional };

// The 4-bit check over the 12 bits value + telemetry request.
constexpr uint16_t dshot_checksum(uint16_t value_and_request) {
  return static_cast<uint16_t>((value_and_request ^ (value_and_request >> 4) ^ (value_and_request >> 8)) & 0xFu);
}

constexpr uint16_t dshot_frame(uint16_t value, bool telemetry_request, DshotLine line) {
  const uint16_t head = static_cast<uint16_t>((uint32_t{value} & kDshotValueMax) << 1 | (telemetry_request ? 1u : 0u));
  const uint16_t check = line == DshotLine::bidirectional ? static_cast<uint16_t>(~dshot_checksum(head) & 0xFu)
                                                          : dshot_checksum(head);
  return static_cast<uint16_t>((head << 4) | check);
}

// The engine scale 0..1000 to a DShot value: 0 stops the motor (value 0); 1..1000 become throttle
// 49..2047 in steps of 2. A step of 2 keeps every engine step distinct at no cost of a division
// per frame, 1000 is the ESC's full throttle, and an ESC reading the throttle as the fraction
// (v - 48) / 1999 gets back e to within half a step (the simulator's ESC rounds it to e).
constexpr uint16_t dshot_throttle(uint16_t engine) {
  if (engine == 0) return 0;
  const uint16_t e = engine > kDshotEngineMax ? kDshotEngineMax : engine;
  return static_cast<uint16_t>(kDshotThrottleMin - 1 + 2 * e);
}

// What an ESC makes of a throttle value 48..2047: the engine scale, rounded to the nearest unit.
constexpr uint16_t dshot_engine(uint16_t throttle) {
  if (throttle < kDshotThrottleMin) return 0;
  const uint32_t span = kDshotValueMax - kDshotThrottleMin;  // 1999
  return static_cast<uint16_t>(((throttle - kDshotThrottleMin) * uint32_t{kDshotEngineMax} + span / 2) / span);
}

// A received frame as an ESC reads it: the value and request, or nothing when the check fails
// (an ESC drops the frame and keeps the last good value).
struct DshotDecoded {
  bool valid = false;
  uint16_t value = 0;
  bool telemetry_request = false;
};

constexpr DshotDecoded dshot_decode(uint16_t frame, DshotLine line) {
  const uint16_t head = static_cast<uint16_t>(frame >> 4);
  const uint16_t want = line == DshotLine::bidirectional ? static_cast<uint16_t>(~dshot_checksum(head) & 0xFu)
                                                         : dshot_checksum(head);
  if ((frame & 0xFu) != want) return {};
  return {true, static_cast<uint16_t>(head >> 1), (head & 1u) != 0};
}

// ---- bit timing, as data a board turns into timer compare values ----
//
// Each bit is a high pulse then low for the rest of the bit period: 3/4 of it high for a 1, 3/8
// for a 0 (the Handbook: DShot600 bit 1.67 us, T1H 1.25 us, T0H 0.625 us; DShot300 and DShot150
// scale by 2 and 4). After the frame the line rests; a bidirectional ESC answers about 30 us later
// at 5/4 of the bit rate (erpm.hpp).
enum class DshotSpeed : uint8_t { dshot150, dshot300, dshot600, count };

struct DshotTiming {
  DshotSpeed speed;
  uint16_t kbit_s;     // bit rate
  uint16_t bit_ns;     // bit period
  uint16_t t1h_ns;     // high time of a 1
  uint16_t t0h_ns;     // high time of a 0
  uint16_t answer_ns;  // bit period of a bidirectional ESC's answer (5/4 of the bit rate)
};

inline constexpr uint16_t kDshotFrameBits = 16;
inline constexpr uint16_t kDshotAnswerBits = 21;
inline constexpr uint16_t kDshotAnswerDelayNs = 30000;

inline constexpr DshotTiming kDshotTimings[] = {
    {DshotSpeed::dshot150, 150, 6667, 5000, 2500, 5333},
    {DshotSpeed::dshot300, 300, 3333, 2500, 1250, 2667},
    {DshotSpeed::dshot600, 600, 1667, 1250, 625, 1333},
};
static_assert(sizeof(kDshotTimings) / sizeof(kDshotTimings[0]) == static_cast<uint8_t>(DshotSpeed::count),
              "one timing row per speed");

constexpr bool timings_hold_their_ratios() {
  for (uint8_t i = 0; i < static_cast<uint8_t>(DshotSpeed::count); ++i) {
    const DshotTiming& t = kDshotTimings[i];
    if (static_cast<uint8_t>(t.speed) != i) return false;
    // bit = 1e6 / kbit_s ns, T1H = 3/4 and T0H = 3/8 of it, the answer's bit 4/5 of it, each to a ns.
    const uint32_t bit_ns = (1000000u + t.kbit_s / 2) / t.kbit_s;
    if (t.bit_ns != bit_ns) return false;
    if (t.t1h_ns * 4u != 3000000u / t.kbit_s) return false;
    if (t.t0h_ns * 8u != 3000000u / t.kbit_s) return false;
    if (t.answer_ns != (4000000u / 5u + t.kbit_s / 2) / t.kbit_s) return false;
  }
  return true;
}
static_assert(timings_hold_their_ratios(), "kDshotTimings: T1H = 3/4 bit, T0H = 3/8 bit, answer = 4/5 bit");

constexpr const DshotTiming& dshot_timing(DshotSpeed speed) { return kDshotTimings[static_cast<uint8_t>(speed)]; }

// Ticks of a timer running at `clock_hz` for `ns`, rounded: what a board writes to its compare
// registers (at compile time: no 64-bit division on the target).
consteval uint32_t timer_ticks(uint32_t ns, uint32_t clock_hz) {
  return static_cast<uint32_t>((uint64_t{ns} * clock_hz + 500000000u) / 1000000000u);
}

}  // namespace drivers
