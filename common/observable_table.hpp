// Every variable of the QR worth watching live, in one table both ends share: id on the wire,
// name, unit, wire type and decimal scale (value in the unit = raw x 10^scale). The QR reads the
// rows it samples from here (qr/core/observable_readers.hpp ties a reader to each id), sends the
// table on request (observable_get, docs/protocol.md section 13), and a console may use its copy
// or learn the table from the QR. A stream request names ids from this table.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/drivers/crsf.hpp>
#include <common/task_names.hpp>

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
  ROW(time_ms, 31, "ms", u16, 0, "the QR's clock, wrapping every 65.536 s: when a sample was taken") \
  ROW(p_sp, 32, "rad/s", i16, -3, "roll rate set-point: the roll angle loop's output") \
  ROW(q_sp, 33, "rad/s", i16, -3, "pitch rate set-point: the pitch angle loop's output") \
  ROW(roll_p_term, 34, "thrust", i16, -1, "roll rate loop's proportional term, P2 x (p_sp - p)") \
  ROW(roll_d_term, 35, "thrust", i16, -1, "roll rate loop's derivative term, -D x dp/dt") \
  ROW(roll_integral, 36, "thrust", i16, -1, "roll rate loop's integral (a trim moment)") \
  ROW(pitch_p_term, 37, "thrust", i16, -1, "pitch rate loop's proportional term, P2 x (q_sp - q)") \
  ROW(pitch_d_term, 38, "thrust", i16, -1, "pitch rate loop's derivative term, -D x dq/dt") \
  ROW(pitch_integral, 39, "thrust", i16, -1, "pitch rate loop's integral (a trim moment)") \
  ROW(yaw_p_term, 40, "thrust", i16, -1, "yaw rate loop's proportional term, yaw_p x (r_sp - r)") \
  ROW(yaw_integral, 41, "thrust", i16, -1, "yaw rate loop's integral") \
  ROW(roll_moment, 42, "thrust", i16, -1, "roll moment the mixer was asked for (controller or stick)") \
  ROW(pitch_moment, 43, "thrust", i16, -1, "pitch moment the mixer was asked for") \
  ROW(yaw_moment, 44, "thrust", i16, -1, "yaw moment the mixer was asked for") \
  ROW(climb_sp, 45, "m/s", i16, -3, "vertical loop's climb set-point (height hold, landing): its last run's") \
  ROW(vertical_p_term, 46, "m/s2", i16, -3, "vertical speed loop's proportional term, Kv x (climb_sp - climb)") \
  ROW(vertical_integral, 47, "m/s2", i16, -3, "vertical speed loop's integral") \
  ROW(vertical_thrust, 48, "thrust", i16, -1, "per-engine thrust the vertical loops ask for") \
  ROW(cycles_link, 49, "cycles", u16, 0, "the link task's last run, in the board's cycles") \
  ROW(cycles_filter, 50, "cycles", u16, 0, "the filter task's last run") \
  ROW(cycles_calibration, 51, "cycles", u16, 0, "the calibration task's last run") \
  ROW(cycles_accel_angles, 52, "cycles", u16, 0, "the accelerometer angles task's last run") \
  ROW(cycles_estimator, 53, "cycles", u16, 0, "the attitude estimator task's last run") \
  ROW(cycles_height, 54, "cycles", u16, 0, "the height estimate task's last run") \
  ROW(cycles_attitude, 55, "cycles", u16, 0, "the attitude control task's last run") \
  ROW(cycles_yaw, 56, "cycles", u16, 0, "the yaw control task's last run") \
  ROW(cycles_mixer, 57, "cycles", u16, 0, "the mixer task's last run") \
  ROW(cycles_manual, 58, "cycles", u16, 0, "the manual mixer task's last run") \
  ROW(cycles_safety, 59, "cycles", u16, 0, "the safety task's last run") \
  ROW(cycles_telemetry, 60, "cycles", u16, 0, "the telemetry task's last run (before this sample's tick)") \
  ROW(cycles_logger, 61, "cycles", u16, 0, "the logger task's last run (before this sample's tick)") \
  ROW(cycles_vertical, 62, "cycles", u16, 0, "the vertical loops task's last run") \
  ROW(cycles_stream, 63, "cycles", u16, 0, "the stream task's last run (before this sample's tick)") \
  ROW(rpm_front, 64, "rpm", u16, 0, "engine 0's speed from its ESC's eRPM answer (bidirectional DShot)") \
  ROW(rpm_right, 65, "rpm", u16, 0, "engine 1's speed") \
  ROW(rpm_back, 66, "rpm", u16, 0, "engine 2's speed") \
  ROW(rpm_left, 67, "rpm", u16, 0, "engine 3's speed") \
  ROW(rc_ch1, 68, "crsf", u16, 0, "radio channel 1 as received, before the channel map: 172..1811 (0: none yet)") \
  ROW(rc_ch2, 69, "crsf", u16, 0, "radio channel 2") \
  ROW(rc_ch3, 70, "crsf", u16, 0, "radio channel 3") \
  ROW(rc_ch4, 71, "crsf", u16, 0, "radio channel 4") \
  ROW(rc_ch5, 72, "crsf", u16, 0, "radio channel 5") \
  ROW(rc_ch6, 73, "crsf", u16, 0, "radio channel 6") \
  ROW(rc_ch7, 74, "crsf", u16, 0, "radio channel 7") \
  ROW(rc_ch8, 75, "crsf", u16, 0, "radio channel 8") \
  ROW(rc_ch9, 76, "crsf", u16, 0, "radio channel 9") \
  ROW(rc_ch10, 77, "crsf", u16, 0, "radio channel 10") \
  ROW(rc_ch11, 78, "crsf", u16, 0, "radio channel 11") \
  ROW(rc_ch12, 79, "crsf", u16, 0, "radio channel 12") \
  ROW(rc_ch13, 80, "crsf", u16, 0, "radio channel 13") \
  ROW(rc_ch14, 81, "crsf", u16, 0, "radio channel 14") \
  ROW(rc_ch15, 82, "crsf", u16, 0, "radio channel 15") \
  ROW(rc_ch16, 83, "crsf", u16, 0, "radio channel 16")

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
// The per-task cycle rows, cycles_<task>, one per task in the wire's task order
// (common/task_names.hpp), from cycles_link on.
inline constexpr uint8_t kFirstTaskCyclesObservable = static_cast<uint8_t>(ObservableId::cycles_link);

