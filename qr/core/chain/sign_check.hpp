// The sign check (docs/safety.md rule 21): does the vehicle answer its controllers the right way?
// The IN4073 report's team never flew stabilised because their feedback had the wrong sign; a
// first build can get the same from a motor on the wrong output or turning the wrong way, an IMU
// mounted turned, a sensor axis read backwards. Three checks, each for what it can see:
//
// - The probe, on the ground, at the end of every calibration: each loop (roll, pitch, yaw) is
//   given a small known error on a copy of itself, its answer goes through a copy of the mixer,
//   and the engines are read back through the model of engine_mixer.hpp run forwards. The moment
//   they make must not push the error further. This is the check that would have caught the
//   report's controller: a sign lost in a loop or in the mixer, which no sensor can show on the
//   ground.
// - The wrong-way monitor, in the first flight after a calibration, from the engines' start
//   until 1 s after the take-off: on each axis the loops fly, the loops pushing against the
//   measured rate for most of 20 ms while that rate still grows is a vehicle that answers the
//   wrong way. Judged only while the sticks ask for no motion (set-points within 3 degrees and
//   0.1 rad/s, as at a take-off): a rate the pilot asked for, braked as the stick comes back, is
//   not. Two such 20 ms blocks in a row on one axis are the verdict. This sees what only the air
//   shows: the wiring and the mounting (the probe trusts the geometry it was written for).
// - The lift-off kick (below), in the same flight, from the take-off for 160 ms: a known push on
//   roll then pitch, whose answer must turn the vehicle about the pushed axis the way it was
//   pushed. It finds in a tenth of a second what the monitor sees only once it has grown.
//
// A verdict names its axis; the safety machine refuses yaw and full control on it, or in the air
// cuts the engines at once (safety.cpp).
#pragma once

#include <stdint.h>

#include <qr/core/board.hpp>
#include <qr/core/control_rate.hpp>

namespace qr::chain {

enum class SignAxis : uint8_t { none = 0, roll, pitch, yaw };
inline constexpr const char* kSignAxisNames[] = {"", "roll", "pitch", "yaw"};

// What engines do to the airframe by the mixer's model read forwards (engine_mixer.hpp): engine i
// gives thrust w_i = ae_i^2 (in thousandths of thrust units), and
//   roll L = w3 - w1, pitch M = w0 - w2, yaw N = w1 + w3 - w0 - w2.
struct AxisMoments {
  int32_t axis[3] = {0, 0, 0};  // roll, pitch, yaw
};

constexpr AxisMoments moments_of(const EngineCommand& e) {
  int32_t w[4] = {};
  for (int i = 0; i < 4; ++i) {
    const int32_t v = e.value[i];
    w[i] = v * v;  // <= 10^6
  }
  return {{w[3] - w[1], w[0] - w[2], w[1] + w[3] - w[0] - w[2]}};
}

// The probe's known errors: the estimate 3 degrees (0.05 rad) off its set-point of 0 on roll and
// pitch, the yaw rate 0.5 rad/s off 0; positive, so each answer must be negative. The lift the
// mixer mixes them into: a hover's, where no moment is scaled away.
template <class Angle>
inline constexpr Angle kProbeAngle = Angle(0.05);
template <class Rate>
inline constexpr Rate kProbeYawRate = Rate(0.5);
inline constexpr uint16_t kProbeLift = 500;

// The first axis whose loop, answering a positive error, makes a positive moment on its own axis
// (none: every answer opposes its error, or is zero, as with a gain set to 0). `Loops` gives a
// loop's answer by axis, as moments for the mixer; `Mixer` is a copy that may be changed.
template <class Loops, class Mixer, class Thrust>
SignAxis probe_signs(Loops& loops, Mixer& mixer, Thrust lift) {
  for (int axis = 0; axis < 3; ++axis) {
    const AxisMoments made = moments_of(mixer.mix_thrust(lift, loops.answer(axis)));
    if (made.axis[axis] > 0) return static_cast<SignAxis>(axis + 1);
  }
  return SignAxis::none;
}

class WrongWayMonitor {
 public:
  static constexpr uint32_t kBlockTicks = kControlHz / 50;  // 20 ms
  static constexpr uint32_t kWindowTicks = kControlHz;      // 1 s after the take-off
  // A growth a vehicle that answers rightly does not show while its loops push against it: at
  // least 0.3 rad/s (17 deg/s, which no take-off turns at), grown by 0.1 rad/s in 20 ms.
  static constexpr int32_t kMinRateMrad = 300;
  static constexpr int32_t kGrowthMrad = 100;
  // The loops push: at least 2 % of one engine's thrust (thrust units), for 3/4 of a block.
  static constexpr int32_t kMinMoment = 20;
  static constexpr uint32_t kAgainstTicks = kBlockTicks * 3 / 4;
  static constexpr uint8_t kStrikes = 2;

