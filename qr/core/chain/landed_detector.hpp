// Flying or landed, believed from more than one sense, for the controllers' integrals (on the
// ground a held stick or a tilted floor is an angle error the vehicle cannot correct, and an
// integral that sees it winds up and rolls the vehicle over at take-off), for height hold (a
// height to hold needs a vehicle in the air) and for a landing's touchdown.
//
// No single sense tells. On the ground the accelerometer reads 1 g whatever the engines do (the
// ground takes what the thrust does not carry), and so does a steady climb, a hover or a steady
// descent. A climb beyond 1.1 g shows a firm take-off, but a gentle one (a lift stick a few
// units above the hover, 0.3 m/s) never reads it, and heavy vibration that the sensor clips
// reads it in flight and on the ground alike. The height estimate sees every climb, but drifts
// over minutes. The thrust says what the engines can carry, once the vehicle's hover thrust is
// known; that is learnt in flight, from the thrust that was flying while the accelerometer read
// near 1 g and the vehicle moved slowly up or down (then thrust / |f| = weight), and kept for the
// session (a battery that sags raises the true hover above the learnt one, which only makes the
// gates below more permissive).
//
// Landed -> flying: some thrust (and, with the hover known, at least 90 % of it: less cannot lift
// the vehicle) and one of
//   - the accelerometer beyond takeoff_mg for 50 ms (a firm take-off), or
//   - the height estimate climbing faster than 0.1 m/s and 0.1 m above where it last stood
//     still, both for 50 ms (a gentle one; on the ground, vibration x10 moves the estimate by
//     less than 0.05 m and 0.07 m/s).
// Flying -> landed:
//   - no thrust (the lift stick down, the engines stopped), at once;
//   - the ground carries it: the hover known, the thrust below 90 % of it, yet the accelerometer's
//     mean within 0.1 g of 1 g and the climb slower than 0.25 m/s, all for 0.5 s (in the air that
//     thrust reads at most 0.9 g and accelerates the vehicle down past 0.25 m/s within 0.3 s: a
//     lift stick held a little below the hover on the ground is not a flight). Between 90 and
//     100 % of the hover the ground and a hover read alike: such a vehicle stays "flying", and
//     its thrust is learnt as the hover (at most 10 % low, which only widens the take-off gate);
//   - a landing's touchdown (vertical_controller.hpp), accepted only within 1 m of the ground the
//     vehicle took off from (touch_down): a clipped, vibrating accelerometer can read an impact
//     at any height.
#pragma once

#include <stdint.h>

#include <qr/core/chain/numeric.hpp>

namespace qr::chain {

template <class N, uint32_t SampleHz>
class LandedDetector {
 public:
  using Accel = typename N::Accel;
  using Thrust = typename N::Thrust;
  using Height = typename N::Height;
  using Climb = typename N::Climb;

  static constexpr uint32_t kClimbSamples = SampleHz / 20;  // 50 ms
  static constexpr uint32_t kGroundSamples = SampleHz / 2;  // 0.5 s

  // What the detector looks at, every tick.
  struct Senses {
    Thrust thrust;  // the per-engine thrust the mixer is asked for (0: engines stopped)
    Accel f_z;      // calibrated, filtered specific force along body z, g (-1 at rest)
    Height height;  // the height estimate, m
    Climb climb;    // its vertical speed, m/s, up
  };

  // takeoff_mg: the parameter, 1000..4000 mg. Accel holds +-16 g: the conversion is exact.
  void set_takeoff(int32_t takeoff_mg) { takeoff_ = N::template ratio<Accel>(-takeoff_mg, 1000); }

