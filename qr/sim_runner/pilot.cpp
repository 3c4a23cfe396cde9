#include <qr/sim_runner/pilot.hpp>

#include <algorithm>
#include <cmath>

#include <common/link_timing.hpp>

namespace qrsim {

Pilot::Pilot(SimBoard& board, uint8_t first_seq) : board_(board), resend_(first_seq) {}

void Pilot::send(const wire::FrameBytes& frame) {
  if (silent_ && !radio_) return;  // with a radio, silence is the radio's
  for (uint8_t i = 0; i < frame.size; ++i) put(frame.bytes[i]);
}

void Pilot::damage_line(const LineFaults& faults) {
  faults_ = faults;
  damaged_ = true;
  rng_.seed(faults.seed);
  next_garbage_us_ = board_.world().now_us() + faults.garbage_every_us;
}

bool Pilot::lost() { return damaged_ && std::uniform_real_distribution<double>(0, 1)(rng_) < faults_.byte_loss; }

void Pilot::put(uint8_t byte) {
  ++counts_.bytes_up;
  if (lost()) {
    ++counts_.bytes_up_lost;
    return;
  }
  board_.pc_send(byte);
  if (on_bytes_up_) on_bytes_up_(byte);
}

void Pilot::request_mode(wire::Mode mode) {
  // With a radio, a mode its mode switch has a position for is armed by the switch (off, then
  // on). Any other goes to the QR as the console's key sends it (pc/core/radio_pilot.hpp): safe,
  // panic and calibration stay the PC's, and a flying mode the radio does not arm (height hold,
  // acro) the QR refuses, radio_is_pilot (docs/safety.md rule 17).
  if (radio_ && transmitter_.arm(mode, board_.world().now_us())) return;
  const uint32_t now_ms = static_cast<uint32_t>(board_.world().now_us() / 1000);
  send(resend_.submit(wire::ModeChange{0, mode}, now_ms));
}

void Pilot::set_parameter(wire::ParamId id, int32_t raw) {
  const uint32_t now_ms = static_cast<uint32_t>(board_.world().now_us() / 1000);
  send(resend_.submit(wire::ParamSet{0, static_cast<uint8_t>(id), raw}, now_ms));
}

void Pilot::step() {
  const uint64_t now_us = board_.world().now_us();

  uint8_t byte = 0;
  uint64_t sent_at_us = 0;
  for (;;) {
    uint64_t at = 0;
    const bool has = board_.pc_next_sent_at_us(at);
    if (!board_.pc_receive(byte)) break;
    ++counts_.bytes_down;
    if (lost()) {
      ++counts_.bytes_down_lost;
      continue;
    }
    // A frame's start byte carries the time of the tick that sent it.
    if (has && parser_.buffered() == 0) sent_at_us = at;
    parser_.push(byte, [&](const wire::Frame& frame) { on_frame(frame, sent_at_us); });
  }

  const uint32_t now_ms = static_cast<uint32_t>(now_us / 1000);
  wire::ResendEvent event;
  while (resend_.poll(now_ms, event)) {
    if (event.kind == wire::ResendEvent::Kind::resend) {
      send(event.frame);
    } else {
      ++view_.requests_given_up;
    }
  }

  if (damaged_ && faults_.garbage_every_us != 0 && now_us >= next_garbage_us_) {
    next_garbage_us_ = now_us + faults_.garbage_every_us;
    const uint32_t n = std::uniform_int_distribution<uint32_t>(1, faults_.garbage_max_bytes)(rng_);
    ++counts_.garbage_bursts;
    counts_.garbage_bytes += n;
    for (uint32_t i = 0; i < n; ++i) put(static_cast<uint8_t>(rng_()));
  }

  if (now_us >= next_control_us_) {
    next_control_us_ = now_us + wire::kControlPeriodMs * 1000;
    send(wire::encode(sticks_));
  }
  if (radio_) {
    transmitter_.set_sticks(sticks_);
    transmitter_.step(now_us, silent_, board_);
  }
}

void Pilot::on_frame(const wire::Frame& frame, uint64_t sent_at_us) {
  struct Handler {
    Pilot& p;
    uint64_t at;
    void operator()(const wire::TelemetryAttitude& m) {
      p.view_.heard = true;
      p.view_.mode = m.mode;
      p.view_.flags = m.flags;
      p.view_.attitude_at_us = at;
      p.view_.phi_e4 = m.phi;
      p.view_.theta_e4 = m.theta;
      p.view_.psi_e4 = m.psi;
    }
    void operator()(const wire::Ack& m) {
      if (p.resend_.on_ack(m) == wire::AnswerMatch::matched) ++p.view_.acks;
    }
    void operator()(const wire::Nack& m) {
      if (p.resend_.on_nack(m) == wire::AnswerMatch::matched) {
        ++p.view_.nacks;
        p.view_.last_nack = m.reason;
      }
    }
    void operator()(const wire::DebugText& m) { p.view_.debug_text.append(m.text, m.length()); }
    void operator()(const wire::TelemetryRpm& m) {
      for (int i = 0; i < 4; ++i) p.view_.rpm[i] = m.rpm[i];
    }
    void operator()(const wire::TelemetryRadio& m) { p.view_.radio_flags = m.flags; }
  };
  Handler handler{*this, sent_at_us};
  wire::dispatch(frame, handler);
  if (on_every_frame_) on_every_frame_(frame, parser_.counters());
}

uint16_t lift_for_height(const sim::Quadrotor& plant, double target, double ramp, double trim) {
  const sim::PlantState& s = plant.state();
  const double height = -s.position.z, climb = -s.velocity.z;
  const double accel = std::clamp(2.0 * (target - height) - 2.5 * climb + trim, -3.0, 3.0);
  const sim::Vec3 body_down = sim::rotate(s.attitude, {0, 0, 1});
  const double cos_tilt = std::max(0.5, body_down.z);
  const double thrust_ratio = std::max(0.0, (sim::kGravity + accel) / (sim::kGravity * cos_tilt));
  const double lift = plant.hover_command() * std::sqrt(thrust_ratio) * std::clamp(ramp, 0.0, 1.0);
  return static_cast<uint16_t>(std::clamp(std::lround(lift), 0L, 1000L));
}

uint16_t HeightThumb::lift(const sim::Quadrotor& plant, double target, double ramp, double dt) {
  const double error = target + plant.state().position.z;  // target - height
  if (std::abs(error) < 0.5 && std::abs(plant.state().velocity.z) < 0.5)
    trim_ = std::clamp(trim_ + 0.5 * error * dt, -2.0, 2.0);
  return lift_for_height(plant, target, ramp, trim_);
}

}  // namespace qrsim
