// The console's exit (docs/console.md "Exiting"): it asks the QR to go to safe and stop, and
// waits for the answer, at most kExitWaitMs. Whatever ends the wait (the answer, no answer, a
// second request, the line gone) is said once, and says whether the QR confirmed: the simulator
// is then given a moment to stop by itself.
#pragma once

#include <stdint.h>

#include <functional>
#include <string>

#include <common/nack_reason.hpp>
#include <common/resend_queue.hpp>
#include <pc/core/console_log.hpp>

namespace qrterm {

// How long the console waits for the QR to confirm an exit: the resend queue's 1 s of tries, and
// a little for the last answer to arrive.
inline constexpr uint32_t kExitWaitMs = wire::kGiveUpAfterMs + 200;

class ExitHandshake {
 public:
  using Note = std::function<void(Severity, const std::string&)>;

  explicit ExitHandshake(Note note) : note_(std::move(note)) {}

  // Not asked to exit yet: the console still obeys the pilot and keeps the QR's settings up.
  bool running() const { return state_ == State::running; }
  bool done() const { return state_ == State::done; }
  bool confirmed() const { return confirmed_; }

  // x, a second ESC, a signal. True when the QR is to be asked now (the caller sends the exit
  // request). A second call while waiting ends without waiting; with no QR to tell (the line
  // closed, or never up) it ends at once.
  bool request(bool qr_reachable, uint32_t now_ms);
  // The QR's answer to the exit request (reason none: ack).
  void on_answer(wire::NackReason reason);
  // The resend queue gave up on the exit request.
  void unanswered();
  // The serial line is gone.
  void line_closed();
  // Ends the wait when the QR has not answered within kExitWaitMs.
  void tick(uint32_t now_ms);

 private:
  enum class State : uint8_t { running, waiting_for_qr, done };
  void finish(Severity severity, const std::string& why, bool confirmed);

  Note note_;
  State state_ = State::running;
  uint32_t started_ms_ = 0;
  bool confirmed_ = false;
};

}  // namespace qrterm
