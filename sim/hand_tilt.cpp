#include <sim/hand_tilt.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace sim {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180;

}  // namespace

double hand_tilt_peak_rate(const HandTiltSpec& spec) {
  return 3 * std::numbers::pi * std::abs(spec.degrees * kRadPerDeg) / (2 * spec.seconds);
}

std::string hand_tilt_problem(const HandTiltSpec& spec) {
  if (!(spec.degrees != 0 && std::abs(spec.degrees) <= kMaxHandTiltDegrees)) {
    return "the angle is a tilt: not 0, within +-90 degrees";
  }
  if (!(spec.seconds >= kMinHandTurnSeconds && spec.seconds <= kMaxHandTurnSeconds)) {
    return "a tilt takes 0.5 .. 60 s";
  }
  if (hand_tilt_peak_rate(spec) > kMaxHandTurnRate) {
    char text[120];
    std::snprintf(text, sizeof text,
                  "peak rate 3 pi |A| / (2 S) = %.2f rad/s is beyond the gyro's 8 rad/s: take longer",
                  hand_tilt_peak_rate(spec));
    return text;
  }
  return "";
}

HandTilt::HandTilt(const Quat& start, const HandTiltSpec& spec, uint64_t start_us)
    : HandHold(start, spec.axis, spec.seconds, start_us), radians_(spec.degrees * kRadPerDeg), third_s_(seconds() / 3) {
}

double HandTilt::angle(uint64_t now_us) const {
  if (done(now_us)) return 0;
  const double t = elapsed_s(now_us);
  if (t < third_s_) return radians_ * (1 - std::cos(std::numbers::pi * t / third_s_)) / 2;
  if (t < 2 * third_s_) return radians_;
  return radians_ * (1 + std::cos(std::numbers::pi * (t - 2 * third_s_) / third_s_)) / 2;
}

Vec3 HandTilt::rate(uint64_t now_us) const {
  if (done(now_us)) return {};
  const double t = elapsed_s(now_us);
  const double peak = radians_ * std::numbers::pi / (2 * third_s_);
  if (t < third_s_) return axis_ * (peak * std::sin(std::numbers::pi * t / third_s_));
  if (t < 2 * third_s_) return {};
  return axis_ * (-peak * std::sin(std::numbers::pi * (t - 2 * third_s_) / third_s_));
}

}  // namespace sim
