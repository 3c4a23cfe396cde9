#include <pc/core/exit_handshake.hpp>

#include <pc/core/request_texts.hpp>

namespace qrterm {

bool ExitHandshake::request(bool qr_reachable, uint32_t now_ms) {
  if (state_ == State::done) return false;
  if (state_ == State::waiting_for_qr) {
    finish(Severity::warning, "exit without waiting for the QR", false);
    return false;
  }
  if (!qr_reachable) {
    finish(Severity::info, "exit: no QR to tell", false);
    return false;
  }
  note_(Severity::info, "exit: asking the QR to go to safe and stop");
  state_ = State::waiting_for_qr;
  started_ms_ = now_ms;
  return true;
}

void ExitHandshake::on_answer(wire::NackReason reason) {
  if (reason != wire::NackReason::none) {
    finish(Severity::warning, "the QR refused the exit: " + reason_text(reason), false);
  } else {
    finish(Severity::info, "the QR confirmed the exit", true);
  }
}

void ExitHandshake::unanswered() { finish(Severity::error, "no answer from the QR to the exit", false); }

void ExitHandshake::line_closed() {
  if (state_ == State::waiting_for_qr) finish(Severity::warning, "exit not confirmed: the line is gone", false);
}

void ExitHandshake::tick(uint32_t now_ms) {
  if (state_ == State::waiting_for_qr && now_ms - started_ms_ >= kExitWaitMs) unanswered();
}

void ExitHandshake::finish(Severity severity, const std::string& why, bool confirmed) {
  note_(severity, why);
  state_ = State::done;
  confirmed_ = confirmed;
}

}  // namespace qrterm
