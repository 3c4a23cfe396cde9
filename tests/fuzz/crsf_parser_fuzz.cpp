// Fuzz target: arbitrary bytes into the CRSF receiver parser (common/drivers/crsf_parser.hpp) and
// the payload decoders and channel map behind it. Checks, beyond what ASan and UBSan catch: every
// frame handed out has a length inside the format and a right check; an RC frame's channels encode
// back to the same frame and map to sticks inside the wire's ranges; link statistics encode back to
// the same bytes; the parser never keeps a whole frame's worth of bytes or skips more than it got.
#include <stddef.h>
#include <stdint.h>

#include <common/crc8.hpp>
#include <common/drivers/crsf.hpp>
#include <common/drivers/crsf_parser.hpp>
#include <common/drivers/rc_sticks.hpp>

#include "fuzz_checks.hpp"

namespace {

using fuzz::require;

bool same_payload(const drivers::CrsfFrameBytes& bytes, const drivers::CrsfFrame& frame) {
  if (bytes.size != frame.size + 4u || bytes.bytes[2] != frame.type) return false;
  for (uint8_t i = 0; i < frame.size; ++i) {
    if (bytes.bytes[3 + i] != frame.payload[i]) return false;
  }
  return true;
}

void check_frame(const drivers::CrsfFrame& frame) {
  require(frame.size <= drivers::kCrsfMaxPayload);
  drivers::CrsfChannels channels;
  if (drivers::decode_rc_channels(frame, channels)) {
    require(same_payload(drivers::encode_rc_channels(channels), frame));
    const drivers::RcSticks s = drivers::rc_sticks(channels, drivers::RcChannelMap{});
    require(s.lift <= wire::kLiftMax);
    require(s.roll >= -wire::kStickMax && s.roll <= wire::kStickMax);
    require(s.pitch >= -wire::kStickMax && s.pitch <= wire::kStickMax);
    require(s.yaw >= -wire::kStickMax && s.yaw <= wire::kStickMax);
    require(s.mode_position <= 2);
    // The flight's way, the six mapped channels read straight from the payload, agrees.
    drivers::RcSticks direct;
    require(drivers::rc_sticks(frame, drivers::RcChannelMap{}, direct));
    require(direct.lift == s.lift && direct.roll == s.roll && direct.pitch == s.pitch && direct.yaw == s.yaw &&
            direct.arm == s.arm && direct.mode_position == s.mode_position);
  }
  drivers::CrsfLinkStatistics stats;
  if (drivers::decode_link_statistics(frame, stats))
    require(same_payload(drivers::encode_link_statistics(stats), frame));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  drivers::CrsfParser parser;
  uint32_t frames = 0;
  for (size_t i = 0; i < size; ++i) {
    parser.push(data[i], [&](const drivers::CrsfFrame& frame) {
      ++frames;
      check_frame(frame);
    });
    require(parser.buffered() < drivers::kCrsfMaxFrameBytes);
  }
  require(parser.counters().frames == frames);
  require(parser.counters().bytes == size);
  require(parser.counters().bytes_skipped <= size);
  return 0;
}
