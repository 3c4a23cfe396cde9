// Angles live in [-pi, pi): after every update an angle is wrapped back into that interval, so a
// roll through 180 degrees does not leave the estimate or its error out of range.
#pragma once

#include <qr/core/chain/design_math.hpp>

namespace qr::chain {

template <class Angle>
inline constexpr Angle kPiAngle = Angle(design::kPi);
template <class Angle>
inline constexpr Angle kTwoPiAngle = Angle(2 * design::kPi);

// For x in [-3 pi, 3 pi), which holds any sum or difference of two wrapped angles and a small
// step. The Angle format must hold +-2 pi (FixedNumbers::Angle holds +-8).
template <class Angle>
constexpr Angle wrap_angle(Angle x) {
  if (!(x < kPiAngle<Angle>)) return x - kTwoPiAngle<Angle>;
  if (x < -kPiAngle<Angle>) return x + kTwoPiAngle<Angle>;
  return x;
}

}  // namespace qr::chain
