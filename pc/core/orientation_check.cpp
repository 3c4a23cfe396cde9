#include <pc/core/orientation_check.hpp>

#include <algorithm>
#include <cmath>

namespace qrterm {
namespace {

constexpr double kDegPerRad = 57.29577951308232;
constexpr const char* kAxisNames[] = {"roll", "pitch", "yaw"};

// The axis that moved furthest, and the one after it.
std::array<size_t, 2> furthest(const std::array<double, 3>& most_deg) {
  std::array<size_t, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return std::fabs(most_deg[a]) > std::fabs(most_deg[b]); });
  return {order[0], order[1]};
}

}  // namespace

void OrientationCheck::start() {
  in_force_ = hooks_.in_force();
  phase_ = Phase::ready;
  step_ = 0;
  results_ = {};
  turned_deg_ = {};
  rest_.clear();  // a rest from before a new orientation or calibration is no zero for this check
}

void OrientationCheck::enter() {
  if (phase_ == Phase::result || phase_ == Phase::set) {
    if (phase_ == Phase::result && offered()) {
      const int orientation = *offered();
      const std::string failed = hooks_.set(orientation);
      if (!failed.empty()) return hooks_.note(Severity::error, failed);
      phase_ = Phase::set;
      return hooks_.note(Severity::info, "imu_orientation = " + std::to_string(orientation) +
                                             " sent to the QR and kept in the parameter file: calibrate again (3), "
                                             "level and still, then check again (Enter)");
    }
    return start();
  }
  if (!safe_) return hooks_.note(Severity::warning, "the orientation check runs in safe only: 0 first");
  begin_step();
}

void OrientationCheck::begin_step() {
  // The rest's mean is each axis' zero: a QR not calibrated yet reads its gyro's bias.
  zero_deg_s_ = {};
  for (const std::array<double, 3>& r : rest_) {
    for (size_t a = 0; a < 3; ++a) zero_deg_s_[a] += r[a] / static_cast<double>(rest_.size());
  }
  turned_deg_ = {};
  most_deg_ = {};
  still_s_ = 0;
  phase_ = Phase::moving;
  const CheckStep& s = kCheckSteps[step_];
  if (!hooks_.hand(step_)) {
    hooks_.note(Severity::info, std::string("step ") + std::to_string(step_ + 1) + ", " + s.ask + ": " + s.how +
                                    ", hold it a moment and set it down as it was");
  }
}

void OrientationCheck::rest(const std::array<double, 3>& rates_deg_s, size_t keep) {
  rest_.push_back(rates_deg_s);
  while (rest_.size() > keep) rest_.pop_front();
}

void OrientationCheck::on_rates(const wire::TelemetryRates& rates, uint32_t telemetry_hz) {
  if (telemetry_hz == 0) return;
  const double period_s = 1.0 / telemetry_hz;
  const std::array<double, 3> raw{rates.p * 1e-3 * kDegPerRad, rates.q * 1e-3 * kDegPerRad,
                                  rates.r * 1e-3 * kDegPerRad};
  if (phase_ != Phase::moving) {
    rest(raw, static_cast<size_t>(std::ceil(kRestS * telemetry_hz)));
    rates_deg_s_ = raw;
    return;
  }
  bool still = true;
  for (size_t a = 0; a < 3; ++a) {
    rates_deg_s_[a] = raw[a] - zero_deg_s_[a];
    turned_deg_[a] += rates_deg_s_[a] * period_s;
    if (std::fabs(turned_deg_[a]) > std::fabs(most_deg_[a])) most_deg_[a] = turned_deg_[a];
    still = still && std::fabs(rates_deg_s_[a]) < kStillDegS;
  }
  const size_t moved = furthest(most_deg_)[0];
  const bool clear = std::fabs(most_deg_[moved]) >= kClearMotionDeg;
  const bool back = std::fabs(turned_deg_[moved]) < std::fabs(most_deg_[moved]) / 3;
  still_s_ = clear && back && still ? still_s_ + period_s : 0;
  if (still_s_ >= kStillS - 1e-9) finish_step();
}

void OrientationCheck::finish_step() {
  const std::array<size_t, 2> order = furthest(most_deg_);
  const size_t moved = order[0], next = order[1];
  phase_ = Phase::ready;
  rest_.clear();  // the next step's zero comes from the rest after this one
  if (std::fabs(most_deg_[next]) > kOtherAxisShare * std::fabs(most_deg_[moved])) {
    hooks_.note(Severity::warning, std::string("step ") + std::to_string(step_ + 1) + ": " + kAxisNames[moved] +
                                       " and " + kAxisNames[next] + " both moved: do it again, about one axis (Enter)");
    return;
  }
  const AxisAnswer answer{static_cast<int>(moved), most_deg_[moved] > 0 ? 1 : -1};
  results_[step_] = StepResult{most_deg_, answer};
  hooks_.note(answer.axis == static_cast<int>(step_) && answer.sign > 0 ? Severity::info : Severity::warning,
              std::string("step ") + std::to_string(step_ + 1) + ", " + kCheckSteps[step_].ask + ": the QR read " +
                  kAxisNames[moved] + (answer.sign > 0 ? " +" : " -"));
  if (++step_ < kCheckStepCount) return;
  std::array<AxisAnswer, 3> answers;
  for (size_t i = 0; i < kCheckStepCount; ++i) answers[i] = results_[i]->answer;
  verdict_ = infer_mounting(answers, in_force_);
  phase_ = Phase::result;
  const bool explained = verdict_.kind == MountingVerdict::Kind::mounting;
  hooks_.note(explained ? Severity::info : Severity::warning,
              "orientation check: " + verdict_text(verdict_, in_force_));
}

void OrientationCheck::on_mode(wire::Mode mode) {
  safe_ = mode == wire::Mode::safe;
  if (safe_ || phase_ != Phase::moving) return;
  phase_ = Phase::ready;
  hooks_.note(Severity::warning, "orientation check: the QR left safe, the step stopped (0, then Enter)");
}

std::optional<int> OrientationCheck::offered() const {
  if (phase_ != Phase::result || verdict_.kind != MountingVerdict::Kind::mounting) return std::nullopt;
  if (verdict_.orientation == in_force_) return std::nullopt;
  return verdict_.orientation;
}

}  // namespace qrterm