  // From the end of a calibration: the next flight is watched.
  void arm() {
    *this = WrongWayMonitor{};
    watching_ = true;
  }
  bool watching() const { return watching_; }

  // One tick. `moment`: what the last mix asked of each axis (thrust units); `rate`: the rates now
  // (mrad/s); `loops`: bit i set where the loops fly axis i; `landed`: the landed detector's
  // verdict; `lifting`: the engines are asked to turn. The axis of a verdict, once; else none.
  SignAxis update(const int32_t (&moment)[3], const int32_t (&rate)[3], uint8_t loops, bool landed, bool lifting) {
    if (!lifting || loops == 0) return SignAxis::none;
    if (!landed && ++airborne_ticks_ > kWindowTicks) {
      watching_ = false;
      return SignAxis::none;
    }
    for (int i = 0; i < 3; ++i) {
      if ((loops & (1u << i)) != 0 && push_against(moment[i], rate[i])) ++against_[i];
    }
    if (++block_tick_ < kBlockTicks) return SignAxis::none;
    block_tick_ = 0;
    for (int i = 0; i < 3; ++i) {
      const bool wrong = against_[i] >= kAgainstTicks && grew(start_[i], rate[i]);
      strikes_[i] = wrong ? static_cast<uint8_t>(strikes_[i] + 1) : uint8_t{0};
      against_[i] = 0;
      start_[i] = rate[i];
      if (strikes_[i] >= kStrikes) {
        watching_ = false;
        return static_cast<SignAxis>(i + 1);
      }
    }
    return SignAxis::none;
  }

 private:
  static constexpr int32_t magnitude(int32_t v) { return v < 0 ? -v : v; }
  static constexpr bool push_against(int32_t moment, int32_t rate) {
    return magnitude(moment) >= kMinMoment && ((moment < 0) != (rate < 0)) && rate != 0;
  }
  static constexpr bool grew(int32_t from, int32_t to) {
    return magnitude(to) >= kMinRateMrad && ((from < 0) == (to < 0)) && magnitude(to) - magnitude(from) >= kGrowthMrad;
  }

  bool watching_ = false;
  uint32_t airborne_ticks_ = 0;
  uint32_t block_tick_ = 0;
  int32_t start_[3] = {0, 0, 0};
  uint32_t against_[3] = {0, 0, 0};
  uint8_t strikes_[3] = {0, 0, 0};
};

// The lift-off kick: the monitor above needs a wrong answer grown past the noise, and a vehicle
// whose motors are on each other's outputs, or whose IMU is turned, grows one slowly (the loops
// chase a mode that mixes the axes: 0.02 rad/s 0.2 s after the lift-off, under the rate noise).
// So in the first flight after a calibration, from the tick the vehicle is seen lifting off, the
// flight gives it a small known push on roll, then on pitch, and reads the estimate's answer.
// Each push is a doublet, 40 ms one way then 40 ms the other, which leaves no rate behind;
// pitch's begins 60 ms after roll's. A vehicle answers a push 20 to 40 ms after it (the motors'
// lag and the filters'), about the pushed axis, the way it was pushed. The verdict names the
// pushed axis:
// - at once, when the estimate turns a pushed axis 6 mrad the other way while its answer lasts
//   (a sensor axis read backwards, an IMU turned half round, a pair of motors crossed over an
//   axis);
// - 90 ms in, before pitch's push shows on pitch, when pitch turned by more than half of roll
//   (a motor on a neighbour's output turns roll's push about a diagonal; an IMU turned a quarter
//   reads it as pitch).
// An answer too small to judge is no verdict: the monitor still watches. The sticks moving, the
// engines stopping or a mode without the angle loops stops the kick without one.
class LiftOffKick {
 public:
  static constexpr uint32_t kHalfTicks = kControlHz / 25;       // 40 ms each way
  static constexpr uint32_t kPitchFrom = kControlHz * 6 / 100;  // pitch's push, 60 ms in
  static constexpr uint32_t kAcrossAt = kControlHz * 9 / 100;   // roll's answer read across
  // A push's own axis is judged from when its answer can show (30 ms in) for 70 ms; after that
  // the loops bring the vehicle back, past where it began.
  static constexpr uint32_t kLagTicks = kControlHz * 3 / 100;
  static constexpr uint32_t kAnswerTicks = kControlHz / 10;
  static constexpr uint32_t kTicks = kPitchFrom + kAnswerTicks;
  // The least turn the other way that is a verdict (mrad): a push turns the simulator's vehicle
  // 11 to 18 mrad its own way by 90 ms in, and the estimate's noise reaches 5 at vibration x8
  // (docs/safety.md rule 21 has the figures).
  static constexpr int32_t kMinTurnMrad = 6;
  // Across: pitch turned at least this far, and by more than half of roll's turn. Roll's push
  // turns a vehicle with a motor on its neighbour's output about half as far (one engine of the
  // two answers on roll), 5 to 8 mrad, and pitch as far.
  static constexpr int32_t kMinAcrossMrad = 4;