// `a` starts with `prefix` (whole: a == prefix when `whole`).
constexpr bool starts_with(const char* a, const char* prefix, bool whole = false) {
  size_t i = 0;
  for (; prefix[i] != '\0'; ++i) {
    if (a[i] != prefix[i]) return false;
  }
  return !whole || a[i] == '\0';
}

constexpr bool task_cycle_rows_follow_the_tasks() {
  if (kFirstTaskCyclesObservable + kTaskCount > kObservableCount) return false;
  for (uint8_t task = 0; task < kTaskCount; ++task) {
    const char* name = kObservableTable[kFirstTaskCyclesObservable + task].name;
    if (!starts_with(name, "cycles_") || !starts_with(name + 7, kTaskNames[task], true)) return false;
  }
  return true;
}
static_assert(task_cycle_rows_follow_the_tasks(), "cycles_<task>: one row per task, in the wire's task order");

// The radio's channels, rc_ch1..rc_ch16 in channel order (radios count from 1), from rc_ch1 on:
// the console's radio screen asks for them as four streams of four.
inline constexpr uint8_t kFirstRcChannelObservable = static_cast<uint8_t>(ObservableId::rc_ch1);

constexpr bool rc_channel_rows_follow_the_channels() {
  if (kFirstRcChannelObservable + drivers::kCrsfChannelCount > kObservableCount) return false;
  for (uint8_t ch = 0; ch < drivers::kCrsfChannelCount; ++ch) {
    const char* name = kObservableTable[kFirstRcChannelObservable + ch].name;
    const uint8_t number = static_cast<uint8_t>(ch + 1);
    const char digits[3] = {static_cast<char>(number < 10 ? '0' + number : '0' + number / 10),
                            static_cast<char>(number < 10 ? '\0' : '0' + number % 10), '\0'};
    if (!starts_with(name, "rc_ch") || !starts_with(name + 5, digits, true)) return false;
  }
  return true;
}
static_assert(rc_channel_rows_follow_the_channels(), "rc_ch<N>: one row per radio channel, in channel order");

static_assert(observable_texts_fit(),
              "name, space, unit and a NUL fit four observable_text frames; units have no space");

}  // namespace wire
