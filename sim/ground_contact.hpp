// The ground: a flat plane at world z = 0 (NED, so anything with z > 0 is below it), met by
// a handful of points on the airframe, each a stiff spring-damper that can push but never pull,
// with Coulomb friction. Penalty contact rather than a constraint solver: a point sinks a fraction
// of a millimetre at rest, and the same few lines handle resting, landing, tipping over and a
// crash on the arms, with nothing to converge. The points are the four feet, the four motor
// hubs and the top of the battery, so in any orientation something lies between the centre of
// mass and the ground.
#pragma once

#include <array>

#include <sim/quaternion.hpp>
#include <sim/vehicle.hpp>
#include <sim/wrench.hpp>

namespace sim {

inline constexpr int kContactPoints = 9;

struct ContactResult {
  Wrench wrench;         // on the airframe, body axes
  double deepest_m = 0;  // how far the lowest point is below the ground (<= 0: above; when
                         // far above, a bound: the centre's height less the farthest point)
  bool touching = false;
};

class GroundContact {
 public:
  explicit GroundContact(const VehicleParams& vehicle);

  ContactResult at(const Vec3& position, const Vec3& velocity, const Quat& attitude, const Vec3& body_rate) const {
    // Above this height nothing can touch, and the nine rotations are skipped (most of a flight).
    if (position.z + reach_ < 0) {
      ContactResult far;
      far.deepest_m = position.z + reach_;
      return far;
    }
    return near(position, velocity, attitude, body_rate);
  }

  const std::array<Vec3, kContactPoints>& points() const { return points_; }
  // The farthest contact point from the centre of mass: below this height nothing can touch.
  double reach() const { return reach_; }

 private:
  ContactResult near(const Vec3& position, const Vec3& velocity, const Quat& attitude, const Vec3& body_rate) const;

  double stiffness_, damping_, friction_;
  std::array<Vec3, kContactPoints> points_;  // body frame, from the centre of mass
  double reach_ = 0;                         // farthest point from the centre of mass
};

}  // namespace sim