  void arm() {
    *this = LiftOffKick{};
    armed_ = true;
  }
  bool kicking() const { return push(0) != 0 || push(1) != 0; }
  // The axes that answer the kick, not only their loops (bit 0 roll, bit 1 pitch): each from its
  // push's start until the kick is over.
  uint8_t pushed_axes() const {
    if (!armed_ || tick_ == 0) return 0;
    return tick_ > kPitchFrom ? uint8_t{3} : uint8_t{1};
  }
  // The push for the next mix on `axis` (0 roll, 1 pitch): +1, -1 or 0.
  int8_t push(int axis) const {
    if (!armed_ || tick_ == 0) return 0;
    const uint32_t start = axis == 0 ? 0 : kPitchFrom;
    const uint32_t t = tick_ - 1;  // the tick update() last judged
    if (t < start || t >= start + 2 * kHalfTicks) return 0;
    return t < start + kHalfTicks ? int8_t{1} : int8_t{-1};
  }

  // One tick, beside the monitor's: `quiet` the tilt loops fly with the engines turning and the
  // sticks asking for no motion (else a kick begun stops without a verdict), `lifting` the
  // vehicle is seen leaving the ground (or off it), `angle` the estimate's roll and pitch (mrad).
  // The axis of a verdict, once; else none.
  SignAxis update(bool quiet, bool lifting, const int32_t (&angle)[2]) {
    // Only at the lift-off: sticks that move then (or while it runs) leave this flight unkicked;
    // later in the air the vehicle would still be answering them.
    if (!quiet && (tick_ > 0 || lifting)) armed_ = false;
    if (!armed_ || !quiet || (tick_ == 0 && !lifting)) return SignAxis::none;
    if (tick_ == 0) {
      from_[0] = angle[0];
      from_[1] = angle[1];
    }
    const uint32_t t = tick_++;
    // Pitch's own turn counts from its push's start: a vehicle may lift off turning slowly on
    // pitch (seen: 6 mrad in 90 ms at vibration x8.6), which is no answer to the push.
    if (t == kPitchFrom) pitch_from_ = angle[1];
    const int32_t roll = angle[0] - from_[0], pitch = angle[1] - from_[1];
    const bool across = t == kAcrossAt && magnitude(pitch) >= kMinAcrossMrad && 2 * magnitude(pitch) > roll;
    SignAxis verdict = SignAxis::none;
    if ((t >= kLagTicks && t < kAnswerTicks && roll <= -kMinTurnMrad) || across) {
      verdict = SignAxis::roll;
    } else if (t >= kPitchFrom + kLagTicks && angle[1] - pitch_from_ <= -kMinTurnMrad) {
      verdict = SignAxis::pitch;
    }
    if (verdict != SignAxis::none || t + 1 >= kTicks) armed_ = false;
    return verdict;
  }

 private:
  static constexpr int32_t magnitude(int32_t v) { return v < 0 ? -v : v; }

  bool armed_ = false;
  uint32_t tick_ = 0;
  int32_t from_[2] = {0, 0};
  int32_t pitch_from_ = 0;
};

}  // namespace qr::chain
