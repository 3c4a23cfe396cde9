// One log line packed and unpacked by the same code (code() with a LineIo either way), so the two
// cannot disagree. A line is the sensor record and, on every Contents::telemetry_every-th line, the
// telemetry record (docs/protocol.md section 8: the telemetry log at most at 100 Hz). Each
// value is coded as its residual from a prediction, in an adaptive Rice code (rice_code.hpp):
//   time          the last time plus the last period (0 while the logger keeps its rate)
//   raw axes      the axis' linear predictor (linear_predictor.hpp)
//   filtered axes what the Model says the chain's filters gave for these raw samples: exact while
//                 the model's copy of the filters is in step, so one bit says "as predicted";
//                 otherwise (a divider above 1, a parameter changed) their residuals follow
//   the rest      the same value in the line before
// A keyframe (every kKeyframeLines lines) keeps what a decoder needs to start there: the
// predictors' coefficients, the model, the lines before. Predictors' histories and the codes' means
// start afresh at a keyframe, on both sides.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/log_records.hpp>
#include <qr/core/log_pack/bit_stream.hpp>
#include <qr/core/log_pack/linear_predictor.hpp>
#include <qr/core/log_pack/rice_code.hpp>

namespace qr::log_pack {

inline constexpr uint16_t kKeyframeLines = 4 * LinearPredictor::kBlockLines;

struct LogLine {
  wire::SensorLogRecord sensor;
  wire::TelemetryLogRecord telemetry;
  bool has_telemetry = false;
};

// Which records a log keeps (LogStart::logs), and how often the telemetry record comes.
struct Contents {
  bool sensor = true;
  bool telemetry = true;
  uint16_t telemetry_every = 1;  // lines; 1 when the telemetry record is the only one kept
  // Line `index` carries a telemetry record.
  bool telemetry_on(uint32_t index) const { return telemetry && index % telemetry_every == 0; }
};

// The bits of a line going in (packing) or out (unpacking): one class, so each coding function is
// one body on the QR for both directions (its flash is short); a line codes some 20 values.
class LineIo {
 public:
  static LineIo packing(uint8_t* area, size_t bytes, size_t bit) { return LineIo(area, bytes, bit, true); }
  // Unpacking never writes: the area is only read.
  static LineIo unpacking(const uint8_t* area, size_t bytes, size_t bit) {
    return LineIo(const_cast<uint8_t*>(area), bytes, bit, false);
  }

  bool packs() const { return packs_; }
  // `v` written as its residual from `prediction`, or read.
  [[gnu::noinline]] void value(uint32_t& v, uint32_t prediction, RiceCode& code) {
    if (packs_) {
      ok_ = code.put(out_, static_cast<int32_t>(v - prediction)) && ok_;
    } else {
      v = prediction + static_cast<uint32_t>(code.get(in_));
    }
  }
  void flag(bool& f) {
    if (packs_) {
      ok_ = out_.put(f ? 1u : 0u, 1) && ok_;
    } else {
      f = in_.get(1) == 1u;
    }
  }
  bool ok() const { return packs_ ? ok_ : in_.ok(); }
  size_t bit() const { return packs_ ? out_.bit() : in_.bit(); }

 private:
  LineIo(uint8_t* area, size_t bytes, size_t bit, bool packs)
      : out_(area, bytes, bit), in_(area, bytes, bit), packs_(packs) {}
  BitWriter out_;
  BitReader in_;
  bool packs_;
  bool ok_ = true;
};

// A record's scalar fields as int32 and back, in the order of its fields() (arrays element by
// element): what lets the telemetry record be coded field by field without naming each field.
namespace detail {
struct CountFields {
  size_t n = 0;
  template <class T>
  constexpr void operator()(T&) {
    ++n;
  }
  template <class T, size_t N>
  constexpr void operator()(T (&array)[N]) {
    for (T& e : array) (*this)(e);
  }
};
struct Flatten {
  int32_t* out;
  size_t n = 0;
  template <class T>
  constexpr void operator()(T& v) {
    out[n++] = static_cast<int32_t>(v);
  }
  template <class T, size_t N>
  constexpr void operator()(T (&array)[N]) {
    for (T& e : array) (*this)(e);
  }
};
struct Unflatten {
  const int32_t* in;
  size_t n = 0;
  template <class T>
  constexpr void operator()(T& v) {
    v = static_cast<T>(in[n++]);
  }
  template <class T, size_t N>
  constexpr void operator()(T (&array)[N]) {
    for (T& e : array) (*this)(e);
  }
};
template <class Record>
constexpr size_t field_count() {
  Record r{};
  CountFields c;
  Record::fields(r, c);
  return c.n;
}
}  // namespace detail

// Model: copyable, with predict(const wire::SensorLogRecord& raw, int16_t (&out)[6])
// giving the filtered gyro then accelerometer counts the chain had for those raw samples.
template <class Model>
struct Keyframe {
  int16_t coefficients[6][LinearPredictor::kOrder] = {};
  Model model{};
  wire::SensorLogRecord sensor{};  // the line before the keyframe's
  wire::TelemetryLogRecord telemetry{};
  uint32_t period_us = 0;
};

template <class Model>
class LineCoder {
 public:
  static constexpr size_t kTelemetryFields = detail::field_count<wire::TelemetryLogRecord>();

  // Each raw axis its lane: their fits take turns (linear_predictor.hpp). Cold: a loop at start-up.
  [[gnu::cold, gnu::noinline]] LineCoder() {
    for (uint8_t i = 0; i < 6; ++i) raw_[i].set_lane(i);
  }

