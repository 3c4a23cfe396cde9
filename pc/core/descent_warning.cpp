#include <pc/core/descent_warning.hpp>

#include <limits>

#include <common/units.hpp>

namespace qrterm {

double spare_acceleration_m_s2(uint16_t hover_lift) {
  if (hover_lift == 0) return kUnknownSpareMS2;
  const double full_over_hover = double{wire::kLiftMax} / hover_lift;
  const double spare = kSpareShare * kGravityMS2 * (full_over_hover * full_over_hover - 1.0);
  return spare > 0 ? spare : 0;
}

DescentVerdict judge_descent(double height_m, double climb_m_s, uint16_t hover_lift, bool flying) {
  DescentVerdict verdict;
  verdict.spare_m_s2 = spare_acceleration_m_s2(hover_lift);
  const double speed = -climb_m_s;  // down, m/s
  const double braking = verdict.spare_m_s2 > 0 ? speed * speed / (2 * verdict.spare_m_s2)
                                                : std::numeric_limits<double>::infinity();
  verdict.needed_m = speed * kReactionS + braking + kMarginM;
  const bool too_fast = speed > kSafeTouchdownMS;
  if (!flying || !too_fast) return verdict;
  if (height_m <= verdict.needed_m) {
    verdict.danger = DescentDanger::cannot_stop;
  } else if (height_m <= kNearGroundM) {
    verdict.danger = DescentDanger::too_fast_low;
  }
  verdict.warn = verdict.danger != DescentDanger::none;
  return verdict;
}

}  // namespace qrterm
