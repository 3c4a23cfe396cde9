// Member definitions of qr::Flight (a template, so they live in a header). Include flight.hpp.
#pragma once

#include <qr/core/flight.hpp>

namespace qr {

// Rows in FlightTask order (flight_tasks.hpp).
template <class Chain>
const Task<Flight<Chain>> Flight<Chain>::kTasks[kFlightTaskCount] = {
    {"link", [](Flight& f) { f.run_link(); }, 1},
    {"filter", [](Flight& f) { f.run_filter(); }, 1},
    {"calibration", [](Flight& f) { f.run_calibration(); }, 1},
    {"estimator", [](Flight& f) { f.run_estimator(); }, 1},
    {"attitude", [](Flight& f) { f.run_attitude_control(); }, 1},
    {"yaw", [](Flight& f) { f.run_yaw_control(); }, 1},
    {"mixer", [](Flight& f) { f.run_mixer(); }, 1},
    {"manual", [](Flight& f) { f.run_manual_mixer(); }, 1},
    {"safety", [](Flight& f) { f.run_safety(); }, 1},
    {"telemetry", [](Flight& f) { f.run_telemetry(); }, 1},
    {"logger", [](Flight& f) { f.run_logger(); }, 1},
};

namespace flight_text {
inline constexpr const char* kModeNames[wire::kModeCount] = {"safe", "panic", "manual", "calibration", "yaw control", "full control"};
inline constexpr const char* kPanicCauses[] = {"", "requested", "link lost", "battery low", "tilt"};
}  // namespace flight_text

// Applies one decoded message from the PC; for requests, `answer` is what the ack/nack says.
template <class Chain>
struct Flight<Chain>::RequestHandler {
  Flight& f;
  NackReason answer = NackReason::none;
  wire::ParamReport report{};  // id 0: nothing to report

  void operator()(const wire::Control& c) { f.controls_ = ControlInput{c.lift, c.roll, c.pitch, c.yaw}; }
  void operator()(const wire::ModeChange& m) {
    answer = f.safety_.request(static_cast<uint8_t>(m.mode), f.situation());
  }
  void operator()(const wire::ParamSet& p) {
    answer = f.params_.set(p.id, p.value);
    if (answer != NackReason::none) return;
    f.apply_parameters();
    report = wire::ParamReport{p.id, p.value};  // after the ack: the value now in force
  }
  void operator()(const wire::ParamGet& g) {
    if (g.id == wire::kAllParameters) {
      f.report_next_ = 0;
      f.report_end_ = static_cast<uint8_t>(wire::kParameterCount);
      return;
    }
    for (uint8_t row = 0; row < wire::kParameterCount; ++row) {
      if (static_cast<uint8_t>(wire::kParameterTable[row].id) == g.id) {
        f.report_next_ = row;
        f.report_end_ = static_cast<uint8_t>(row + 1);
        return;
      }
    }
    answer = NackReason::unknown_parameter;
  }
  void operator()(const wire::Exit&) { f.safety_.request_exit(f.situation()); }
  void operator()(const wire::LogStart& l) { log(f.log_.start(l.logs)); }
  void operator()(const wire::LogStop&) { log(f.log_.stop()); }
  void operator()(const wire::LogDownload& d) { log(f.log_.download(d)); }

