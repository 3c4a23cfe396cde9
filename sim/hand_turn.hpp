// A hand turning the vehicle: it takes the vehicle where it is, turns it about one of its body
// axes through whole turns and sets it down again exactly as it was. This is what a person does
// for a gyro scale calibration (docs/parameters.md, gyro_turns): the integrated rate of a known
// angle gives each axis' sensitivity. While held, the body follows the kinematics exactly and
// nothing else acts on it (the hand turns it about its centre of mass, clear of the ground).
#pragma once

#include <stdint.h>

#include <string>

#include <sim/quaternion.hpp>

namespace sim {

enum class BodyAxis : uint8_t { x, y, z };

struct HandTurnSpec {
  BodyAxis axis = BodyAxis::z;
  int turns = 1;  // whole turns, negative the other way
  double seconds = 2;
};

// The limits a turn must keep, so the gyro (±500 °/s, sim/imu.hpp) can read it.
inline constexpr int kMaxHandTurns = 10;
inline constexpr double kMinHandTurnSeconds = 0.5;
inline constexpr double kMaxHandTurnSeconds = 60;
inline constexpr double kMaxHandTurnRate = 8;  // rad/s, below 500 °/s = 8.73 rad/s with a 3 % scale error
// The profile's peak rate, 4 pi |N| / S.
double hand_turn_peak_rate(const HandTurnSpec& spec);
// Empty when the turn keeps the limits, otherwise what is wrong ("turns must be ...").
std::string hand_turn_problem(const HandTurnSpec& spec);
// A number read as turns: itself when whole and within the limit, else 0 (which
// hand_turn_problem refuses with the rule).
int whole_turns(double turns);
// "x", "y" or "z" to an axis; false for anything else.
bool body_axis_from_text(const std::string& text, BodyAxis& axis);
// The axis as a unit vector in body axes.
Vec3 unit_of(BodyAxis axis);
// `start` turned by `angle` rad about the body's unit vector `axis`: start (x) rotation(axis, angle).
Quat turned_about(const Quat& start, const Vec3& axis, double angle);

// What a hand holding the vehicle shares, whatever it does with it (a turn here, a tilt in
// hand_tilt.hpp): where it took the vehicle, the body axis it moves it about, and when it lets go.
class HandHold {
 public:
  bool done(uint64_t now_us) const { return now_us >= end_us_; }
  uint64_t end_us() const { return end_us_; }

 protected:
  // The hold's `seconds` on the clock's whole microseconds, so a profile ends exactly at end_us().
  HandHold(const Quat& start, BodyAxis axis, double seconds, uint64_t start_us);
  double seconds() const { return static_cast<double>(end_us_ - start_us_) * 1e-6; }
  double elapsed_s(uint64_t now_us) const;
  // start (x) rotation(axis, angle) while held; at the end exactly `start` again.
  Quat attitude_at(uint64_t now_us, double angle) const {
    return done(now_us) ? start_ : turned_about(start_, axis_, angle);
  }

  Quat start_;
  Vec3 axis_;
  uint64_t start_us_;
  uint64_t end_us_;
};

class HandTurn : public HandHold {
 public:
  // From the vehicle's attitude `start` at `start_us`, the turn `spec` (which keeps the limits).
  HandTurn(const Quat& start, const HandTurnSpec& spec, uint64_t start_us)
      : HandHold(start, spec.axis, spec.seconds, start_us), turns_(spec.turns) {}

  // The angle turned, rad, and the body rate, rad/s, at `now_us`: a raised-cosine rate, zero at
  // both ends, theta(t) = 2 pi N (t/S - sin(2 pi t/S) / (2 pi)).
  double angle(uint64_t now_us) const;
  Vec3 rate(uint64_t now_us) const;
  // start (x) rotation(axis, angle); at the end exactly `start` again.
  Quat attitude(uint64_t now_us) const { return attitude_at(now_us, angle(now_us)); }

 private:
  double turns_;
};

// What an accelerometer at the centre of mass of a body held still against gravity reads: the
// hand's push, (0, 0, -g) in world axes, in body axes.
Vec3 held_specific_force(const Quat& attitude, double gravity);

}  // namespace sim
