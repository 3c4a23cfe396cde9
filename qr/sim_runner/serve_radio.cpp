#include <qr/sim_runner/serve_radio.hpp>

#include <common/messages.hpp>

namespace qrsim {

void ServeRadio::hear(uint8_t byte, uint64_t now_us) {
  parser_.push(byte, [&](const wire::Frame& frame) {
    wire::dispatch(frame, [&](const wire::Control& sticks) {
      transmitter_.set_sticks(sticks);
      heard_ = true;
      sticks_at_us_ = now_us;
    });
  });
}

void ServeRadio::step(uint64_t now_us, SimBoard& board) { transmitter_.step(now_us, !sending(now_us), board); }

}  // namespace qrsim
