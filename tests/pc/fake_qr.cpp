#include "fake_qr.hpp"

#include <algorithm>
#include <cmath>

#include <common/link_timing.hpp>

#include "observable_table_feed.hpp"

namespace qrterm_test {
namespace {

bool flight_mode(wire::Mode mode) {
  return mode == wire::Mode::manual || mode == wire::Mode::yaw_control || mode == wire::Mode::full_control;
}

bool neutral(const wire::Control& c) { return c.lift == 0 && c.roll == 0 && c.pitch == 0 && c.yaw == 0; }

}  // namespace

// Decoded requests and control.
struct FakeQr::Handler {
  FakeQr& qr;
  wire::NackReason answer = wire::NackReason::none;

  void operator()(const wire::Control& c) {
    qr.control = c;
    ++qr.controls_received;
    if (qr.mode == wire::Mode::motor_test && c.lift > 0) qr.mode = wire::Mode::safe;
  }
  void operator()(const wire::MotorTest& m) {
    if (qr.mode != wire::Mode::safe) {
      if (qr.mode == wire::Mode::motor_test) qr.mode = wire::Mode::safe;
      answer = wire::NackReason::not_from_this_mode;
    } else if (qr.refuse_leaving_safe != wire::NackReason::none) {
      answer = qr.refuse_leaving_safe;
    } else if (!neutral(qr.control)) {
      answer = wire::NackReason::controls_not_neutral;
    } else {
      qr.mode = wire::Mode::motor_test;
      qr.mode_since_ms_ = qr.now_ms_;
      qr.test_engine_ = m.engine;
      qr.test_level_ = m.level;
    }
  }
  void operator()(const wire::ModeChange& m) { answer = qr.change_mode(m.mode); }
  void operator()(const wire::ParamSet& p) {
    answer = qr.params.set(p.id, p.value);
    if (answer == wire::NackReason::none && qr.report_after_set)
      qr.send(wire::encode(wire::ParamReport{p.id, p.value}));
  }
  void operator()(const wire::ParamGet& g) {
    for (const wire::ParameterSpec& spec : wire::kParameterTable) {
      const uint8_t id = static_cast<uint8_t>(spec.id);
      if (g.id == wire::kAllParameters || g.id == id)
        qr.send(wire::encode(wire::ParamReport{id, qr.params.get(spec.id)}));
    }
  }
  void operator()(const wire::ObservableGet&) {
    if (!qr.observable_table) return;
    // The whole table at once (the firmware sends a row a tick): the console takes it either way.
    struct Encoder {
      FakeQr& qr;
      void on(const wire::ObservableInfo& m) { qr.send(wire::encode(m)); }
      void on(const wire::ObservableText& m) { qr.send(wire::encode(m)); }
    } encoder{qr};
    qrterm::send_observable_table(encoder);
  }
  void operator()(const wire::StreamRequest& r) {
    Stream& stream = qr.streams_[r.stream];  // valid(): a stream there is
    stream.asked = r;
    stream.packer.start(r.stream, r.count());
    stream.next_ms = qr.now_ms_;
  }
  void operator()(const wire::LogStart&) { qr.logging = true; }
  void operator()(const wire::LogStop&) { qr.logging = false; }
  void operator()(const wire::LogDownload& d) {
    const size_t lines = d.log == wire::LogKind::sensor ? qr.sensor_log.size() : qr.telemetry_log.size();
    if (qr.logging) {
      answer = wire::NackReason::busy;
    } else if (d.first_line >= lines) {
      answer = wire::NackReason::bad_value;  // as the firmware: no such lines
    } else {
      qr.send_log(d.log, d.first_line, d.count);
    }
  }
  void operator()(const wire::LogResend& r) {
    const size_t lines = r.log == wire::LogKind::sensor ? qr.sensor_log.size() : qr.telemetry_log.size();
    if (qr.logging) {
      answer = wire::NackReason::busy;
    } else if (r.first_line >= lines) {
      answer = wire::NackReason::bad_value;
    } else {
      qr.resend_log_parts(r);
    }
  }
  void operator()(const wire::Exit&) {
    qr.exited = true;
    qr.mode = flight_mode(qr.mode) ? wire::Mode::panic : wire::Mode::safe;
    qr.mode_since_ms_ = qr.now_ms_;
  }
};

wire::NackReason FakeQr::change_mode(wire::Mode wanted) {
  if (!wire::valid_mode(wanted)) return wire::NackReason::unknown_mode;
  if (mode == wire::Mode::motor_test) mode = wire::Mode::safe;  // any mode request ends a motor test
  if (wanted == wire::Mode::safe || wanted == wire::Mode::panic) {
    // Safe is reached from flight through panic; in safe or calibration a panic lands in safe.
    const bool flying = flight_mode(mode);
    mode = flying ? wire::Mode::panic : (mode == wire::Mode::panic ? wire::Mode::panic : wire::Mode::safe);
    if (flying) mode_since_ms_ = now_ms_;
    return wire::NackReason::none;
  }
  if (mode != wire::Mode::safe) return wire::NackReason::not_from_this_mode;
  if (refuse_leaving_safe != wire::NackReason::none) return refuse_leaving_safe;
  if (!neutral(control)) return wire::NackReason::controls_not_neutral;
  if ((wanted == wire::Mode::yaw_control || wanted == wire::Mode::full_control) && !calibrated) {
    return wire::NackReason::not_calibrated;
  }
  mode = wanted;
  mode_since_ms_ = now_ms_;
  return wire::NackReason::none;
}

wire::NackReason FakeQr::apply(const wire::Frame& frame) {
  Handler handler{*this};
  if (wire::dispatch(frame, handler) == wire::DispatchResult::invalid_payload) return wire::NackReason::bad_value;
  return handler.answer;
}

void FakeQr::receive(const uint8_t* data, size_t count, uint32_t now_ms) {
  now_ms_ = now_ms;
  for (size_t i = 0; i < count; ++i) {
    parser_.push(data[i], [&](const wire::Frame& frame) {
      last_frame_ms_ = now_ms;
      if (exited) return;
      const wire::Admission admission = dedup_.admit(frame, now_ms);
      if (!admission.request) {
        Handler handler{*this};
        wire::dispatch(frame, handler);
        return;
      }
      requests.push_back(frame);
      if (!answer_requests) return;
      const bool log_request = frame.type == wire::MessageType::log_start ||
                               frame.type == wire::MessageType::log_stop ||
                               frame.type == wire::MessageType::log_download;
      if (admission.duplicate) {
        send(wire::reply_frame(frame.type, admission.seq, admission.previous));
        return;
      }
      // The answer goes before what the request makes the QR send (reports, log parts).
      const size_t before = output_.size();
      const wire::NackReason answer = apply(frame);
      ++requests_applied;
      dedup_.record(frame, answer, now_ms);
      const wire::FrameBytes reply = wire::reply_frame(frame.type, admission.seq, answer);
      if (!silent)
        output_.insert(output_.begin() + static_cast<std::ptrdiff_t>(before), reply.bytes, reply.bytes + reply.size);
      if (log_request) send(wire::encode(log_status()));  // the firmware does the same
    });
  }
}

void FakeQr::tick(uint32_t now_ms) {
  now_ms_ = now_ms;
  if (flight_mode(mode) && now_ms - last_frame_ms_ >= kLinkTimeoutMs) {
    mode = wire::Mode::panic;
    mode_since_ms_ = now_ms;
  }
  if (mode == wire::Mode::calibration && now_ms - mode_since_ms_ >= kCalibrationMs) {
    calibrated = true;
    mode = wire::Mode::safe;
  }
  if (mode == wire::Mode::panic && now_ms - mode_since_ms_ >= kPanicMs) mode = wire::Mode::safe;
  if (mode == wire::Mode::motor_test && now_ms - mode_since_ms_ >= kMotorTestMs) mode = wire::Mode::safe;
  update_engines();
  if (telemetry && wire::reached(now_ms, next_telemetry_ms_)) {
    next_telemetry_ms_ = now_ms + kTelemetryPeriodMs;
    send_telemetry();
  }
  send_samples();
}

void FakeQr::send_samples() {
  for (Stream& stream : streams_) {
    const uint8_t count = stream.asked.count();
    for (; stream.asked.divider > 0 && wire::reached(now_ms_, stream.next_ms); stream.next_ms += stream.asked.divider) {
      int16_t values[wire::kStreamObservablesMax] = {};
      for (uint8_t i = 0; i < count; ++i) values[i] = stream_wave(stream.asked.id[i], stream.next_ms);
      wire::ObservableSamples frame;
      if (stream.packer.add(values, frame)) send(wire::encode(frame));
    }
  }
}

int16_t stream_wave(uint8_t id, uint32_t t_ms) {
  constexpr double kTwoPi = 6.283185307179586;
  const double t_s = t_ms / 1000.0;
  double value = 0;
  if (id == static_cast<uint8_t>(wire::ObservableId::phi)) value = 0.1 * std::sin(kTwoPi * t_s / 2);
  if (id == static_cast<uint8_t>(wire::ObservableId::height)) value = 5.0 + 0.5 * std::sin(kTwoPi * t_s / 4);
  const wire::ObservableSpec* spec = wire::find_observable(id);
  const double raw = spec == nullptr ? 0 : std::round(value * std::pow(10.0, -spec->scale));
  return static_cast<int16_t>(std::clamp(raw, -32768.0, 32767.0));
}

void FakeQr::update_engines() {
  for (uint16_t& e : engine) {
    if (mode == wire::Mode::motor_test) {
      e = &e == &engine[test_engine_ % 4] ? test_level_ : 0;
    } else if (mode == wire::Mode::panic) {
      e = std::min<uint16_t>(e, 350);
    } else if (flight_mode(mode)) {
      e = control.lift == 0 ? 0 : std::max<uint16_t>(control.lift, 180);
    } else {
      e = 0;
    }
  }
}

void FakeQr::send_telemetry() {
  wire::TelemetryAttitude attitude;
  attitude.tick = tick_++;
  attitude.mode = mode;
  attitude.flags = static_cast<uint8_t>((calibrated ? wire::kFlagCalibrated : 0) | (logging ? wire::kFlagLogging : 0) |
                                        (flying_flag ? wire::kFlagFlying : 0));
  send(wire::encode(attitude));
  send(wire::encode(wire::TelemetryRates{}));
  if (height) send(wire::encode(*height));
  if (!tasks.empty()) send(wire::encode(tasks[next_task_++ % tasks.size()]));
  switch (slow_group_++ % 5) {
    case 0: {
      wire::TelemetryEngines engines;
      std::copy(engine, engine + 4, engines.engine);
      send(wire::encode(engines));
      break;
    }
    case 1: send(wire::encode(wire::TelemetrySetpoints{control.lift, 0, 0, 0})); break;
    case 2: send(wire::encode(wire::TelemetrySystem{11850, 420, 612, 0})); break;
    case 3: send(wire::encode(log_status())); break;
    default: {
      const wire::LinkCounters& c = parser_.counters();
      send(wire::encode(wire::TelemetryLink{static_cast<uint16_t>(c.frames_ok), static_cast<uint16_t>(c.check_failures),
                                            static_cast<uint16_t>(c.unknown_types),
                                            static_cast<uint16_t>(c.bytes_skipped)}));
      break;
    }
  }
}

template <class Record>
static void send_lines(const std::map<uint16_t, Record>& log, uint16_t first, uint16_t count,
                       const std::function<bool(uint16_t, uint8_t)>& drop,
                       const std::function<void(const wire::FrameBytes&)>& out) {
  for (const auto& [line, record] : log) {
    if (line < first || (count != 0 && line >= uint32_t{first} + count)) continue;
    for (uint8_t part = 0; part < Record::kParts; ++part) {
      if (drop && drop(line, part)) continue;
      out(wire::encode(wire::make_log_part(record, part)));
    }
  }
}

void FakeQr::send_log(wire::LogKind log, uint16_t first, uint16_t count) {
  const auto out = [this](const wire::FrameBytes& frame) { send(frame); };
  if (log == wire::LogKind::sensor) {
    send_lines(sensor_log, first, count, drop_log_part, out);
  } else {
    send_lines(telemetry_log, first, count, drop_log_part, out);
  }
}

template <class Record>
static void resend_parts(const std::map<uint16_t, Record>& log, const wire::LogResend& r,
                         const std::function<bool(uint16_t, uint8_t)>& drop,
                         const std::function<void(const wire::FrameBytes&)>& out) {
  for (size_t bit = 0; bit < wire::kLogResendMaskBytes * 8; ++bit) {
    if (!r.wants(bit)) continue;
    const auto found = log.find(static_cast<uint16_t>(r.first_line + bit / Record::kParts));
    const uint8_t part = static_cast<uint8_t>(bit % Record::kParts);
    if (found == log.end() || (drop && drop(found->first, part))) continue;
    out(wire::encode(wire::make_log_part(found->second, part)));
  }
}

void FakeQr::resend_log_parts(const wire::LogResend& r) {
  const auto out = [this](const wire::FrameBytes& frame) { send(frame); };
  if (r.log == wire::LogKind::sensor) {
    resend_parts(sensor_log, r, drop_log_part, out);
  } else {
    resend_parts(telemetry_log, r, drop_log_part, out);
  }
}

wire::LogStatus FakeQr::log_status() const {
  const uint8_t on = logging ? wire::kLogStatusSensorOn | wire::kLogStatusTelemetryOn : 0;
  return {on, static_cast<uint16_t>(sensor_log.size()), static_cast<uint16_t>(telemetry_log.size()), kLogCapacity};
}

void FakeQr::say(const char* text) {
  for (size_t at = 0; text[at] != '\0';) {
    wire::DebugText piece;
    at += piece.fill(text + at, 64);
    send(wire::encode(piece));
  }
}

void FakeQr::send(const wire::FrameBytes& frame) {
  if (!silent) output_.insert(output_.end(), frame.bytes, frame.bytes + frame.size);
}

std::vector<uint8_t> FakeQr::take_output() {
  std::vector<uint8_t> out;
  out.swap(output_);
  return out;
}

}  // namespace qrterm_test
