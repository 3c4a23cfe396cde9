#include <pc/core/descent_warning.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

#include <common/units.hpp>
#include <pc/core/radio_pilot.hpp>

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

namespace {

// The descent warning's log line: what, where, why, and what to do.
std::string sinking_text(const DescentVerdict& verdict, double height_m, double climb_m_s, const char* advice) {
  char why[160];
  if (verdict.danger == DescentDanger::too_fast_low) {
    std::snprintf(why, sizeof why, "within %.0f m of the ground, faster than a safe touchdown (%.1f m/s)", kNearGroundM,
                  kSafeTouchdownMS);
  } else if (std::isinf(verdict.needed_m)) {
    std::snprintf(why, sizeof why, "the engines have no lift to spare above the hover: it cannot stop");
  } else {
    std::snprintf(why, sizeof why, "it needs %.1f m to stop (%.0f s to act, braking at %.1f m/s^2, %.0f m to spare)",
                  verdict.needed_m, kReactionS, verdict.spare_m_s2, kMarginM);
  }
  char line[240];
  std::snprintf(line, sizeof line, "SINKING %.1f m/s at %.1f m: %s; %s", -climb_m_s, height_m, why, advice);
  return line;
}

// What the pilot can do: the console's lift keys, unless the QR ignores them (panic) or flies a
// real radio's sticks (the simulator's radio takes the console's).
const char* sinking_advice(const TelemetryModel& telemetry, bool simulator) {
  if (sinking_in_panic(telemetry)) return "the QR is in panic: the sticks do nothing, it comes down by itself";
  if (radio_flies(telemetry) && !simulator) return "lift now, on the radio's throttle";
  return "lift now (PgUp)";
}

}  // namespace

std::string DescentWatch::on_height(const wire::TelemetryHeight& height, const TelemetryModel& telemetry,
                                    bool simulator, uint32_t now_ms) {
  const bool valid = (height.flags & wire::kHeightValid) != 0;
  const bool flying = telemetry.flag(wire::kFlagFlying);
  const double h = height.height_mm / 1000.0, v = height.climb_mm_s / 1000.0;
  const DescentVerdict verdict = valid ? judge_descent(h, v, height.hover_lift, flying) : DescentVerdict{};
  if (verdict.warn) {
    const bool rises = !sinking_;
    sinking_ = Sinking{-v, now_ms};
    return rises ? sinking_text(verdict, h, v, sinking_advice(telemetry, simulator)) : std::string();
  }
  if (!sinking_) return {};
  // Landed ends it at once (the ground has stopped the descent); else it holds a moment.
  if (!flying || !valid || now_ms - sinking_->last_warn_ms >= kSinkingHoldMs) {
    sinking_.reset();
  } else {
    sinking_->speed_m_s = -v;
  }
  return {};
}

std::optional<double> DescentWatch::speed_m_s() const {
  if (!sinking_) return std::nullopt;
  return sinking_->speed_m_s;
}

bool sinking_in_panic(const TelemetryModel& telemetry) {
  return telemetry.attitude && telemetry.attitude->mode == wire::Mode::panic;
}

}  // namespace qrterm
