// The console at the ground line's full rate (a scenario's `at T console full`, docs/simulator.md):
// issue 16's test of the line, in simulated time, so the host's load cannot move its clock.
//
// While full, beside the pilot's own frames, it keeps the line towards the QR busy without a gap
// (control frames with the pilot's sticks, back to back: 11,520 bytes a second at 115200 baud,
// 8N1), and every 101 ms it sends a mode_change to the mode telemetry shows (answered, and
// changes nothing) with a fresh sequence number. It watches
//   - every frame that went up the line, cut by a parser like the QR's, and when its last byte
//     reached the QR; the QR's telemetry_link counters against them;
//   - each of its requests, from its last byte reaching the QR to the answer's last byte reaching
//     the console, against the QR's promise: the tick after the request's last byte arrived reads
//     it and answers (within two control periods, the second for the rest of a frame already on
//     its way), and the answer then waits at most for the QR's 32-byte transmit buffer ahead of
//     it and its own 5 bytes on the line.
// The figures are `line_*` (docs/simulator.md section 6.5).
#pragma once

#include <stdint.h>

#include <vector>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <qr/boards/sim/sim_board.hpp>
#include <qr/sim_runner/pilot.hpp>
#include <qr/sim_runner/scenario.hpp>

namespace qrsim {

class FullLineConsole {
 public:
  // A request every this many ns while full: about the real-time test's 100 ms (full_line.py),
  // and a millisecond later each time in the QR's 20 ms telemetry period, so over 20 requests the
  // answers meet every moment of it (at 100 ms they would all meet the same one).
  static constexpr uint64_t kRequestEveryNs = 101'000'000;
  // The bound on an answer, from its request's last byte reaching the QR to its own last byte
  // reaching the console: two control periods, then the QR's transmit buffer full ahead of it
  // and its own bytes on the line.
  static uint64_t answer_bound_ns();

  // Takes over the pilot's hooks for the bytes it sends and the frames it receives.
  FullLineConsole(SimBoard& board, Pilot& pilot);

  void set_full(bool full);
  // The pilot's line is pulled (`link off`): nothing goes up, the console's frames neither.
  void go_silent(bool silent) { silent_ = silent; }
  // Once per control period, after the pilot's step: fills the line to the next period.
  void step();

  // The line_* figures, in print order.
  void add_figures(std::vector<Figure>& figures) const;

 private:
  struct Request {
    uint8_t seq;
    uint64_t reached_qr_ns;    // its last byte through
    uint64_t answered_ns = 0;  // the answer's last byte at the console; 0: none yet
  };
  struct LinkReport {
    wire::TelemetryLink counters;
    uint64_t sent_ns;  // when the QR queued its last byte: at or after the tick that composed it
  };

  void send(const wire::FrameBytes& frame);
  void went_up(uint8_t byte);  // every byte that went up the line, the pilot's and this console's
  void on_frame(const wire::Frame& frame);
  uint64_t now_ns() const { return board_.world().now_us() * 1000; }

  SimBoard& board_;
  Pilot& pilot_;
  bool full_ = false;
  bool silent_ = false;
  uint64_t full_since_ns_ = 0;
  uint64_t full_ns_ = 0;  // time at the full rate, over every stretch
  uint64_t idle_ns_ = 0;  // time the line stood idle while full
  uint64_t next_request_ns_ = 0;
  uint8_t seq_ = 0;
  std::vector<Request> requests_;

  wire::FrameParser up_{wire::Listen::pc_to_qr};
  uint64_t last_byte_arrives_ns_ = 0;
  std::vector<uint64_t> frame_arrivals_ns_;  // each good frame's last byte at the QR, in order
  std::vector<LinkReport> reports_;
};

}  // namespace qrsim
