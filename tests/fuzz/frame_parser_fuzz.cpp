// Fuzz target: arbitrary bytes into the frame parser; every frame it accepts is decoded as its
// message, fed to the request dedup and the log line assemblers. Checks, beyond what ASan and
// UBSan catch: the parser never keeps a full frame's worth of bytes, accounts for every byte, only
// delivers frames whose check is right, and a decoded message encodes back to the same bytes.
#include <stddef.h>
#include <stdint.h>

#include <common/crc24.hpp>
#include <common/crc8.hpp>
#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/request_dedup.hpp>

namespace {

void require(bool condition) {
  if (!condition) __builtin_trap();
}

struct ReEncode {
  const wire::Frame& frame;
  wire::LogLineAssembler<wire::SensorLogRecord>& sensor;
  wire::LogLineAssembler<wire::TelemetryLogRecord>& telemetry;

  template <wire::Message Msg>
  void operator()(const Msg& message) {
    const wire::FrameBytes bytes = wire::encode(message);
    require(bytes.size == wire::frame_length(*wire::find_message(wire::type_byte(frame.type))));
    require(bytes.bytes[1] == wire::type_byte(frame.type));
    for (uint8_t i = 0; i < frame.length; ++i) require(bytes.bytes[2 + i] == frame.payload[i]);
  }
  void operator()(const wire::SensorLogPart& part) {
    (*this).operator()<wire::SensorLogPart>(part);
    wire::SensorLogRecord line;
    sensor.add(part, line);
  }
  void operator()(const wire::TelemetryLogPart& part) {
    (*this).operator()<wire::TelemetryLogPart>(part);
    wire::TelemetryLogRecord line;
    telemetry.add(part, line);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  wire::FrameParser parser(wire::Listen::both);
  wire::RequestDedup dedup;
  wire::LogLineAssembler<wire::SensorLogRecord> sensor;
  wire::LogLineAssembler<wire::TelemetryLogRecord> telemetry;
  uint32_t bytes_in_frames = 0;
  uint32_t now_ms = 0;

  for (size_t i = 0; i < size; ++i) {
    parser.push(data[i], [&](const wire::Frame& frame) {
      const wire::MessageSpec* spec = wire::find_message(wire::type_byte(frame.type));
      require(spec != nullptr && spec->payload_length == frame.length);
      uint8_t checked[1 + wire::kMaxPayloadBytes];
      checked[0] = wire::type_byte(frame.type);
      for (uint8_t k = 0; k < frame.length; ++k) checked[1 + k] = frame.payload[k];
      const wire::FrameBytes again = wire::make_frame(frame.type, frame.payload, frame.length);
      require(again.size == wire::frame_length(*spec) &&
              again.bytes[again.size - 1] == wire::crc8(&again.bytes[1], again.size - 2u));
      if (spec->guarded) {  // the guard the parser accepted is the type's and payload's CRC-24
        const uint32_t guard = wire::crc24(checked, 1u + frame.length);
        for (uint8_t k = 0; k < wire::kGuardBytes; ++k)
          require(again.bytes[2 + frame.length + k] == ((guard >> (8 * k)) & 0xFF));
      }
      bytes_in_frames += wire::frame_length(*wire::find_message(wire::type_byte(frame.type)));

      wire::dispatch(frame, ReEncode{frame, sensor, telemetry});
      const wire::Admission a = dedup.admit(frame, now_ms);
      require(a.request == spec->acked);
      if (a.request && !a.duplicate) dedup.record(frame, wire::NackReason::none, now_ms);
    });
    require(parser.buffered() < wire::kMaxFrameBytes);
    now_ms += 7;
  }
  const wire::LinkCounters& c = parser.counters();
  require(c.bytes_received == size);
  require(c.bytes_received == c.bytes_skipped + bytes_in_frames + parser.buffered());
  return 0;
}
