// Serve mode's pace: when the simulated world may take its next control period, by the wall clock.
//
// The world runs in step with the wall clock, a period per period. A host that runs it late (a
// sleep that ends late on a loaded machine, a process stopped for seconds) must never make the
// firmware see what a QR on a wire would not: the console's bytes are read when the host runs, so
// simulated time that passes without the host reading them reads to the QR's link watchdog (which
// counts simulated time) as a console gone silent. So:
//
//  - a world a little behind (up to kMaxBehindUs) catches up, but no faster than kCatchUpFactor
//    times the wall clock, counted from when it fell behind: the console's control frames, 20 ms
//    apart on the wall, are then about 40 ms apart in the world at most, and the bytes read at
//    each kick arrive in order behind those already on the line. (How far behind the world was
//    does not matter to the QR: no simulated time passed while the host was not running it, and
//    what the console sent meanwhile is read the moment it runs again; only the catch-up's pace
//    spreads the console's frames.) Counted from when it fell behind, not kick by kick, so that a
//    kick the host ran late (a sleep that overslept, a devboard round trip that took long) is made
//    up by the ones after it;
//  - a world further behind pauses: it resumes from now where it was, and never skips simulated
//    time. The console's bytes that waited in the pty meanwhile go onto the line in order, at its
//    115200 baud. The pauses are counted for the report (docs/simulator.md, section 5, "Serve
//    mode on a loaded host").
//
// All times in µs; the wall clock is the caller's (serve.cpp reads CLOCK_MONOTONIC), so the rule is
// tested without sleeping.
#pragma once

#include <stdint.h>

namespace qrsim {

struct ServeTiming {
  uint64_t kicks = 0;
  uint64_t late_wakeups = 0;   // kicks taken a period or more after they were due (the host was late)
  uint64_t behind_kicks = 0;   // kicks taken a period or more behind the wall clock (catching up)
  uint64_t max_behind_us = 0;  // the furthest behind the wall clock a kick was taken and caught up
  uint64_t pauses = 0;         // times the world paused, kMaxBehindUs or more behind
  uint64_t paused_us = 0;      // wall time the world stood still for, in all
  uint64_t longest_pause_us = 0;
};

class ServeClock {
 public:
  // Behind the wall clock by more than this, the world does not catch up: it pauses. Up to it, a
  // hiccup of the host (tens of ms on this shared machine, a devboard's QEMU held up) is made up
  // and the world stays on the wall clock; beyond it the world would run fast for as long again.
  static constexpr uint64_t kMaxBehindUs = 200000;
  // While catching up, simulated time runs at most this many times as fast as the wall clock.
  static constexpr uint64_t kCatchUpFactor = 2;

  explicit ServeClock(uint64_t period_us) : period_us_(period_us) {}

  // The world is at `sim_us` at wall time `wall_us`.
  void start(uint64_t wall_us, uint64_t sim_us);
  // The wall time at which the kick at simulated `kick_us` may be taken (the physics run up to it,
  // the firmware's tick): when the wall clock reaches it, and while catching up no sooner than
  // simulated time at kCatchUpFactor times the wall clock from where the world fell behind.
  uint64_t due_us(uint64_t kick_us) const;
  // The kick at `kick_us` is taken at `wall_us` (at or after due_us()). A world more than
  // kMaxBehindUs behind pauses: returns how long it stood still (0 when it did not).
  uint64_t begin(uint64_t kick_us, uint64_t wall_us);

  const ServeTiming& timing() const { return timing_; }

 private:
  // On time: the wall time of simulated `sim_us`.
  uint64_t on_time_us(uint64_t sim_us) const {
    return static_cast<uint64_t>(wall_minus_sim_us_ + static_cast<int64_t>(sim_us));
  }

  uint64_t period_us_;
  // Wall time minus simulated time while the world keeps time; every pause adds its length.
  int64_t wall_minus_sim_us_ = 0;
  // Behind the wall clock: since which kick and wall time, for the catch-up's pace.
  bool catching_up_ = false;
  uint64_t behind_since_kick_us_ = 0;
  uint64_t behind_since_wall_us_ = 0;
  ServeTiming timing_;
};

}  // namespace qrsim
