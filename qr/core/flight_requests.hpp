// Applying the pilot's messages: each decoded message from the console becomes a change to the
// flight (sticks, a mode request, a motor test, a parameter, a log command); for a request, `answer` is what
// its ack or nack says. Included by flight_link.hpp, whose on_frame() dispatches to it.
#pragma once

#include <common/messages.hpp>
#include <common/parameter_table.hpp>

namespace qr {

// The parameters the attitude estimator's state depends on.
constexpr bool feeds_estimator(uint8_t id) {
  using wire::ParamId;
  return id == static_cast<uint8_t>(ParamId::attitude_c1) || id == static_cast<uint8_t>(ParamId::attitude_c2) ||
         id == static_cast<uint8_t>(ParamId::accel_lag_ms) || id == static_cast<uint8_t>(ParamId::imu_orientation);
}

template <class Flight>
struct FlightRequests {
  Flight& f;
  NackReason answer = NackReason::none;
  wire::ParamReport report{};  // id 0: nothing to report

  void operator()(const wire::Control& c) {
    if (f.pilot_ != Pilot::pc) return;  // the radio flies: the PC's sticks are nobody's (rule 17)
    f.controls_ = ControlInput{c.lift, c.roll, c.pitch, c.yaw};
    f.pilot_changed_ = true;
    // A lift change ends height hold before the chain runs this tick.
    f.safety_.sticks_moved(f.controls_);
  }
  void operator()(const wire::ModeChange& m) {
    answer = f.safety_.request(static_cast<uint8_t>(m.mode), f.situation());
  }
  void operator()(const wire::ParamSet& p) {
    // Who flies (docs/safety.md rule 17) and how the IMU sits in the frame change in safe only;
    // the value in force is no change (a console sends every parameter at its start, whatever
    // the mode).
    // An array, not a braced list: the RV32 toolchain has no <initializer_list> (freestanding).
    static constexpr wire::ParamId kSafeOnly[] = {wire::ParamId::pilot, wire::ParamId::imu_orientation};
    for (const wire::ParamId safe_only : kSafeOnly) {
      if (p.id == static_cast<uint8_t>(safe_only) && p.value != f.params_.get(safe_only) &&
          f.safety_.mode() != Mode::safe) {
        answer = NackReason::not_from_this_mode;
        return;
      }
    }
    answer = f.params_.set(p.id, p.value);
    if (answer != NackReason::none) return;
    f.apply_parameters();
    // The estimator's state is what its divisors made of it: a value it cannot track with (C2 at
    // 1 ruins the bias estimate in a few ticks) would outlive its own undoing. On the ground
    // (safe) the accelerometer reads the tilt, so the estimator starts over from it; in flight it
    // could not, and the change applies as it comes (docs/safety.md, rule 13).
    if (feeds_estimator(p.id) && f.safety_.mode() == Mode::safe) f.chain_.restart_estimator();
    report = wire::ParamReport{p.id, p.value};  // after the ack: the value now in force
  }
  void operator()(const wire::ParamGet& g) {
    if (g.id == wire::kAllParameters) {
      f.report_next_ = 0;
      f.report_end_ = static_cast<uint8_t>(wire::kParameterCount);
      return;
    }
    for (uint8_t row = 0; row < wire::kParameterCount; ++row) {
      if (static_cast<uint8_t>(wire::kParameterLimits[row].id) == g.id) {
        f.report_next_ = row;
        f.report_end_ = static_cast<uint8_t>(row + 1);
        return;
      }
    }
    answer = NackReason::unknown_parameter;
  }
  void operator()(const wire::Exit&) { f.safety_.request_exit(f.situation()); }
  void operator()(const wire::EscDirection& d) {
    answer = f.esc_direction_.request(d.engine, d.direction, f.safety_.mode(), f.engines_, f.tick_us_);
  }
  void operator()(const wire::MotorTest& m) { answer = f.safety_.request_motor_test(m.engine, m.level, f.situation()); }
  void operator()(const wire::ObservableGet& g) {
    answer = kObservableStreams ? f.streams_.request_table(g.id) : NackReason::not_supported;
  }
  void operator()(const wire::StreamRequest& r) {
    answer = kObservableStreams ? f.streams_.request(r, kControlHz, kControlHz / f.telemetry_divider())
                                : NackReason::not_supported;
  }
  void operator()(const wire::LogStart& l) { log(f.log_.start(l.logs, kControlHz / f.log_divider())); }
  void operator()(const wire::LogStop&) { log(f.log_.stop()); }
  void operator()(const wire::LogDownload& d) { log(f.log_.download(d)); }
  // No log_status after it: a bad line brings many, and the logs' sizes have not changed.
  void operator()(const wire::LogResend& r) { answer = f.log_.resend(r); }

 private:
  void log(NackReason reason) {
    answer = reason;
    f.log_status_owed_ = true;
  }
};

}  // namespace qr
