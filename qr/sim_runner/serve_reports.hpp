// What the console's log gets to know from serve mode (qrterm logs qrsim's stderr lines as
// "sim: ..."): a host that stalled the world, and frames dropped because nobody read the line. At
// most a line a second of each, so a host that stalls often, or a console that never reads, cannot
// flood it.
#pragma once

#include <stdint.h>

#include <qr/sim_runner/serve_output.hpp>

namespace qrsim {

class ServeReports {
 public:
  static constexpr uint64_t kQuietUs = 1000000;

  // The world stood still for `pause_us` of wall time at simulated `sim_us` (ServeClock::begin).
  void paused(uint64_t pause_us, uint64_t sim_us);

  // Once a control period: says what is due. `wall_us` for the stalls' rate, `sim_us` for the
  // drops' (a line read again is one that has dropped nothing for a second of the world's time).
  void step(const ServeOutput& out, uint64_t wall_us, uint64_t sim_us);

  // At the end: the frames dropped in all, if any were.
  void finish(const ServeOutput& out) const;

 private:
  uint64_t pauses_ = 0, paused_us_ = 0, longest_us_ = 0, since_sim_us_ = 0;
  bool stall_said_ = false;
  uint64_t stall_said_us_ = 0;
  bool dropping_ = false;
  uint64_t frames_seen_ = 0, bytes_seen_ = 0, episode_frames_ = 0, episode_bytes_ = 0, last_drop_sim_us_ = 0;
};

}  // namespace qrsim
