// Whether the vehicle is on the ground, for the controllers' integrals: on the ground a held stick
// (or a tilted floor) is an angle error the vehicle cannot correct, and an integral that sees it
// winds up to its clamp; at take-off that trim moment then rolls the vehicle over until it is
// unwound (a 3 degree stick for 15 s at 75 % of the hover lift rolled the simulated vehicle to
// 11 degrees after take-off, docs/signal-chain.md).
//
// On the ground the accelerometer reads 1 g whatever the engines do: the ground takes what the
// thrust does not carry. Only once the thrust exceeds the weight does the vehicle climb, and then
// the specific force along the thrust exceeds 1 g. So: landed from lift 0 (engines stopped: on
// the ground, or cut) until the specific force along body z has stayed beyond takeoff_mg for
// 50 ms (vibration that the 20 Hz low-pass leaves cannot hold it there that long). A hover does
// not look different from the ground to this sensor, so flying stays flying until the lift is 0.
//
// The lift is the stick, not a threshold on it: the hover lift depends on the vehicle and its
// battery, and the take-off accelerometer reading does not.
#pragma once

#include <stdint.h>

#include <qr/core/chain/numeric.hpp>

namespace qr::chain {

template <class N, uint32_t SampleHz>
class LandedDetector {
 public:
  using Accel = typename N::Accel;

  static constexpr uint32_t kClimbSamples = SampleHz / 20;  // 50 ms

  // takeoff_mg: the parameter, 1000..4000 mg. Accel holds +-16 g: the conversion is exact.
  void set_takeoff(int32_t takeoff_mg) { takeoff_ = N::template ratio<Accel>(-takeoff_mg, 1000); }

  // lift: the lift stick; f_z: calibrated, filtered specific force along body z (g, -1 at rest).
  bool update(uint16_t lift, Accel f_z) {
    if (lift == 0) {
      landed_ = true;
      climbing_ = 0;
    } else if (landed_) {
      climbing_ = f_z < takeoff_ ? climbing_ + 1 : 0;
      if (climbing_ >= kClimbSamples) landed_ = false;
    }
    return landed_;
  }
  bool landed() const { return landed_; }
  // A landing (panic): flying until its touchdown says otherwise, and then on the ground.
  void take_off() {
    landed_ = false;
    climbing_ = 0;
  }
  void touch_down() { landed_ = true; }

 private:
  static constexpr Accel kDefaultTakeoff = Accel(-1.1);
  Accel takeoff_ = kDefaultTakeoff;
  uint32_t climbing_ = 0;
  bool landed_ = true;
};

}  // namespace qr::chain
