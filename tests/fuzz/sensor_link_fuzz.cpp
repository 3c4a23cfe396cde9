// Fuzz target: arbitrary bytes into both ends' sensor link parsers (common/sensor_link.hpp), the
// devboard's (sensors and I2C ends) and the simulator's (engines and I2C begins). Checks, beyond
// what ASan and UBSan catch: every frame handed out has its type's length and is one of its end's
// messages; one that decodes (a field out of its range does not) encodes back to the same bytes;
// the parser never skips more bytes than it was given.
#include <stddef.h>
#include <stdint.h>

#include <common/sensor_link.hpp>

namespace {

void require(bool condition) {
  if (!condition) __builtin_trap();
}

template <class Msg>
bool round_trip(const simlink::LinkFrame& frame) {
  if (frame.type != static_cast<uint8_t>(Msg::kType)) return false;
  Msg message;
  if (!frame.decode(message)) return true;  // refused: a field outside its range
  const simlink::LinkFrameBytes bytes = simlink::encode(message);
  require(bytes.size == frame.length + simlink::kLinkOverhead);
  require(bytes.bytes[1] == frame.type);
  for (uint8_t i = 0; i < frame.length; ++i) require(bytes.bytes[2 + i] == frame.payload[i]);
  return true;
}

void check(simlink::LinkEnd end, const uint8_t* data, size_t size) {
  simlink::LinkParser parser(end);
  for (size_t i = 0; i < size; ++i) {
    parser.push(data[i], [&](const simlink::LinkFrame& frame) {
      require(frame.length == simlink::payload_length(end, frame.type));
      if (end == simlink::LinkEnd::qr) {
        require(round_trip<simlink::SensorFrame>(frame) || round_trip<simlink::I2cDoneFrame>(frame));
      } else {
        require(round_trip<simlink::EngineFrame>(frame) || round_trip<simlink::I2cBeginFrame>(frame));
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
