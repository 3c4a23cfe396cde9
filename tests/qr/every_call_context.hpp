// A scheduler context with every call the scheduler makes (the SchedulerContext concept,
// qr/core/scheduler.hpp), each doing nothing: one task row, one set. Tests derive from it and
// delete or replace the one member they are about.
#pragma once

#include <stdint.h>

#include <qr/core/scheduler.hpp>

namespace qr::test_context {

// Everything but the set count, so that a context without it can be written too.
template <class Self>
struct EveryCallButTheSetCount {
  static constexpr uint8_t kTaskCount = 1;
  static constexpr uint8_t kSet[] = {0};
  static constexpr Task<Self> task(uint8_t) {
    return {"row", [](Self&) {}, 1, 0, 100};
  }
  static constexpr TaskSet task_set(uint8_t) { return {kSet, 1}; }
  void begin_tick(uint32_t, const SensorSample&) {}
  uint32_t rx_space() const { return 0; }
  void receive(uint8_t) {}
  EngineCommand engines() const { return {}; }
  uint8_t leds() const { return 0; }
  bool tx_peek(uint8_t&) const { return false; }
  void tx_pop() {}
  void account(const TickReport&, const SchedulerStats<kTaskCount>&) {}
  uint8_t current_set() const { return 0; }
  bool running() const { return true; }
};

template <class Self>
struct EveryCall : EveryCallButTheSetCount<Self> {
  static constexpr uint8_t kSetCount = 1;
};

}  // namespace qr::test_context
