// Count, min, mean and max of a cycle measurement (per task, per tick), and the measurements over
// a budget.
//
// This runs after every task of every tick, so its usual case is made cheap: a measurement inside
// the range already seen and within the budget changes neither min, max nor the overruns, and
// only counts and sums (one compare decides it). Anything else takes the full path, which also
// remakes that range.
#pragma once

#include <stdint.h>

namespace qr {

struct CycleStats {
  static constexpr uint32_t kNoBudget = 0xFFFFFFFFu;

  uint32_t count = 0;
  uint32_t min = 0;
  uint32_t max = 0;
  uint32_t overruns = 0;  // measurements over the budget
  uint32_t last = 0;      // the latest measurement (a live plot's per-task cycles): one store
  // The sum in two words: a million ticks of 4,000 cycles overflows 32 bits, and a 64-bit add
  // costs RV32 twice a 32-bit one with a carry that is almost never taken.
  uint32_t sum_low = 0;
  uint32_t sum_high = 0;

  [[gnu::always_inline]] inline void add(uint32_t cycles, uint32_t budget = kNoBudget) {
    last = cycles;
    if (cycles - min < usual_span_) {
      count_and_sum(cycles);
      return;
    }
    add_unusual(cycles, budget);
  }
  uint64_t sum() const { return (static_cast<uint64_t>(sum_high) << 32) | sum_low; }
  // Telemetry asks for one task's mean every period. Until a task's sum passes 2^32 (hours of
  // flight at any budget of the task table) RV32IM's own 32-bit division does it; the 64-bit one
  // is libgcc's __udivdi3, about 350 instructions.
  uint32_t mean() const {
    if (count == 0) return 0u;
    if (sum_high == 0) return sum_low / count;
    return static_cast<uint32_t>(sum() / count);
  }
  void reset() { *this = CycleStats{}; }

 private:
  [[gnu::noinline]] void add_unusual(uint32_t cycles, uint32_t budget) {
    if (cycles < min || count == 0) min = cycles;
    if (cycles > max) max = cycles;
    if (cycles > budget) ++overruns;
    count_and_sum(cycles);
    // The usual range: [min, min(max, budget)]; empty when the budget is below the minimum. Its
    // width saturates, so [0, 2^32 - 1] leaves only 2^32 - 1 itself to the full path.
    const uint32_t top = max < budget ? max : budget;
    const uint32_t width = top - min;
    usual_span_ = top < min ? 0u : width == 0xFFFFFFFFu ? width : width + 1u;
  }
  [[gnu::always_inline]] inline void count_and_sum(uint32_t cycles) {
    ++count;
    const uint32_t low = sum_low + cycles;
    if (low < cycles) ++sum_high;
    sum_low = low;
  }

  // Measurements m with m - min < usual_span_ are usual; 0 while nothing has been measured.
  uint32_t usual_span_ = 0;
};

}  // namespace qr