 private:
  void log(NackReason reason) {
    answer = reason;
    f.log_status_owed_ = true;
  }
};

template <class Chain>
void Flight<Chain>::run_link() {
  uint8_t byte = 0;
  while (rx_.pop(byte)) {
    last_byte_us_ = tick_us_;
    parser_.push(byte, [this](const wire::Frame& frame) { on_frame(frame); });
  }
  // A frame's bytes come within a millisecond; after 50 ms of silence what the parser holds is
  // the start of a frame whose sender stopped (docs/protocol.md, section 4).
  if (parser_.buffered() != 0 && tick_us_ - last_byte_us_ > 50000u) parser_.line_idle();

  chain_.set_pilot(controls_);

  if (log_status_owed_) {
    log_status_owed_ = false;
    send(wire::encode(log_.status()));
  }

  // Parameter reports owed to a param_get: one per tick, so a full report never crowds out
  // telemetry or replies.
  if (report_next_ < report_end_ && tx_.space() >= wire::kMaxFrameBytes) {
    const wire::ParameterSpec& spec = wire::kParameterTable[report_next_++];
    send(wire::encode(wire::ParamReport{static_cast<uint8_t>(spec.id), params_.get(spec.id)}));
  }
}

template <class Chain>
void Flight<Chain>::on_frame(const wire::Frame& frame) {
  const wire::Admission admission = dedup_.admit(frame, uptime_ms_);
  if (admission.duplicate) {
    last_frame_us_ = tick_us_;  // the resend decoded when it was first applied
    send(wire::reply_frame(frame.type, admission.seq, admission.previous));
    return;
  }
  RequestHandler handler{*this};
  const wire::DispatchResult result = wire::dispatch<wire::PcToQrMessages>(frame, handler);
  // Only a frame whose every field is in range proves the console alive: a console sending
  // nothing but out-of-range controls flies on no sticks at all and ends in the link-loss panic
  // (docs/safety.md), not in a flight on the last good ones.
  if (result != wire::DispatchResult::invalid_payload) last_frame_us_ = tick_us_;
  if (!admission.request) return;  // control: periodic, never answered

  const NackReason answer = result == wire::DispatchResult::handled           ? handler.answer
                            : result == wire::DispatchResult::invalid_payload ? NackReason::bad_value
                                                                              : NackReason::not_supported;
  dedup_.record(frame, answer, uptime_ms_);
  send(wire::reply_frame(frame.type, admission.seq, answer));
  if (handler.report.id != 0) send(wire::encode(handler.report));
}

template <class Chain>
void Flight<Chain>::run_safety() {
  const Situation s = situation();
  safety_.supervise(s);
  engines_ = safety_.limit_engines(wanted_, s);

  const Mode now = safety_.mode();
  if (now == announced_mode_) return;
  announced_mode_ = now;
  say("mode: ");
  say(flight_text::kModeNames[index(now)]);
  if (now == Mode::panic) {
    say(" (");
    say(flight_text::kPanicCauses[static_cast<uint8_t>(safety_.panic_cause())]);
    say(")");
  }
  say("\n");
}

template <class Chain>
void Flight<Chain>::run_telemetry() {
  if (++telemetry_count_ < telemetry_divider_) return;
  telemetry_count_ = 0;

  send(wire::encode(wire::TelemetryAttitude{telemetry_seq_++, safety_.mode(), telemetry_flags(), chain_.roll_e4(),
                                            chain_.pitch_e4(), chain_.yaw_e4()}));
  send(wire::encode(wire::TelemetryRates{chain_.p_e3(), chain_.q_e3(), chain_.r_e3()}));
  send_slow_group();
  if (task_stats_ != nullptr) {
    const CycleStats& c = task_stats_->task[stats_task_];
    send(wire::encode(wire::TelemetryTask{stats_task_, saturate_u16(c.min), saturate_u16(c.mean()), saturate_u16(c.max)}));
    stats_task_ = static_cast<uint8_t>((stats_task_ + 1) % kTaskCount);
  }
}

template <class Chain>
uint8_t Flight<Chain>::telemetry_flags() const {
  uint8_t flags = 0;
  if (chain_.calibrated()) flags |= wire::kFlagCalibrated;
  if (log_.logging()) flags |= wire::kFlagLogging;
  if (safety_.battery_warning()) flags |= wire::kFlagBatteryWarning;
  if (log_.full()) flags |= wire::kFlagLogFull;
  return flags;
}

// Engines, set-points, system, link and log status take turns, each at a fifth of the
// telemetry rate.
template <class Chain>
void Flight<Chain>::send_slow_group() {
  const uint8_t group = slow_group_;
  slow_group_ = static_cast<uint8_t>(slow_group_ == 4 ? 0 : slow_group_ + 1);
  if (group == 0) {
    wire::TelemetryEngines m;
    for (int i = 0; i < 4; ++i) m.engine[i] = engines_.value[i];
    send(wire::encode(m));
  } else if (group == 1) {
    send(wire::encode(wire::TelemetrySetpoints{controls_.lift, chain_.roll_setpoint_e4(),
                                               chain_.pitch_setpoint_e4(), chain_.yaw_rate_setpoint_e3()}));
  } else if (group == 2) {
    const uint16_t loop = saturate_u16(loop_time_us_);
    loop_time_us_ = 0;
    send(wire::encode(wire::TelemetrySystem{sample_.battery_mv, cpu_load_permille_, loop,
                                            static_cast<uint16_t>(deadline_misses_)}));
  } else if (group == 4) {
    send(wire::encode(log_.status()));
  } else {
    const wire::LinkCounters& c = parser_.counters();
    send(wire::encode(wire::TelemetryLink{static_cast<uint16_t>(c.frames_ok), static_cast<uint16_t>(c.check_failures),
                                          static_cast<uint16_t>(c.unknown_types),
                                          static_cast<uint16_t>(c.bytes_skipped)}));
  }
}

template <class Chain>
void Flight<Chain>::apply_parameters() {
  using wire::ParamId;
  const auto get = [this](ParamId id) { return static_cast<uint32_t>(params_.get(id)); };
  SafetyLimits& l = safety_.limits();
  l.link_timeout_us = get(ParamId::link_timeout_ms) * 1000u;
  l.battery_warn_mv = static_cast<uint16_t>(get(ParamId::battery_warning_mv));
  l.battery_panic_mv = static_cast<uint16_t>(get(ParamId::battery_panic_mv));
  l.tilt_limit_mrad = static_cast<int32_t>(get(ParamId::tilt_limit_mrad));
  l.panic_level = static_cast<uint16_t>(get(ParamId::panic_level));
  l.panic_hold_us = get(ParamId::panic_hold_ms) * 1000u;
  l.panic_ramp_us = get(ParamId::panic_ramp_ms) * 1000u;
  l.idle = static_cast<uint16_t>(get(ParamId::idle_level));
  telemetry_divider_ = divider_for(get(ParamId::telemetry_rate_hz));
  log_.set_divider(static_cast<uint16_t>(get(ParamId::log_divider)));
  chain_.set_parameters(params_);
}

// A line in each running log every log_divider ticks; otherwise, parts of a download while the
// link has room for them next to a telemetry period's frames.
template <class Chain>
void Flight<Chain>::run_logger() {
  if (log_.due()) {
    wire::SensorLogRecord s;
    s.time_us = tick_us_;
    for (int axis = 0; axis < 3; ++axis) {
      s.gyro[axis] = sample_.gyro[axis];
      s.accel[axis] = sample_.accel[axis];
      s.gyro_filtered[axis] = chain_.gyro_filtered(axis);
      s.accel_filtered[axis] = chain_.accel_filtered(axis);
    }
    s.battery_mv = sample_.battery_mv;

    wire::TelemetryLogRecord t;
    t.time_us = tick_us_;
    t.mode = safety_.mode();
    t.flags = telemetry_flags();
    t.lift = controls_.lift;
    t.roll = chain_.roll_setpoint_e4();
    t.pitch = chain_.pitch_setpoint_e4();
    t.yaw_rate = chain_.yaw_rate_setpoint_e3();
    t.phi = chain_.roll_e4();
    t.theta = chain_.pitch_e4();
    t.psi = chain_.yaw_e4();
    t.p = chain_.p_e3();
    t.q = chain_.q_e3();
    t.r = chain_.r_e3();
    for (int i = 0; i < 4; ++i) t.engine[i] = engines_.value[i];
    t.loop_time_us = saturate_u16(last_busy_us_);
    t.battery_mv = sample_.battery_mv;
    t.cpu_load = cpu_load_permille_;
    t.deadline_misses = static_cast<uint16_t>(deadline_misses_);
    log_.write(s, t);
    return;
  }
  // Room is kept for a telemetry period (attitude, rates, a slow group, a task figure) and a reply.
  constexpr size_t kTxReserve = 64;
  log_.send_parts(4, [this](const wire::FrameBytes& frame) {
    if (tx_.space() < size_t{frame.size} + kTxReserve) return false;
    send(frame);
    return true;
  });
}

template <class Chain>
uint8_t Flight<Chain>::leds() const {
  // One LED per state the pilot must see at a glance: safe, panic, flying, battery warning.
  const Mode m = safety_.mode();
  const bool flying = m == Mode::manual || m == Mode::yaw_control || m == Mode::full_control;
  return static_cast<uint8_t>((m == Mode::safe ? 1u : 0u) | (m == Mode::panic ? 2u : 0u) | (flying ? 4u : 0u) |
                              (safety_.battery_warning() ? 8u : 0u));
}

template <class Chain>
void Flight<Chain>::send(const wire::FrameBytes& frame) {
  if (!tx_.push(frame.bytes, frame.size)) ++tx_dropped_;
}

template <class Chain>
void Flight<Chain>::say(const char* text) {
  while (*text != '\0') {
    wire::DebugText piece;
    text += piece.fill(text, wire::kDebugTextChars);
    send(wire::encode(piece));
  }
}

}  // namespace qr
