#include <sim/hand_turn.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace sim {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

}  // namespace

Vec3 unit_of(BodyAxis axis) {
  static constexpr Vec3 kUnit[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  return kUnit[static_cast<int>(axis)];
}

Quat turned_about(const Quat& start, const Vec3& axis, double angle) {
  const double s = std::sin(angle / 2);
  return normalized(start * Quat{std::cos(angle / 2), axis.x * s, axis.y * s, axis.z * s});
}

double hand_turn_peak_rate(const HandTurnSpec& spec) { return 2 * kTwoPi * std::abs(spec.turns) / spec.seconds; }

std::string hand_turn_problem(const HandTurnSpec& spec) {
  if (spec.turns == 0 || std::abs(spec.turns) > kMaxHandTurns)
    return "turns must be a whole number, not 0, within +-10";
  if (!(spec.seconds >= kMinHandTurnSeconds && spec.seconds <= kMaxHandTurnSeconds)) {
    return "a turn takes 0.5 .. 60 s";
  }
  if (hand_turn_peak_rate(spec) > kMaxHandTurnRate) {
    char text[120];
    std::snprintf(text, sizeof text, "peak rate 4 pi |N| / S = %.2f rad/s is beyond the gyro's 8 rad/s: take longer",
                  hand_turn_peak_rate(spec));
    return text;
  }
  return "";
}

int whole_turns(double turns) {
  return std::abs(turns) <= kMaxHandTurns && turns == std::trunc(turns) ? static_cast<int>(turns) : 0;
}

bool body_axis_from_text(const std::string& text, BodyAxis& axis) {
  static constexpr const char* kNames[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (text == kNames[i]) {
      axis = static_cast<BodyAxis>(i);
      return true;
    }
  }
  return false;
}

HandHold::HandHold(const Quat& start, BodyAxis axis, double seconds, uint64_t start_us)
    : start_(start), axis_(unit_of(axis)), start_us_(start_us),
      end_us_(start_us + static_cast<uint64_t>(std::llround(seconds * 1e6))) {}

double HandHold::elapsed_s(uint64_t now_us) const {
  if (now_us <= start_us_) return 0;
  return static_cast<double>(std::min(now_us, end_us_) - start_us_) * 1e-6;
}

double HandTurn::angle(uint64_t now_us) const {
  if (done(now_us)) return kTwoPi * turns_;
  const double phase = kTwoPi * elapsed_s(now_us) / seconds();
  return turns_ * (phase - std::sin(phase));
}

Vec3 HandTurn::rate(uint64_t now_us) const {
  if (done(now_us)) return {};
  const double phase = kTwoPi * elapsed_s(now_us) / seconds();
  return axis_ * (kTwoPi * turns_ / seconds() * (1 - std::cos(phase)));
}

Vec3 held_specific_force(const Quat& attitude, double gravity) { return rotate_inverse(attitude, {0, 0, -gravity}); }

}  // namespace sim
