#include <qr/sim_runner/serve_reports.hpp>

#include <cstdio>

namespace qrsim {

void ServeReports::paused(uint64_t pause_us, uint64_t sim_us) {
  if (pauses_ == 0) since_sim_us_ = sim_us;
  ++pauses_;
  paused_us_ += pause_us;
  longest_us_ = pause_us > longest_us_ ? pause_us : longest_us_;
}

void ServeReports::step(const ServeOutput& out, uint64_t wall_us, uint64_t sim_us) {
  if (pauses_ > 0 && (!stall_said_ || wall_us - stall_said_us_ >= kQuietUs)) {
    if (pauses_ == 1) {
      std::fprintf(stderr,
                   "qrsim: the host stalled for %.2f s at t=%.3f s: the world paused there and went on "
                   "(simulated time skips nothing; the console's bytes reach the QR in order)\n",
                   static_cast<double>(paused_us_) * 1e-6, static_cast<double>(since_sim_us_) * 1e-6);
    } else {
      std::fprintf(stderr,
                   "qrsim: the host stalled %llu times since t=%.3f s: the world paused %.2f s in all, the longest "
                   "%.2f s\n",
                   static_cast<unsigned long long>(pauses_), static_cast<double>(since_sim_us_) * 1e-6,
                   static_cast<double>(paused_us_) * 1e-6, static_cast<double>(longest_us_) * 1e-6);
    }
    stall_said_ = true;
    stall_said_us_ = wall_us;
    pauses_ = paused_us_ = longest_us_ = 0;
  }
  const uint64_t dropped = out.frames_dropped();
  if (dropped > frames_seen_) {
    if (!dropping_) {
      std::fprintf(stderr,
                   "qrsim: the console does not read the serial line: the QR's oldest frames are dropped, "
                   "whole, and the world flies on\n");
      dropping_ = true;
      episode_frames_ = frames_seen_;
      episode_bytes_ = bytes_seen_;
    }
    frames_seen_ = dropped;
    bytes_seen_ = out.bytes_dropped();
    last_drop_sim_us_ = sim_us;
  } else if (dropping_ && sim_us - last_drop_sim_us_ >= kQuietUs) {
    std::fprintf(stderr, "qrsim: the console reads the serial line again: %llu frames (%llu bytes) dropped meanwhile\n",
                 static_cast<unsigned long long>(frames_seen_ - episode_frames_),
                 static_cast<unsigned long long>(bytes_seen_ - episode_bytes_));
    dropping_ = false;
  }
}

void ServeReports::finish(const ServeOutput& out) const {
  if (out.frames_dropped() == 0) return;
  std::fprintf(stderr, "qrsim: %llu of the QR's frames (%llu bytes) dropped in all while nobody read the serial line\n",
               static_cast<unsigned long long>(out.frames_dropped()),
               static_cast<unsigned long long>(out.bytes_dropped()));
}

}  // namespace qrsim
