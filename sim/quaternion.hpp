// Attitude as a unit quaternion rotating body-frame vectors into the world frame. Kept as a
// quaternion (not Euler angles) so the plant has no singularity at ±90° pitch; Euler angles in
// the Z-Y-X order of docs/conventions.md are only read out for scoring and display.
#pragma once

#include <cmath>

#include <sim/vec3.hpp>

namespace sim {

struct Quat {
  double w = 1;
  double x = 0;
  double y = 0;
  double z = 0;
};

constexpr Quat operator*(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

inline Quat normalized(const Quat& q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// Body -> world.
constexpr Vec3 rotate(const Quat& q, const Vec3& v) {
  // v + 2 u x (u x v + w v), u the vector part: two cross products instead of a matrix.
  const Vec3 u{q.x, q.y, q.z};
  const Vec3 t = cross(u, v) + q.w * v;
  return v + 2.0 * cross(u, t);
}

// World -> body.
constexpr Vec3 rotate_inverse(const Quat& q, const Vec3& v) { return rotate(Quat{q.w, -q.x, -q.y, -q.z}, v); }

// Time derivative of the attitude for body rates w: q' = q (0, w) / 2.
constexpr Quat derivative(const Quat& q, const Vec3& w) {
  const Quat d = q * Quat{0, w.x, w.y, w.z};
  return {0.5 * d.w, 0.5 * d.x, 0.5 * d.y, 0.5 * d.z};
}

struct Euler {
  double roll = 0;   // φ, positive right side down
  double pitch = 0;  // θ, positive nose up
  double yaw = 0;    // ψ, positive nose right
};

// Z-Y-X (yaw, then pitch, then roll) as in docs/conventions.md.
inline Quat from_euler(const Euler& e) {
  const double cr = std::cos(e.roll / 2), sr = std::sin(e.roll / 2);
  const double cp = std::cos(e.pitch / 2), sp = std::sin(e.pitch / 2);
  const double cy = std::cos(e.yaw / 2), sy = std::sin(e.yaw / 2);
  return {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
          cr * cp * sy - sr * sp * cy};
}

inline Euler to_euler(const Quat& q) {
  const double sin_pitch = 2 * (q.w * q.y - q.z * q.x);
  return {std::atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y)),
          std::asin(sin_pitch > 1    ? 1
                    : sin_pitch < -1 ? -1
                                     : sin_pitch),
          std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))};
}

}  // namespace sim
