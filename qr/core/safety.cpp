#include <stddef.h>

#include <common/battery_rest.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/safety.hpp>

namespace qr {
namespace {

constexpr const wire::ModeSpec& rule(Mode m) { return wire::mode_spec(m); }

// log2 of the control rate, rounded up: the battery filter's shift (time constant 1.02 s at 1 kHz
// and at 500 Hz).
constexpr int filter_shift(uint32_t hz) {
  int k = 0;
  while ((1u << k) < hz) ++k;
  return k;
}
constexpr int kBatteryFilterShift = filter_shift(kControlHz);
static_assert((1u << kBatteryFilterShift) >= kControlHz && kControlHz > (1u << kBatteryFilterShift) / 2);
// The flying lift's low-pass: a quarter of the battery's time constant, 0.26 s.
constexpr int kFlyingLiftShift = kBatteryFilterShift - 2;

// A request into a mode other than safe/panic must pass every guard, in this order.
struct Guard {
  NackReason reason;
  bool (*blocks)(Mode from, Mode to, const Situation& s, const SafetyLimits& l);
};

constexpr Guard kGuards[] = {
    // One pilot at a time: while the radio flies, only its arm switch enters a flight mode, and the
    // PC spins no engine (its lift, which would stop a motor test, is nobody's).
    {NackReason::radio_is_pilot,
     [](Mode, Mode to, const Situation& s, const SafetyLimits&) {
       return s.pilot != s.requester && (rule(to).flies || to == Mode::motor_test);
     }},
    {NackReason::not_from_this_mode,
     [](Mode from, Mode to, const Situation&, const SafetyLimits&) { return from != rule(to).entered_from; }},
    // Leaving safe: the pilot's hands and the engines at rest (height hold is entered in flight).
    // Leaving safe needs an IMU that streams (rule 20): calibration would average a held or
    // missing signal, and every mode but manual flies on it.
    {NackReason::imu_fault,
     [](Mode from, Mode, const Situation& s, const SafetyLimits&) { return from == Mode::safe && !s.imu_healthy; }},
    {NackReason::controls_not_neutral, [](Mode from, Mode, const Situation& s,
                                          const SafetyLimits&) { return from == Mode::safe && !s.controls.neutral(); }},
    {NackReason::engines_running, [](Mode from, Mode, const Situation& s,
                                     const SafetyLimits&) { return from == Mode::safe && !s.engines.all_zero(); }},
    {NackReason::not_calibrated, [](Mode, Mode to, const Situation& s,
                                    const SafetyLimits&) { return rule(to).needs_calibration && !s.calibrated; }},
    // A loop that the vehicle answers the wrong way flies it over (rule 21): the sign check's
    // verdict holds until a calibration finds none.
    {NackReason::sign_check, [](Mode, Mode to, const Situation& s,
                                const SafetyLimits&) { return rule(to).needs_calibration && s.wrong_sign != 0; }},
    // A height to hold needs the barometer's reference, made by the calibration.
    {NackReason::not_calibrated,
     [](Mode, Mode to, const Situation& s, const SafetyLimits&) { return rule(to).holds_height && !s.height_valid; }},
    // A mode entered in flight needs the vehicle flying: a height to hold, a hover to excite.
    {NackReason::not_flying,
     [](Mode, Mode to, const Situation& s, const SafetyLimits&) { return wire::entered_in_flight(to) && s.landed; }},
    // The height to hold is the barometer's (rule 20); full control does without it.
    {NackReason::barometer_fault, [](Mode, Mode to, const Situation& s,
                                     const SafetyLimits&) { return rule(to).holds_height && !s.barometer_healthy; }},
    {NackReason::battery_low,
     [](Mode, Mode, const Situation& s, const SafetyLimits& l) { return s.battery_mv < l.battery_panic_mv; }},
};

// A panic lands (level, a bounded descent on the height estimate, the engines stopped at
// touchdown) only when everything it flies on is trusted; each row is one thing it needs.
// Otherwise it is the IN4073 cut: hold, ramp, safe.
struct LandingNeed {
  bool (*met)(Mode from, PanicCause cause, const Situation& s, uint16_t flying_lift, const SafetyLimits& l);
};

constexpr LandingNeed kLandingNeeds[] = {
    // The attitude loops fly it level: a mode that flies on the attitude estimate, calibrated.
    {[](Mode from, PanicCause, const Situation&, uint16_t, const SafetyLimits&) { return rule(from).needs_attitude; }},
    {[](Mode, PanicCause, const Situation& s, uint16_t, const SafetyLimits&) { return s.calibrated; }},
    // The descent is flown on the height estimate's vertical speed.
    {[](Mode, PanicCause, const Situation& s, uint16_t, const SafetyLimits&) { return s.height_valid; }},
    // Both fly on the sensors: the level on the IMU, the descent on the barometer (rule 20).
    {[](Mode, PanicCause, const Situation& s, uint16_t, const SafetyLimits&) {
      return s.imu_healthy && s.barometer_healthy;
    }},
    // Loops that push the vehicle further cannot level it (rule 21).
    {[](Mode, PanicCause cause, const Situation&, uint16_t, const SafetyLimits&) {
      return cause != PanicCause::wrong_sign;
    }},
    // It was flying: some lift above idle in the last quarter second (a lift stick let go an
    // instant before the panic still counts; a vehicle resting with its engines still does not).
    {[](Mode, PanicCause, const Situation&, uint16_t flying_lift, const SafetyLimits& l) {
      return flying_lift > l.idle;
    }},
};

// Watchdogs that end a flight: each is checked every tick in the modes it applies to.
// Conditions that count only when they last: a load spike is no empty battery, an upset that
// recovers is no lost vehicle.
struct Lasting {
  bool battery_low;
  bool tilt;
};

struct Watchdog {
  PanicCause cause;
  bool (*tripped)(const Situation& s, const SafetyLimits& l, Mode m, const Lasting& lasting);
};

constexpr Watchdog kWatchdogs[] = {
    {PanicCause::link_lost, [](const Situation& s, const SafetyLimits& l, Mode,
                               const Lasting&) { return s.now_us - s.last_frame_us > l.link_timeout_us; }},
    {PanicCause::battery_low,
     [](const Situation&, const SafetyLimits&, Mode, const Lasting& lasting) { return lasting.battery_low; }},
    {PanicCause::tilt, [](const Situation&, const SafetyLimits&, Mode m,
                          const Lasting& lasting) { return rule(m).needs_attitude && lasting.tilt; }},
    // The IMU lost in a mode that flies on it (rule 20). Its time is the driver's: lost after
    // kLostAfterFailures failed reads in a row (10 ms at 1 kHz), the last sample held till then.
    // Manual flies the sticks open loop and needs no sensor: it flies on.
    {PanicCause::imu_lost, [](const Situation& s, const SafetyLimits&, Mode m,
                              const Lasting&) { return rule(m).needs_calibration && !s.imu_healthy; }},
    // The vehicle answers its loops the wrong way (rule 21): the engines stop at once.
    {PanicCause::wrong_sign, [](const Situation& s, const SafetyLimits&, Mode m,
                                const Lasting&) { return rule(m).needs_calibration && s.wrong_sign != 0; }},
};

constexpr size_t kWatchdogCount = sizeof(kWatchdogs) / sizeof(kWatchdogs[0]);

// The first watchdog in table order that has tripped (none: PanicCause::none). Unrolled over the
// table at compile time, so each check is a direct call the compiler inlines: this runs every tick,
// and three calls through pointers cost more than the checks themselves.
template <size_t I = 0>
[[gnu::always_inline]] inline PanicCause first_tripped(const Situation& s, const SafetyLimits& l, Mode m,
                                                       const Lasting& lasting) {
  if constexpr (I == kWatchdogCount) {
    return PanicCause::none;
  } else {
    constexpr Watchdog w = kWatchdogs[I];
    if (w.tripped(s, l, m, lasting)) return w.cause;
    return first_tripped<I + 1>(s, l, m, lasting);
  }
}

uint16_t scale(uint16_t v, uint32_t num, uint32_t den) {
  return static_cast<uint16_t>(static_cast<uint32_t>(v) * num / den);
}

}  // namespace

SafetyLimits safety_limits(const wire::ParameterValues& p) {
  using wire::ParamId;
  const auto get = [&p](ParamId id) { return static_cast<uint32_t>(p.get(id)); };
  SafetyLimits l{};
  l.link_timeout_us = get(ParamId::link_timeout_ms) * 1000u;
  l.battery_warn_mv = static_cast<uint16_t>(get(ParamId::battery_warning_mv));
  l.battery_panic_mv = static_cast<uint16_t>(get(ParamId::battery_panic_mv));
  l.tilt_limit_mrad = static_cast<int32_t>(get(ParamId::tilt_limit_mrad));
  l.tilt_time_us = get(ParamId::tilt_time_ms) * 1000u;
  l.panic_hold_pct = static_cast<uint16_t>(get(ParamId::panic_level));
  l.descent_mm_s = static_cast<uint16_t>(get(ParamId::panic_descent_mm_s));
  l.panic_hold_us = get(ParamId::panic_hold_ms) * 1000u;
  l.panic_ramp_us = get(ParamId::panic_ramp_ms) * 1000u;
  l.idle = static_cast<uint16_t>(get(ParamId::idle_level));
  l.battery_sag_mv = static_cast<uint16_t>(get(ParamId::battery_sag_mv));
  return l;
}

NackReason SafetyMachine::refusal(Mode to, const Situation& s) const {
  for (const Guard& g : kGuards) {
    if (g.blocks(mode_, to, s, limits_)) return g.reason;
  }
  return NackReason::none;
}

NackReason SafetyMachine::request(uint8_t wanted, const Situation& s) {
  // Any mode request ends a motor test at once, in safe (rule 22); it is then judged from there.
  if (mode_ == Mode::motor_test) enter(Mode::safe);
  if (wanted >= kModeCount) return NackReason::unknown_mode;
  const Mode to = static_cast<Mode>(wanted);
  // The motor test says its engine and level: its own request enters it, never a mode change.
  if (to == Mode::motor_test) return NackReason::bad_value;
  if (to == mode_) return NackReason::none;

  // The pilot's toggle out of height hold or the autotune: back to full control, flying on.
  if (wire::entered_in_flight(mode_) && to == Mode::full_control) {
    enter(to);
    return NackReason::none;
  }

  if (to == Mode::safe || to == Mode::panic) {
    if (rule(mode_).flies) {
      enter_panic(PanicCause::requested, s);
    } else if (mode_ != Mode::panic) {
      enter(Mode::safe);  // engines are not turning: nothing to ramp down
    }
    return NackReason::none;
  }

  const NackReason refused = refusal(to, s);
  if (refused != NackReason::none) return refused;
  held_ = s.controls;
  enter(to);
  return NackReason::none;
}

NackReason SafetyMachine::request_motor_test(uint8_t engine, uint16_t level, const Situation& s) {
  // A motor test asked for during one ends it: the pilot starts the next from safe.
  if (mode_ == Mode::motor_test) {
    enter(Mode::safe);
    return NackReason::not_from_this_mode;
  }
  if (engine >= 4 || level > wire::kMotorTestMaxLevel) return NackReason::bad_value;
  const NackReason refused = refusal(Mode::motor_test, s);
  if (refused != NackReason::none) return refused;
  test_engine_ = engine;
  test_level_ = level;
  test_start_us_ = s.now_us;
  enter(Mode::motor_test);
  return NackReason::none;
}

void SafetyMachine::request_exit(const Situation& s) {
  exit_pending_ = true;
  request(index(Mode::safe), s);
  supervise(s);
}

NackReason SafetyMachine::radio_switches(bool arm, Mode wanted, const Situation& s) {
  // A frame after a silence longer than the link timeout is the link coming back.
  if (!radio_heard_ || s.now_us - radio_heard_us_ > limits_.link_timeout_us) arm_seen_off_ = false;
  radio_heard_ = true;
  radio_heard_us_ = s.now_us;
  arm_on_ = arm;
  if (!arm) {
    arm_seen_off_ = true;
    if (rule(mode_).flies) enter_panic(PanicCause::disarmed, s);  // the pilot's emergency stop
    return NackReason::none;
  }
  if (!arm_seen_off_) return NackReason::none;
  // One movement, one attempt: a refused arming waits for the next, and so does a movement made
  // outside safe (the emergency stop's switch put back on while the panic lands the vehicle must
  // not start the engines once it is down).
  arm_seen_off_ = false;
  if (mode_ != Mode::safe) return NackReason::none;
  return request(index(wanted), s);
}

void SafetyMachine::calibration_finished() {
  if (mode_ == Mode::calibration) enter(Mode::safe);
}

void SafetyMachine::sticks_moved(const ControlInput& c) {
  if (mode_ == Mode::height_hold && c.lift != held_.lift) enter(Mode::full_control);
  // The autotune flies the sticks it was entered with: any movement is the pilot taking over.
  if (mode_ == Mode::autotune &&
      (c.lift != held_.lift || c.roll != held_.roll || c.pitch != held_.pitch || c.yaw != held_.yaw)) {
    enter(Mode::full_control);
  }
  if (mode_ == Mode::motor_test && c.lift > 0) enter(Mode::safe);
}

void SafetyMachine::supervise(const Situation& s) {
  // The lift that was flying: the engines' mean, low-passed, frozen while panicking.
  if (mode_ != Mode::panic) {
    const uint32_t mean_q8 = (uint32_t{s.engines.value[0]} + s.engines.value[1] + s.engines.value[2] +
                              s.engines.value[3])
                             << 6;
    flying_q8_ = static_cast<uint32_t>(
        static_cast<int32_t>(flying_q8_) +
        ((static_cast<int32_t>(mean_q8) - static_cast<int32_t>(flying_q8_)) >> kFlyingLiftShift));
  }
  // First-order low-pass, alpha = 2^-k per tick with 2^k the control rate rounded up to a power of
  // two: a time constant of 1.02 s at 1 kHz and at 500 Hz. Starts at the first sample (no transient from zero).
  const uint32_t sample_q8 = static_cast<uint32_t>(
                                 wire::battery_rested_mv(s.battery_mv, s.engines.value, limits_.battery_sag_mv))
                             << 8;
  if (battery_q8_ == 0) battery_q8_ = sample_q8;
  battery_q8_ = static_cast<uint32_t>(
      static_cast<int32_t>(battery_q8_) +
      ((static_cast<int32_t>(sample_q8) - static_cast<int32_t>(battery_q8_)) >> kBatteryFilterShift));
  const uint16_t measure = battery_measure_mv();
  // The warning comes below its level and goes only clearly above it: no flicker on the edge.
  if (measure < limits_.battery_warn_mv) {
    battery_warning_ = true;
  } else if (measure >= limits_.battery_warn_mv + limits_.battery_hysteresis_mv) {
    battery_warning_ = false;
  }
  const bool below = measure < limits_.battery_panic_mv;
  if (below && !battery_low_) battery_low_since_us_ = s.now_us;
  battery_low_ = below;
  const bool battery_low_long = below && s.now_us - battery_low_since_us_ >= limits_.battery_trip_us;
  const bool tilted = s.tilt_mrad > limits_.tilt_limit_mrad;
  if (tilted && !tilted_) tilted_since_us_ = s.now_us;
  tilted_ = tilted;
  const Lasting lasting{battery_low_long, tilted && s.now_us - tilted_since_us_ >= limits_.tilt_time_us};

  if (rule(mode_).flies) {
    const PanicCause cause = first_tripped(s, limits_, mode_, lasting);
    if (cause != PanicCause::none) enter_panic(cause, s);
  }

  // Height hold without its barometer: back to full control, where the pilot's lift flies (rule 20).
  if (mode_ == Mode::height_hold && !s.barometer_healthy) enter(Mode::full_control);

  // The autotune ends in full control when its sequence is over, when its excitation has taken the
  // vehicle beyond its few degrees, or when the battery warns (rule 23).
  if (mode_ == Mode::autotune &&
      (s.identification_over || s.tilt_mrad > limits_.autotune_tilt_mrad || battery_warning_)) {
    enter(Mode::full_control);
  }

  // The motor test ends by itself after its time, and at once when the pilot's link falls silent:
  // a console that can no longer stop it must not leave an engine turning (rule 22).
  if (mode_ == Mode::motor_test &&
      (s.now_us - test_start_us_ >= limits_.motor_test_us || s.now_us - s.last_frame_us > limits_.link_timeout_us)) {
    enter(Mode::safe);
  }

  if (mode_ == Mode::panic) {
    const uint32_t elapsed = s.now_us - panic_start_us_;
    // A panic entered in this very call sees the chain's verdict from before its descent began
    // (a lift stick let go reads "landed"): only a later tick's touchdown counts.
    if (landing_ && s.landed && elapsed > 0) {
      enter(Mode::safe);  // touched down: the engines stop this tick
    } else if (landing_ && elapsed >= descent_limit_us_) {
      // No touchdown in twice the time the descent needs: the landing is not working; the cut.
      landing_ = false;
      panic_start_us_ = s.now_us;
    } else if (!landing_ && elapsed >= limits_.panic_hold_us + limits_.panic_ramp_us) {
      enter(Mode::safe);
    }
  }
  if (exit_pending_ && mode_ == Mode::safe) stopped_ = true;
}

EngineCommand SafetyMachine::limit_engines(const EngineCommand& wanted, const Situation& s) const {
  EngineCommand out;
  if (mode_ == Mode::panic && landing_) {
    // The chain flies the landing (level, descending): its engines, within their range.
    for (int i = 0; i < 4; ++i) out.value[i] = wanted.value[i] > kEngineMax ? kEngineMax : wanted.value[i];
    return out;
  }
  if (mode_ == Mode::panic) {
    // The cut: all four engines alike (no moment), held, then ramped to zero.
    const uint32_t t = s.now_us - panic_start_us_;
    const uint32_t end = limits_.panic_hold_us + limits_.panic_ramp_us;
    const uint16_t hold = hold_level_;
    for (int i = 0; i < 4; ++i) {
      out.value[i] = t < limits_.panic_hold_us ? hold : t < end ? scale(hold, end - t, limits_.panic_ramp_us) : 0;
    }
    return out;
  }
  if (mode_ == Mode::motor_test) {
    out.value[test_engine_] = test_level_;  // the others stay zero
    return out;
  }
  if (!rule(mode_).flies || s.controls.lift == 0) return out;
  for (int i = 0; i < 4; ++i) {
    const uint16_t v = wanted.value[i];
    out.value[i] = v < limits_.idle ? limits_.idle : v > kEngineMax ? kEngineMax : v;
  }
  return out;
}

void SafetyMachine::enter_panic(PanicCause cause, const Situation& s) {
  landing_ = true;
  for (const LandingNeed& need : kLandingNeeds) {
    if (!need.met(mode_, cause, s, flying_lift(), limits_)) landing_ = false;
  }
  enter(Mode::panic);
  panic_cause_ = cause;
  panic_start_us_ = s.now_us;
  // A tilt with no trusted estimate to level it by: held at 90 % with no attitude control the
  // engines would drive the tilted vehicle sideways and over. They stop at once; so they do for a
  // vehicle answering the wrong way (rule 21), which the cut's first instants take off the ground.
  const bool stop = cause == PanicCause::tilt || cause == PanicCause::wrong_sign;
  hold_level_ = stop ? uint16_t{0} : scale(flying_lift(), limits_.panic_hold_pct, 100);
  // Twice the time to descend from the height estimate (at most 100 m) plus 2 m, at the descent
  // rate: (h + 2000 mm) x 2000 / v ms. A division, once per panic.
  const int32_t h = s.height_mm < 0 ? 0 : s.height_mm > 100000 ? 100000 : s.height_mm;
  const uint32_t rate = limits_.descent_mm_s == 0 ? 1u : limits_.descent_mm_s;
  descent_limit_us_ = static_cast<uint32_t>(h + 2000) * 2000u / rate * 1000u;
}

}  // namespace qr
