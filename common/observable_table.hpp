// Every variable of the QR worth watching live, in one table both ends share: id on the wire,
// name, unit, wire type and decimal scale (value in the unit = raw x 10^scale). The QR reads the
// rows it samples from here (qr/core/observable_readers.hpp ties a reader to each id), sends the
// table on request (observable_get, docs/protocol.md section 13), and a console may use its copy
// or learn the table from the QR. A stream request names ids from this table.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace wire {

// How a sample travels: 16 bits, signed or not. Wider quantities are scaled to fit.
enum class ObservableType : uint8_t { i16 = 0, u16 = 1 };

// The rows, once: identifier (the name), wire id, unit, type, scale (power of ten), meaning.
// Units are short and without spaces: they end up on a plot's axis and in CSV column names.
// A set-point sits next to what follows it: `phi_sp` is phi's.
#define WIRE_OBSERVABLE_ROWS(ROW) \
  ROW(phi, 0, "rad", i16, -4, "roll angle, estimated") \
  ROW(theta, 1, "rad", i16, -4, "pitch angle, estimated") \
  ROW(psi, 2, "rad", i16, -4, "yaw angle, estimated") \
  ROW(p, 3, "rad/s", i16, -3, "roll rate, bias-corrected gyro") \
  ROW(q, 4, "rad/s", i16, -3, "pitch rate, bias-corrected gyro") \
  ROW(r, 5, "rad/s", i16, -3, "yaw rate, bias-corrected gyro") \
  ROW(phi_sp, 6, "rad", i16, -4, "roll angle set-point (sticks, trims, max_tilt_mrad)") \
  ROW(theta_sp, 7, "rad", i16, -4, "pitch angle set-point") \
  ROW(r_sp, 8, "rad/s", i16, -3, "yaw rate set-point") \
  ROW(lift, 9, "permille", u16, 0, "lift the pilot asks for, 0..1000") \
  ROW(engine_front, 10, "permille", u16, 0, "engine 0 command after the safety machine") \
  ROW(engine_right, 11, "permille", u16, 0, "engine 1 command") \
  ROW(engine_back, 12, "permille", u16, 0, "engine 2 command") \
  ROW(engine_left, 13, "permille", u16, 0, "engine 3 command") \
  ROW(gyro_x, 14, "counts", i16, 0, "gyro x, raw sample") \
  ROW(gyro_y, 15, "counts", i16, 0, "gyro y, raw sample") \
  ROW(gyro_z, 16, "counts", i16, 0, "gyro z, raw sample") \
  ROW(accel_x, 17, "counts", i16, 0, "accelerometer x, raw sample") \
  ROW(accel_y, 18, "counts", i16, 0, "accelerometer y, raw sample") \
  ROW(accel_z, 19, "counts", i16, 0, "accelerometer z, raw sample") \
  ROW(gyro_x_f, 20, "counts", i16, 0, "gyro x after the low-pass filter") \
  ROW(gyro_y_f, 21, "counts", i16, 0, "gyro y after the low-pass filter") \
  ROW(gyro_z_f, 22, "counts", i16, 0, "gyro z after the low-pass filter") \
  ROW(accel_x_f, 23, "counts", i16, 0, "accelerometer x after the low-pass filter") \
  ROW(accel_y_f, 24, "counts", i16, 0, "accelerometer y after the low-pass filter") \
  ROW(accel_z_f, 25, "counts", i16, 0, "accelerometer z after the low-pass filter") \
  ROW(battery, 26, "V", u16, -3, "battery voltage") \
  ROW(height, 27, "m", i16, -3, "height estimate above the calibration's reference, saturated") \
  ROW(climb, 28, "m/s", i16, -3, "vertical speed estimate, up positive") \
  ROW(tilt, 29, "rad", u16, -3, "tilt from level, estimated") \
  ROW(tick_busy, 30, "us", u16, 0, "time the last tick's tasks took (the board's clock)") \
  ROW(time_ms, 31, "ms", u16, 0, "the QR's clock, wrapping every 65.536 s: when a sample was taken")