  // Where a decoder may start: the predictors' coefficients kept, everything else started afresh.
  // Cold: once in 2048 lines.
  [[gnu::cold, gnu::noinline]] void start(const Keyframe<Model>& k) {
    for (int i = 0; i < 6; ++i) {
      raw_[i].load(k.coefficients[i]);
      raw_[i].restart();
    }
    model_ = k.model;
    sensor_ = k.sensor;
    telemetry_ = k.telemetry;
    period_us_ = k.period_us;
    time_code_ = battery_code_ = RiceCode{};
    for (RiceCode& c : raw_code_) c = RiceCode{};
    for (RiceCode& c : filtered_code_) c = RiceCode{};
    for (RiceCode& c : telemetry_code_) c = RiceCode{};
  }
  // The coder as new (a log started): no coefficients, no lines before.
  [[gnu::cold, gnu::noinline]] void reset() {
    const int16_t none[LinearPredictor::kOrder] = {};
    for (LinearPredictor& p : raw_) p.load(none);
    model_ = Model{};
    sensor_ = wire::SensorLogRecord{};
    telemetry_ = wire::TelemetryLogRecord{};
    period_us_ = 0;
  }
  // What a decoder needs to start here, written in place (a keyframe is too large for a stack
  // frame on the QR).
  [[gnu::cold, gnu::noinline]] void keep(Keyframe<Model>& k) const {
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < LinearPredictor::kOrder; ++j) k.coefficients[i][j] = raw_[i].coefficients()[j];
    }
    k.model = model_;
    k.sensor = sensor_;
    k.telemetry = telemetry_;
    k.period_us = period_us_;
  }
  Model& model() { return model_; }

  // Line `index` of a log keeping `contents`: written from `line` or read into it.
  void code(LineIo& io, LogLine& line, Contents contents, uint32_t index) {
    if (contents.sensor) code_sensor(io, line.sensor);
    line.has_telemetry = contents.telemetry_on(index);
    if (line.has_telemetry) code_telemetry(io, line.telemetry, contents.sensor ? &line.sensor : nullptr);
  }

 private:
  [[gnu::noinline]] void code_sensor(LineIo& io, wire::SensorLogRecord& s) {
    uint32_t time = s.time_us;
    io.value(time, sensor_.time_us + period_us_, time_code_);
    s.time_us = time;
    period_us_ = time - sensor_.time_us;
    for (int i = 0; i < 6; ++i) {
      int16_t& axis = i < 3 ? s.gyro[i] : s.accel[i - 3];
      uint32_t v = static_cast<uint32_t>(int32_t{axis});
      io.value(v, static_cast<uint32_t>(raw_[i].predict()), raw_code_[i]);
      axis = static_cast<int16_t>(v);
      raw_[i].push(axis);
    }
    uint32_t battery = s.battery_mv;
    io.value(battery, sensor_.battery_mv, battery_code_);
    s.battery_mv = static_cast<uint16_t>(battery);
    code_filtered(io, s);
    sensor_ = s;
  }

  [[gnu::noinline]] void code_filtered(LineIo& io, wire::SensorLogRecord& s) {
    int16_t predicted[6];
    model_.predict(s, predicted);
    const auto filtered = [&s](int i) -> int16_t& { return i < 3 ? s.gyro_filtered[i] : s.accel_filtered[i - 3]; };
    bool as_predicted = true;
    if (io.packs()) {
      for (int i = 0; i < 6; ++i) as_predicted = as_predicted && filtered(i) == predicted[i];
    }
    io.flag(as_predicted);
    for (int i = 0; i < 6; ++i) {
      uint32_t v = static_cast<uint32_t>(int32_t{filtered(i)});
      if (!as_predicted) io.value(v, static_cast<uint32_t>(int32_t{predicted[i]}), filtered_code_[i]);
      filtered(i) = as_predicted ? predicted[i] : static_cast<int16_t>(v);
    }
  }

  // `sensor`: the line's sensor record, whose time and battery the telemetry record repeats.
  [[gnu::noinline]] void code_telemetry(LineIo& io, wire::TelemetryLogRecord& t, const wire::SensorLogRecord* sensor) {
    int32_t now[kTelemetryFields], before[kTelemetryFields];
    detail::Flatten flat_now{now}, flat_before{before};
    wire::TelemetryLogRecord::fields(t, flat_now);
    wire::TelemetryLogRecord::fields(telemetry_, flat_before);
    for (size_t i = 0; i < kTelemetryFields; ++i) {
      if (sensor != nullptr && i == kTimeField) {
        now[i] = static_cast<int32_t>(sensor->time_us);
      } else if (sensor != nullptr && i == kBatteryField) {
        now[i] = sensor->battery_mv;
      } else {
        uint32_t v = static_cast<uint32_t>(now[i]);
        io.value(v, static_cast<uint32_t>(before[i]), telemetry_code_[i]);
        now[i] = static_cast<int32_t>(v);
      }
    }
    detail::Unflatten unflat{now};
    wire::TelemetryLogRecord::fields(t, unflat);
    telemetry_ = t;
  }

  static constexpr size_t kTimeField = 0;                        // time_us leads the telemetry record
  static constexpr size_t kBatteryField = kTelemetryFields - 3;  // before cpu_load, deadline_misses

  LinearPredictor raw_[6];
  RiceCode time_code_, battery_code_;
  RiceCode raw_code_[6], filtered_code_[6];
  RiceCode telemetry_code_[kTelemetryFields];
  Model model_{};
  wire::SensorLogRecord sensor_{};
  wire::TelemetryLogRecord telemetry_{};
  uint32_t period_us_ = 0;
};

}  // namespace qr::log_pack
