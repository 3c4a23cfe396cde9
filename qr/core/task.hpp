// A task is one row of the tick: its name, what it runs, how often, on which tick of that cycle,
// and what it may cost. A task set is the list of rows one mode runs, in order.
#pragma once

#include <stdint.h>

namespace qr {

template <class Context>
struct Task {
  const char* name;
  void (*run)(Context&);
  // Runs on the executed ticks t with t % divider == phase (divider 1: every tick). A rate that
  // is a parameter comes from `divider_from`, read again after each run of the task, so a new
  // value takes effect at its next run; the fixed `divider` is then unused.
  uint16_t divider;
  uint16_t phase;
  // Cycles (RV32 instructions on the devboard) one run may take; a run that takes more is an
  // overrun, counted against the task. A student who makes a task slower changes its budget.
  uint32_t budget;
  uint16_t (*divider_from)(const Context&) = nullptr;
};

struct TaskSet {
  const uint8_t* ids;  // indexes into the context's task table
  uint8_t count;
};

inline constexpr uint8_t kNoTask = 0xFF;  // the running-task index between tasks

}  // namespace qr
