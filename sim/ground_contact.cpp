#include <sim/ground_contact.hpp>

#include <algorithm>
#include <cmath>

namespace sim {
namespace {

// Below this sliding speed friction turns viscous: a regularised Coulomb law, so a vehicle at
// rest does not chatter between sticking and slipping from one step to the next.
constexpr double kStickSpeed = 0.02;  // m/s

std::array<Vec3, kContactPoints> contact_points(const VehicleParams& v) {
  const double r = v.foot_radius_m, d = v.foot_depth_m, l = v.arm_m, h = -v.hub_height_m;
  return {{
      {r, 0, d},
      {0, r, d},
      {-r, 0, d},
      {0, -r, d},  // feet
      {l, 0, h},
      {0, l, h},
      {-l, 0, h},
      {0, -l, h},               // motor hubs
      {0, 0, -v.top_height_m},  // battery on top
  }};
}

}  // namespace

GroundContact::GroundContact(const VehicleParams& v)
    : stiffness_(v.contact_stiffness), damping_(v.contact_damping), friction_(v.ground_friction),
      points_(contact_points(v)) {
  for (const Vec3& point : points_) reach_ = std::max(reach_, norm(point));
}

ContactResult GroundContact::near(const Vec3& position, const Vec3& velocity, const Quat& attitude,
                                  const Vec3& body_rate) const {
  ContactResult result;
  result.deepest_m = -1e9;
  for (const Vec3& point : points_) {
    const Vec3 world_point = position + rotate(attitude, point);
    result.deepest_m = std::max(result.deepest_m, world_point.z);
    if (world_point.z <= 0) continue;
    const Vec3 point_velocity = velocity + rotate(attitude, cross(body_rate, point));
    const double normal = std::max(0.0, stiffness_ * world_point.z + damping_ * point_velocity.z);
    if (normal == 0) continue;
    result.touching = true;
    const double slide = std::hypot(point_velocity.x, point_velocity.y);
    const double friction = friction_ * normal / std::max(slide, kStickSpeed);
    const Vec3 world_force{-friction * point_velocity.x, -friction * point_velocity.y, -normal};
    result.wrench += at_point(point, rotate_inverse(attitude, world_force));
  }
  return result;
}

}  // namespace sim
