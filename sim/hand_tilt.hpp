// A hand tilting the vehicle: it takes the vehicle where it is, tilts it about one of its body axes
// to an angle, holds it there and sets it down again exactly as it was. This is what a person does
// for the console's orientation check (docs/console.md, "The orientation check"): right side
// down, nose up, nose right, each read back from the QR to find an IMU mounted turned or upside
// down. Held as a turn is held (hand_turn.hpp): the body follows the kinematics exactly and
// nothing else acts on it.
#pragma once

#include <stdint.h>

#include <string>

#include <sim/hand_turn.hpp>
#include <sim/quaternion.hpp>

namespace sim {

struct HandTiltSpec {
  BodyAxis axis = BodyAxis::x;
  double degrees = 45;   // to this angle, negative the other way
  double seconds = 1.5;  // out, hold and back, a third each
};

// A tilt, not a turn over: at most a right angle either way.
inline constexpr double kMaxHandTiltDegrees = 90;
// The profile's peak rate, 3 pi |A| / (2 S) with A in rad.
double hand_tilt_peak_rate(const HandTiltSpec& spec);
// Empty when the tilt keeps the limits (0 < |degrees| <= 90, the seconds and the peak rate of a
// turn: kMinHandTurnSeconds .. kMaxHandTurnSeconds, kMaxHandTurnRate), otherwise what is wrong.
std::string hand_tilt_problem(const HandTiltSpec& spec);

class HandTilt : public HandHold {
 public:
  // From the vehicle's attitude `start` at `start_us`, the tilt `spec` (which keeps the limits).
  HandTilt(const Quat& start, const HandTiltSpec& spec, uint64_t start_us);

  // The angle tilted, rad, and the body rate, rad/s, at `now_us`. Out and back are half a cosine
  // each, so the rate is zero where the hand starts, holds and lets go:
  // out theta = A (1 - cos(pi t/T)) / 2, hold A, back A (1 + cos(pi (t - 2T)/T)) / 2, T = S/3.
  double angle(uint64_t now_us) const;
  Vec3 rate(uint64_t now_us) const;
  // start (x) rotation(axis, angle); at the end exactly `start` again.
  Quat attitude(uint64_t now_us) const { return attitude_at(now_us, angle(now_us)); }

 private:
  double radians_;
  double third_s_;
};

}  // namespace sim
