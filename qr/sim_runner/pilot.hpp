// The simulated pilot at the console's end of the serial line. It talks to the QR only in wire
// frames, as the ground console does: control 50 times a second (also the heartbeat), requests
// through a resend queue, telemetry and replies through a parser listening to the QR's side.
//
// With a radio (qrsim --rc crsf, use_radio) the sticks go out as CRSF RC frames at 150 Hz on the
// board's receiver line (link statistics at 10 Hz), a mode the radio arms is armed with the arm
// switch (off, then on with the mode switch at that mode's position: docs/safety.md rule 17,
// wire::armed_by_the_radio), and going silent is the radio's link lost; the PC link keeps the
// requests, the parameters and the abort key. A flying mode the radio does not arm (height hold,
// acro) is asked for on the PC link, as the console's key asks, and the QR refuses it
// (radio_is_pilot).
#pragma once

#include <stdint.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/parameter_table.hpp>
#include <common/resend_queue.hpp>
#include <qr/boards/sim/sim_board.hpp>
#include <qr/sim_runner/radio_transmitter.hpp>
#include <sim/quadrotor.hpp>

namespace qrsim {

// The pilot's sticks, as the control frame carries them.
using Sticks = wire::Control;

// What the console knows about the QR, from telemetry and replies.
struct ConsoleView {
  bool heard = false;  // any telemetry yet
  wire::Mode mode = wire::Mode::safe;
  uint8_t flags = 0;
  uint64_t attitude_at_us = 0;  // when the last attitude frame was sent (its tick)
  int16_t phi_e4 = 0, theta_e4 = 0, psi_e4 = 0;
  uint32_t acks = 0;
  uint32_t nacks = 0;
  wire::NackReason last_nack = wire::NackReason::none;
  uint32_t requests_given_up = 0;
  std::string debug_text;          // everything the QR said, lines joined
  uint16_t rpm[4] = {0, 0, 0, 0};  // the last telemetry_rpm
  uint8_t radio_flags = 0;         // the last telemetry_radio's flags
};

// A damaged line between the pilot and the QR (the soak, soak.hpp): each byte either way is lost
// with `byte_loss`, and bursts of random bytes go up the line every `garbage_every_us`. Seeded:
// a run is repeatable.
struct LineFaults {
  double byte_loss = 0;
  uint64_t garbage_every_us = 0;  // 0: no garbage
  uint32_t garbage_max_bytes = 64;
  uint64_t seed = 1;
};

struct LineFaultCounts {
  uint64_t bytes_up = 0, bytes_up_lost = 0;
  uint64_t bytes_down = 0, bytes_down_lost = 0;
  uint64_t garbage_bursts = 0, garbage_bytes = 0;
};

class Pilot {
 public:
  explicit Pilot(SimBoard& board, uint8_t first_seq = 0x40);

  void set_sticks(const Sticks& sticks) { sticks_ = sticks; }
  const Sticks& sticks() const { return sticks_; }
  void request_mode(wire::Mode mode);
  void set_parameter(wire::ParamId id, int32_t raw);
  // Stops sending anything at all on the pilot's link (the cable is pulled, the radio's link
  // lost) or resumes.
  void go_silent(bool silent) { silent_ = silent; }
  // The radio flies from now on (the QR's pilot parameter must say so too).
  void use_radio() { radio_ = true; }

  // Any request through the resend queue (log start, stop, download, ...).
  template <class Request>
  void request(Request r) {
    send(resend_.submit(r, static_cast<uint32_t>(board_.world().now_us() / 1000)));
  }

  // Once per control period, between ticks: takes what the QR sent, sends what is due.
  void step();

  // The line from here on damaged as `faults` say.
  void damage_line(const LineFaults& faults);
  const LineFaultCounts& line_counts() const { return counts_; }
  // Every frame from the QR, after the pilot's own handling (log parts, status, ...), with what
  // the pilot's parser has counted so far.
  void on_every_frame(std::function<void(const wire::Frame&, const wire::LinkCounters&)> f) {
    on_every_frame_ = std::move(f);
  }
  // Every byte that went onto the line towards the QR, after the damage: what the QR will read.
  void on_bytes_up(std::function<void(uint8_t)> f) { on_bytes_up_ = std::move(f); }

  bool request_pending(wire::MessageType type) const { return resend_.pending(type); }
  const ConsoleView& view() const { return view_; }

 private:
  void send(const wire::FrameBytes& frame);
  void put(uint8_t byte);
  bool lost();
  void on_frame(const wire::Frame& frame, uint64_t sent_at_us);

  SimBoard& board_;
  wire::ResendQueue resend_;
  wire::FrameParser parser_{wire::Listen::qr_to_pc};
  Sticks sticks_;
  bool silent_ = false;
  uint64_t next_control_us_ = 0;
  ConsoleView view_;
  LineFaults faults_;
  bool damaged_ = false;
  std::mt19937_64 rng_;
  uint64_t next_garbage_us_ = 0;
  LineFaultCounts counts_;
  std::function<void(const wire::Frame&, const wire::LinkCounters&)> on_every_frame_;
  std::function<void(uint8_t)> on_bytes_up_;
  bool radio_ = false;
  RadioTransmitter transmitter_;
};

// The pilot's thumb on the lift stick, watching the vehicle: lift for the weight (what the pilot
// knows this vehicle hovers at, for its battery now) corrected for the height and climb rate
// the pilot sees and for the tilt, `ramp` (0-1) of it. Slow next to the attitude loops, as a
// person is.
// `trim` (m/s²) is what a person has learnt to add (HeightThumb).
uint16_t lift_for_height(const sim::Quadrotor& plant, double target, double ramp, double trim = 0);

// The same thumb holding a height for long: it trims slowly (0.5 m/s² per metre-second, within
// 0.5 m of the height and slower than 0.5 m/s, at most 2 m/s²), as a person takes out a hover that
// settles off the height. Without it, heavy vibration (the engines' jitter adds thrust) settled
// the proportional thumb 0.19 m high and the scenarios' take-off, which waits for 0.1 m, never
// finished (issue 29).
class HeightThumb {
 public:
  uint16_t lift(const sim::Quadrotor& plant, double target, double ramp, double dt);

 private:
  double trim_ = 0;  // m/s²
};

}  // namespace qrsim
