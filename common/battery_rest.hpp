// The voltage the pack would show at rest: the measured one plus the sag the engines' load causes
// through its internal resistance (parameter battery_sag_mv: the sag with all four engines full).
// The QR's battery rules judge it (docs/safety.md rule 8); the console reads the pack's charge from
// it (pc/core/battery_gauge.hpp), so both ends take the same voltage for the same pack.
#pragma once

#include <stdint.h>

#include <common/units.hpp>

namespace wire {

// Motor current goes with shaft power, which goes with the cube of rotor speed, and the mixer
// makes the engine command proportional to rotor speed (qr/core/chain/engine_mixer.hpp): the load is
// sum (e_i / 1000)^3 / 4, 0 at rest and 1 at all engines full. In per mille:
// e^3 / (4 10^6) for each engine (e^3 <= 10^9 fits 32 bits; divisions by constants).
constexpr uint16_t battery_rested_mv(uint16_t measured_mv, const uint16_t (&engines)[4], uint16_t sag_full_mv) {
  // Engines at rest (every tick on the ground): no load, no sag, no cubes to take.
  if ((engines[0] | engines[1] | engines[2] | engines[3]) == 0) return measured_mv;
  uint32_t load_permille = 0;
  for (const uint16_t e : engines) {
    const uint32_t v = e < kEngineMax ? e : kEngineMax;
    load_permille += v * v * v / 4000000u;
  }
  const uint32_t rested = measured_mv + uint32_t{sag_full_mv} * load_permille / 1000u;
  return static_cast<uint16_t>(rested > 0xFFFFu ? 0xFFFFu : rested);
}

}  // namespace wire
