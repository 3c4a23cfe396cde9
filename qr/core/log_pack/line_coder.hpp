// One log line packed and unpacked by the same code (code() with an Encode or a Decode), so the two
// cannot disagree. A line is the sensor record and, on every kTelemetryEvery-th line, the telemetry
// record (docs/protocol.md section 8: the telemetry log at a tenth of the sensor log's rate). Each
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

inline constexpr uint16_t kTelemetryEvery = 10;
inline constexpr uint16_t kKeyframeLines = 4 * LinearPredictor::kBlockLines;

struct LogLine {
  wire::SensorLogRecord sensor;
  wire::TelemetryLogRecord telemetry;
  bool has_telemetry = false;
};

// Which records a log keeps (LogStart::logs).
struct Contents {
  bool sensor = true;
  bool telemetry = true;
  // Line `index` carries a telemetry record: every line when it is the only record kept.
  bool telemetry_on(uint32_t index) const { return telemetry && (!sensor || index % kTelemetryEvery == 0); }
};

class Encode {
 public:
  static constexpr bool kEncodes = true;
  Encode(uint8_t* area, size_t bytes, size_t bit) : out_(area, bytes, bit) {}
  void value(uint32_t& v, uint32_t prediction, RiceCode& code) {
    ok_ = code.put(out_, static_cast<int32_t>(v - prediction)) && ok_;
  }
  void flag(bool& f) { ok_ = out_.put(f ? 1u : 0u, 1) && ok_; }
  bool ok() const { return ok_; }
  size_t bit() const { return out_.bit(); }

 private:
  BitWriter out_;
  bool ok_ = true;
};

class Decode {
 public:
  static constexpr bool kEncodes = false;
  Decode(const uint8_t* area, size_t bytes, size_t bit) : in_(area, bytes, bit) {}
  void value(uint32_t& v, uint32_t prediction, RiceCode& code) {
    v = prediction + static_cast<uint32_t>(code.get(in_));
  }
  void flag(bool& f) { f = in_.get(1) == 1u; }
  bool ok() const { return in_.ok(); }
  size_t bit() const { return in_.bit(); }

 private:
  BitReader in_;
};

// A record's scalar fields as int32 and back, in the order of its fields() (arrays element by
// element): what lets the telemetry record be coded field by field without naming each field.
namespace detail {
struct CountFields {
  size_t n = 0;
  template <class T>
  constexpr void operator()(T& v) {
    if constexpr (__is_array(T)) {
      for (auto& e : v) (*this)(e);
    } else {
      ++n;
    }
  }
};
struct Flatten {
  int32_t* out;
  size_t n = 0;
  template <class T>
  constexpr void operator()(T& v) {
    if constexpr (__is_array(T)) {
      for (auto& e : v) (*this)(e);
    } else {
      out[n++] = static_cast<int32_t>(v);
    }
  }
};
struct Unflatten {
  const int32_t* in;
  size_t n = 0;
  template <class T>
  constexpr void operator()(T& v) {
    if constexpr (__is_array(T)) {
      for (auto& e : v) (*this)(e);
    } else {
      v = static_cast<T>(in[n++]);
    }
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

// Model: trivially copyable, with predict(const wire::SensorLogRecord& raw, int16_t (&out)[6])
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

  // Where a decoder may start: the predictors' coefficients kept, everything else started afresh.
  void start(const Keyframe<Model>& k) {
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
  Keyframe<Model> keyframe() const {
    Keyframe<Model> k;
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < LinearPredictor::kOrder; ++j) k.coefficients[i][j] = raw_[i].coefficients()[j];
    }
    k.model = model_;
    k.sensor = sensor_;
    k.telemetry = telemetry_;
    k.period_us = period_us_;
    return k;
  }
  Model& model() { return model_; }

  // Line `index` of a log keeping `contents`: written from `line` (Encode) or read into it (Decode).
  template <class Io>
  void code(Io& io, LogLine& line, Contents contents, uint32_t index) {
    if (contents.sensor) code_sensor(io, line.sensor);
    line.has_telemetry = contents.telemetry_on(index);
    if (line.has_telemetry) code_telemetry(io, line.telemetry, contents.sensor ? &line.sensor : nullptr);
  }

 private:
  template <class Io>
  void code_sensor(Io& io, wire::SensorLogRecord& s) {
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

  template <class Io>
  void code_filtered(Io& io, wire::SensorLogRecord& s) {
    int16_t predicted[6];
    model_.predict(s, predicted);
    const auto filtered = [&s](int i) -> int16_t& { return i < 3 ? s.gyro_filtered[i] : s.accel_filtered[i - 3]; };
    bool as_predicted = true;
    if constexpr (Io::kEncodes) {
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
  template <class Io>
  void code_telemetry(Io& io, wire::TelemetryLogRecord& t, const wire::SensorLogRecord* sensor) {
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

  static constexpr size_t kTimeField = 0;  // time_us leads the telemetry record
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
