#include <qr/sim_runner/serve_clock.hpp>

#include <algorithm>

namespace qrsim {

void ServeClock::start(uint64_t wall_us, uint64_t sim_us) {
  wall_minus_sim_us_ = static_cast<int64_t>(wall_us) - static_cast<int64_t>(sim_us);
  catching_up_ = false;
}

uint64_t ServeClock::due_us(uint64_t kick_us) const {
  // The kick's tick runs when the wall clock reaches it, as the firmware's timer would fire.
  const uint64_t on_time = on_time_us(kick_us);
  if (!catching_up_) return on_time;
  return std::max(on_time, behind_since_wall_us_ + (kick_us - behind_since_kick_us_) / kCatchUpFactor);
}

uint64_t ServeClock::begin(uint64_t kick_us, uint64_t wall_us) {
  const uint64_t due = due_us(kick_us);
  const uint64_t on_time = on_time_us(kick_us);
  const uint64_t behind = wall_us > on_time ? wall_us - on_time : 0;
  ++timing_.kicks;
  if (wall_us >= due + period_us_) ++timing_.late_wakeups;
  if (behind > kMaxBehindUs) {
    // Resume from now: this period is on time again, and so is every one after it.
    wall_minus_sim_us_ += static_cast<int64_t>(behind);
    ++timing_.pauses;
    timing_.paused_us += behind;
    timing_.longest_pause_us = std::max(timing_.longest_pause_us, behind);
    catching_up_ = false;
    return behind;
  }
  if (behind < period_us_) {
    catching_up_ = false;  // on time, as near as a sleep wakes
  } else if (!catching_up_) {
    catching_up_ = true;
    behind_since_kick_us_ = kick_us;
    behind_since_wall_us_ = wall_us;
  }
  if (behind >= period_us_) ++timing_.behind_kicks;
  timing_.max_behind_us = std::max(timing_.max_behind_us, behind);
  return 0;
}

}  // namespace qrsim
