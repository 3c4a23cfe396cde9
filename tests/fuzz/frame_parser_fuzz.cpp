// Fuzz target: arbitrary bytes into the frame parser; every frame it accepts is decoded as its
// message, fed to the request dedup, the log line assemblers and the console's log downloader.
// Checks, beyond what ASan and UBSan catch: the parser never keeps a full frame's worth of bytes,
// accounts for every byte, only delivers frames whose check is right, a decoded message encodes
// back to the same bytes, the downloader hands on each line once and asks only for lines there are.
#include <stddef.h>
#include <stdint.h>

#include <common/crc24.hpp>
#include <common/crc8.hpp>
#include <common/frame_parser.hpp>
#include <common/log_downloader.hpp>
#include <common/messages.hpp>
#include <common/request_dedup.hpp>

namespace {

void require(bool condition) {
  if (!condition) __builtin_trap();
}

// A download of this many lines (line numbers up to 1023 in the input, so some are refused).
constexpr uint16_t kDownloadLines = 700;
using SensorDownload = wire::LogDownloader<wire::SensorLogRecord, 1024>;

struct ReEncode {
  const wire::Frame& frame;
  wire::LogLineAssembler<wire::SensorLogRecord>& sensor;
  wire::LogLineAssembler<wire::TelemetryLogRecord>& telemetry;
  SensorDownload& download;
  uint8_t (&handed_on)[kDownloadLines];
  uint32_t now_ms;

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
    download.on_part(part, now_ms, [&](const wire::SensorLogRecord& r) {
      require(r.line < kDownloadLines && handed_on[r.line] == 0);
      handed_on[r.line] = 1;
    });
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
  static SensorDownload download;  // 8 KiB of line bits: not on the stack
  static uint8_t handed_on[kDownloadLines];
  download.begin(kDownloadLines);
  for (uint8_t& h : handed_on) h = 0;
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

      wire::dispatch(frame, ReEncode{frame, sensor, telemetry, download, handed_on, now_ms});
      const wire::Admission a = dedup.admit(frame, now_ms);
      require(a.request == spec->acked);
      if (a.request && !a.duplicate) dedup.record(frame, wire::NackReason::none, now_ms);
    });
    require(parser.buffered() < wire::kMaxFrameBytes);
    uint16_t first = 0, count = 0;
    download.next_download(now_ms, first, count);
    wire::LogResend resend;
    if (download.next_resend(now_ms, resend)) {
      require(resend.log == wire::LogKind::sensor && resend.first_line < kDownloadLines);
      for (size_t bit = 0; bit < wire::kLogResendMaskBytes * 8; ++bit) {
        const size_t line = resend.first_line + bit / wire::SensorLogRecord::kParts;
        require(!resend.wants(bit) || (line < kDownloadLines && handed_on[line] == 0));
      }
    }
    now_ms += 7;
  }
  const wire::LinkCounters& c = parser.counters();
  require(c.bytes_received == size);
  require(c.bytes_received == c.bytes_skipped + bytes_in_frames + parser.buffered());
  return 0;
}
