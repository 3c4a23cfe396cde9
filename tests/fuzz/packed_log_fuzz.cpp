// Fuzz target: the log's unpacking (qr/core/log_pack/) over an area the input fills, and its
// packing of lines the input makes. A log of a few thousand lines (keyframes in its index) has its
// packed bits replaced by the input; every line is then unpacked in order and from scattered
// starts, each with a budget the input picks. Checks, beyond what ASan and UBSan catch: no line
// past the end is reached; the lines that come out, whatever they are, pack again into a fresh log
// and come back the same (the packing is lossless for any values, the escape included).
#include <stddef.h>
#include <stdint.h>

#include <vector>

#include <qr/core/log_pack/packed_log.hpp>

#include "fuzz_checks.hpp"

namespace {

using fuzz::require;
using namespace qr::log_pack;

// Predicts the filtered counts from the raw ones with a state of its own, as the chain's copy does.
struct HalfModel {
  int16_t last[6] = {};
  void predict(const wire::SensorLogRecord& raw, int16_t (&out)[6]) {
    for (int i = 0; i < 6; ++i) {
      const int16_t x = i < 3 ? raw.gyro[i] : raw.accel[i - 3];
      last[i] = static_cast<int16_t>((last[i] + x) / 2);
      out[i] = last[i];
    }
  }
};
using Log = PackedLog<HalfModel>;

bool same(const LogLine& a, const LogLine& b, bool telemetry) {
  wire::SensorLogRecord s = a.sensor, t = b.sensor;
  s.line = t.line = 0;
  wire::TelemetryLogRecord u = a.telemetry, v = b.telemetry;
  u.line = v.line = 0;
  return s == t && (!telemetry || u == v);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;  // two bytes of contents, then at least one of area
  const Contents contents{(data[0] & 1) != 0 || (data[0] & 2) == 0, (data[0] & 2) != 0,
                          static_cast<uint16_t>(1 + data[1] % 12)};
  static std::vector<uint8_t> area(Log::kIndexBytes + 64 * 1024);
  static Log log;
  log.attach(area.data(), area.size());
  log.clear(contents);
  // Lines the packing takes as they are, then the input in place of their bits.
  const uint32_t lines = 1 + (size * 7919u) % 2000u;  // at most 231 B each packed again
  for (uint32_t i = 0; i < lines; ++i) {
    LogLine l;
    l.sensor.time_us = i * 1000u;
    require(log.append(l, [](HalfModel& m) { m = HalfModel{}; }));
  }
  const size_t bytes = log.bytes();
  for (size_t i = 0; i < bytes; ++i) area[i] = data[2 + i % (size - 2)];

  static Log again;
  static std::vector<uint8_t> again_area(Log::kIndexBytes + 512 * 1024);
  again.attach(again_area.data(), again_area.size());
  again.clear(contents);
  LogCursor<HalfModel> cursor, check;
  std::vector<LogLine> out;
  for (uint32_t i = 0; i < lines; ++i) {
    const uint16_t budget = static_cast<uint16_t>(1 + data[i % size] % 16);
    while (!cursor.reach(log, i, budget)) {
    }
    out.push_back(cursor.line());
    require(again.append(cursor.line(), [](HalfModel& m) { m = HalfModel{}; }));
  }
  require(!cursor.reach(log, lines, kKeyframeLines));
  for (uint32_t i = 0; i < lines; i += 1 + data[i % size] % 300u) {
    require(check.reach(again, i, kKeyframeLines));
    require(same(check.line(), out[i], contents.telemetry_on(i)));
  }
  return 0;
}