enum class ObservableId : uint8_t {
#define WIRE_OBSERVABLE_ENUMERATOR(name, id, unit, type, scale, meaning) name = id,
  WIRE_OBSERVABLE_ROWS(WIRE_OBSERVABLE_ENUMERATOR)
#undef WIRE_OBSERVABLE_ENUMERATOR
};

struct ObservableSpec {
  ObservableId id;
  const char* name;  // the enumerator's identifier, spelled the same
  const char* unit;
  ObservableType type;
  int8_t scale;  // value in `unit` = raw x 10^scale
};

inline constexpr ObservableSpec kObservableTable[] = {
#define WIRE_OBSERVABLE_SPEC(name, id, unit, type, scale, meaning) \
  {ObservableId::name, #name, unit, ObservableType::type, scale},
    WIRE_OBSERVABLE_ROWS(WIRE_OBSERVABLE_SPEC)
#undef WIRE_OBSERVABLE_SPEC
};

// What the QR reads at run time: the row's text as observable_text carries it ("name unit", one
// string) and its numbers, nothing else (the image is near its limit).
struct ObservableWireRow {
  const char* text;
  ObservableType type;
  int8_t scale;
};

inline constexpr ObservableWireRow kObservableWire[] = {
#define WIRE_OBSERVABLE_WIRE(name, id, unit, type, scale, meaning) {#name " " unit, ObservableType::type, scale},
    WIRE_OBSERVABLE_ROWS(WIRE_OBSERVABLE_WIRE)
#undef WIRE_OBSERVABLE_WIRE
};

// The meanings apart from the rows: the QR never sends them, so they stay out of its image (the
// linker drops an array nobody reads); the console and the documents read them here.
inline constexpr const char* kObservableMeanings[] = {
#define WIRE_OBSERVABLE_MEANING(name, id, unit, type, scale, meaning) meaning,
    WIRE_OBSERVABLE_ROWS(WIRE_OBSERVABLE_MEANING)
#undef WIRE_OBSERVABLE_MEANING
};

inline constexpr uint8_t kObservableCount = sizeof(kObservableTable) / sizeof(kObservableTable[0]);
inline constexpr uint8_t kNoObservable = 0xFF;    // an empty place in a stream request
inline constexpr uint8_t kAllObservables = 0xFF;  // observable_get: the whole table

// Ids run 0..kObservableCount-1 in row order, so a row is found by its id.
constexpr bool observable_ids_follow_rows() {
  for (uint8_t row = 0; row < kObservableCount; ++row) {
    if (static_cast<uint8_t>(kObservableTable[row].id) != row) return false;
  }
  return true;
}
static_assert(observable_ids_follow_rows(), "observable ids must run 0, 1, 2, ... in table order");
static_assert(kObservableCount < kNoObservable, "0xFF stays free to mean 'none' and 'all'");

constexpr const ObservableSpec* find_observable(uint8_t id) {
  return id < kObservableCount ? &kObservableTable[id] : nullptr;
}

// The text observable_text frames carry: "name unit", a single space between, then at least one
// NUL, which is how a client knows it has the whole text.
inline constexpr size_t kObservableTextChars = 28;  // 4 frames of 7 characters, the NUL included

constexpr size_t text_length(const char* s) {
  size_t n = 0;
  while (s[n] != '\0') ++n;
  return n;
}

constexpr bool observable_texts_fit() {
  for (const ObservableSpec& spec : kObservableTable) {
    if (text_length(spec.name) + 1 + text_length(spec.unit) + 1 > kObservableTextChars) return false;
    for (size_t i = 0; spec.unit[i] != '\0'; ++i) {
      if (spec.unit[i] == ' ') return false;
    }
  }
  return true;
}
static_assert(observable_texts_fit(),
              "name, space, unit and a NUL fit four observable_text frames; units have no space");

}  // namespace wire
