// Fuzz target: arbitrary bytes into both ends' sensor link parsers (common/sensor_link.hpp), the
// devboard's (sensors frames) and the simulator's (engine frames). Checks, beyond what ASan and
// UBSan catch: every frame handed out has its type's length and a right check byte, decodes as
// its message, and encodes back to the same bytes; the parser never skips more bytes than it was
// given.
#include <stddef.h>
#include <stdint.h>

#include <common/sensor_link.hpp>

namespace {

void require(bool condition) {
  if (!condition) __builtin_trap();
}

template <class Msg>
void round_trip(const simlink::LinkFrame& frame) {
  Msg message;
  require(frame.decode(message));
  const simlink::LinkFrameBytes bytes = simlink::encode(message);
  require(bytes.size == frame.length + simlink::kLinkOverhead);
  require(bytes.bytes[1] == frame.type);
  for (uint8_t i = 0; i < frame.length; ++i) require(bytes.bytes[2 + i] == frame.payload[i]);
}

void check(simlink::LinkEnd end, const uint8_t* data, size_t size) {
  simlink::LinkParser parser(end);
  for (size_t i = 0; i < size; ++i) {
    parser.push(data[i], [&](const simlink::LinkFrame& frame) {
      require(frame.length == simlink::payload_length(end, frame.type));
      if (end == simlink::LinkEnd::qr) {
        round_trip<simlink::SensorFrame>(frame);
      } else {
        round_trip<simlink::EngineFrame>(frame);
      }
    });
  }
  require(parser.bytes_skipped() <= size);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  check(simlink::LinkEnd::qr, data, size);
  check(simlink::LinkEnd::simulator, data, size);
  return 0;
}
