// A task is a named step of the tick; a task set is the list of tasks one mode runs, in order.
#pragma once

#include <stdint.h>

namespace qr {

template <class Context>
struct Task {
  const char* name;
  void (*run)(Context&);
  uint16_t divider;  // runs on every divider-th executed tick (1 = every tick)
};

struct TaskSet {
  const uint8_t* ids;  // indexes into the context's task table
  uint8_t count;
};

}  // namespace qr