  bool update(const Senses& s) {
    f_mean_ = f_mean_ + product<Accel>(s.f_z - f_mean_, kMeanGain);
    const bool one_g = magnitude(f_mean_ - kOneG) < kOneGBand;
    if (s.thrust <= Thrust{}) {
      set_landed(true);
    } else if (landed_) {
      // The ground it rests on: the height estimate whenever it is not climbing (so the estimate's
      // drift over minutes on the ground is followed; a copy, the same in every number format).
      const bool climbs = s.climb > kRising;
      if (!climbs) ground_ = s.height;
      const bool pushed = s.f_z < takeoff_, rose = climbs && s.height - ground_ > kRisen;
      // The thrust's gate, a product, only when a sense says take-off (most ticks on the ground
      // it does not).
      const bool can_lift = (pushed || rose) && (!hover_known() || s.thrust >= product<Thrust>(hover_, kBelowHover));
      climbing_ = can_lift && pushed ? climbing_ + 1 : 0;
      rising_ = can_lift && rose ? rising_ + 1 : 0;
      if (climbing_ >= kClimbSamples || rising_ >= kClimbSamples) set_landed(false);
    } else {
      // The same: the thrust's product last, after the readings that a hover fails.
      const bool carried = one_g && magnitude(s.climb) < kStill && hover_known() &&
                           s.thrust < product<Thrust>(hover_, kBelowHover);
      carried_ = carried ? carried_ + 1 : 0;
      if (carried_ >= kGroundSamples) {
        set_landed(true);
      } else if (airborne_ < kSettleSamples) {
        ++airborne_;
      } else if (one_g && !carried && magnitude(s.climb) < kSlow) {
        // Not while the ground may carry part of the weight (that thrust is no hover). In the
        // air the accelerometer reads thrust over weight (f = -T/W g): the weight's thrust
        // is T / |f|, here T (2 - |f|), within 1 % for |f| within 0.1 g of 1 (a division per tick
        // saved). Slower than 1 m/s only: at a descent of some m/s the airframe's drag carries
        // part of the weight and the accelerometer reads 1 g with less thrust (by hand at 6 m/s
        // down, a lift of 510 was learnt for a hover of 535: 4.7 %; as the square of the speed,
        // 0.13 % at 1 m/s). A gentle take-off a lift step above the hover climbs past 0.5 m/s
        // within the half second the learning waits, and must still teach it.
        const Thrust weight = product<Thrust>(s.thrust, kTwoG + f_mean_);
        hover_ = hover_known() ? hover_ + product<Thrust>(weight - hover_, kHoverGain) : weight;
      }
    }
    return landed_;
  }
  bool landed() const { return landed_; }
  // Off the ground, or leaving it: the accelerometer has read a firm take-off (beyond takeoff_mg,
  // with the thrust to lift) for half of the 50 ms that make it a take-off.
  bool lifting() const { return !landed_ || climbing_ >= kClimbSamples / 2; }
  // A landing (panic): flying until its touchdown says otherwise, and then on the ground; a
  // touchdown counts only near the ground (near_ground below), at the height estimate `height`.
  void take_off() { set_landed(false); }
  void touch_down(Height height) {
    if (near_ground(height)) set_landed(true);
  }

  // The learnt per-engine hover thrust (0: no flight has taught it yet).
  Thrust hover() const { return hover_; }
  bool hover_known() const { return hover_ > Thrust{}; }
  // Within 1 m of the ground the vehicle last rested on, by the height estimate.
  bool near_ground(Height height) const { return height - ground_ < kNearGround; }

 private:
  void set_landed(bool landed) {
    landed_ = landed;
    climbing_ = rising_ = carried_ = airborne_ = 0;
  }

  static constexpr Accel kDefaultTakeoff = Accel(-1.1);
  static constexpr Accel kOneG = Accel(-1.0);
  static constexpr Accel kOneGBand = Accel(0.1);
  static constexpr Height kRisen = Height(0.1);
  static constexpr Height kNearGround = Height(1.0);
  static constexpr Climb kRising = Climb(0.1);
  static constexpr Climb kStill = Climb(0.25);
  static constexpr Climb kSlow = Climb(1.0);
  static constexpr Accel kTwoG = Accel(2.0);
  using Scale = typename N::Scale;
  // Below 90 % of the hover thrust the engines cannot lift the vehicle, and on the ground
  // with the accelerometer at 1 g the ground carries the rest: one share for both rules.
  static constexpr Scale kBelowHover = Scale(0.9);
  // Time constants, in ticks: the accelerometer's mean 64 ms, the hover 2 s, learnt from 0.5 s
  // after the take-off (the climb away from the ground is not a hover).
  static constexpr Scale kMeanGain = Scale(1.0 / (SampleHz * 64 / 1000));
  static constexpr Scale kHoverGain = Scale(1.0 / (SampleHz * 2));
  static constexpr uint32_t kSettleSamples = SampleHz / 2;

  Accel takeoff_ = kDefaultTakeoff;
  Accel f_mean_ = kOneG;
  Thrust hover_{};
  Height ground_{};
  uint32_t climbing_ = 0, rising_ = 0, carried_ = 0, airborne_ = 0;
  bool landed_ = true;
};

}  // namespace qr::chain
