// A force and a torque about the centre of mass, both in body axes.
#pragma once

#include <sim/vec3.hpp>

namespace sim {

struct Wrench {
  Vec3 force;
  Vec3 torque;

  Wrench& operator+=(const Wrench& o) {
    force += o.force;
    torque += o.torque;
    return *this;
  }
};

// A force `force` applied at `point` (body frame, from the centre of mass).
inline Wrench at_point(const Vec3& point, const Vec3& force) { return {force, cross(point, force)}; }

}  // namespace sim
