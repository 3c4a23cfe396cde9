// Fuzz target: every payload decoder, without the check byte in the way. The first input byte
// picks a row of the message table, the next says how long the payload claims to be, the rest is
// the payload. A decoder must refuse a wrong length, refuse frames of other types, and what it
// accepts must encode back to exactly the same payload (one encoding per message).
#include <stddef.h>
#include <stdint.h>

#include <common/messages.hpp>

namespace {

void require(bool condition) {
  if (!condition) __builtin_trap();
}

struct AnyMessage {
  template <class Msg>
  void operator()(const Msg&) {}
};

template <class... Msgs>
int decoders_accepting(const wire::Frame& frame, wire::MessageList<Msgs...>) {
  int accepting = 0;
  (
      [&] {
        Msgs message{};
        if (!wire::decode(frame, message)) return;
        ++accepting;
        require(Msgs::kType == frame.type);
        const wire::FrameBytes bytes = wire::encode(message);
        require(bytes.size == wire::frame_length(*wire::find_message(wire::type_byte(frame.type))));
        for (uint8_t i = 0; i < frame.length; ++i) require(bytes.bytes[2 + i] == frame.payload[i]);
        Msgs again{};
        uint8_t payload[wire::kMaxPayloadBytes] = {};
        for (uint8_t i = 0; i < frame.length; ++i) payload[i] = frame.payload[i];
        require(wire::read_fields(payload, frame.length, again) && again == message);
      }(),
      ...);
  return accepting;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const wire::MessageSpec& spec = wire::kMessageTable[data[0] % wire::kMessageCount];
  wire::Frame frame;
  frame.type = spec.type;
  frame.length = static_cast<uint8_t>(data[1] % (wire::kMaxPayloadBytes + 1));
  for (size_t i = 0; i < frame.length && 2 + i < size; ++i) frame.payload[i] = data[2 + i];

  const int accepting = decoders_accepting(frame, wire::AllMessages{});
  require(accepting <= 1);
  if (frame.length != spec.payload_length) require(accepting == 0);

  // The dispatch path must agree with the typed decoders.
  const wire::DispatchResult dispatched = wire::dispatch(frame, AnyMessage{});
  require((dispatched == wire::DispatchResult::handled) == (accepting == 1));
  return 0;
}
