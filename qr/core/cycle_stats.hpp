// Count, min, mean and max of a cycle measurement (per task, per tick).
#pragma once

#include <stdint.h>

namespace qr {

struct CycleStats {
  uint32_t count = 0;
  uint32_t min = 0;
  uint32_t max = 0;
  uint64_t sum = 0;  // 64 bits: a million ticks of 4,000 cycles overflows 32

  void add(uint32_t cycles) {
    if (cycles < min || count == 0) min = cycles;
    if (cycles > max) max = cycles;
    sum += cycles;
    ++count;
  }
  uint32_t mean() const { return count == 0 ? 0u : static_cast<uint32_t>(sum / count); }
  void reset() { *this = CycleStats{}; }
};

}  // namespace qr
