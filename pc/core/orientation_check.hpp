// The orientation check (docs/console.md, "The orientation check"): before the first flight the
// pilot tilts the QR right side down, nose up and nose right by hand, one step at a time, and the
// console reads which of the QR's axes moved and which way; from the three answers it names the
// mounting of the IMU's board that explains them (imu_mounting.hpp) and offers to set
// imu_orientation. In the simulator the simulator's hand tilts it.
//
// It reads the QR's body rates (telemetry_rates) and integrates them into the angle turned during
// the step: the rates are the gyro's own, so they need no calibration (which the QR refuses with
// its board upside down) and no accelerometer, and the integral turns a hand's brief motion into
// an angle that stays on the screen and can be held against the tilt that made it. The attitude
// estimate would need a calibration first and lags the motion by its filter.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <deque>
#include <functional>
#include <optional>
#include <string>

#include <common/mode.hpp>
#include <common/telemetry.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/imu_mounting.hpp>

namespace qrterm {

struct CheckStep {
  const char* ask;  // the step's title, with the axis and sign it expects
  const char* how;  // what the hand does
};

// Step i asks for a positive motion about body axis i.
inline constexpr CheckStep kCheckSteps[] = {
    {"tilt right (roll +)", "tilt it right side down"},
    {"nose up (pitch +)", "lift its nose"},
    {"turn right (yaw +)", "turn its nose to the right, flat"},
};
inline constexpr size_t kCheckStepCount = sizeof(kCheckSteps) / sizeof(kCheckSteps[0]);

// A step is answered by a motion of at least this much about one axis...
inline constexpr double kClearMotionDeg = 20;
// ... with every other axis under this share of it (else it says which two moved and is asked again),
inline constexpr double kOtherAxisShare = 0.5;
// ... once the QR is back (the moved axis under a third of its most) and still (every rate under
// kStillDegS, the rest's mean taken out) for kStillS.
inline constexpr double kStillDegS = 10;
inline constexpr double kStillS = 0.3;
// The rest before a step: the mean of its last kRestS of rates is each axis' zero (the gyro's
// bias, for a QR not calibrated yet).
inline constexpr double kRestS = 0.5;

struct StepResult {
  std::array<double, 3> most_deg{};  // each reported axis' furthest angle during the step, signed
  AxisAnswer answer;
};

class OrientationCheck {
 public:
  struct Hooks {
    std::function<void(Severity, const std::string&)> note;
    std::function<int()> in_force;          // imu_orientation as the QR has it now
    std::function<bool(size_t axis)> hand;  // the simulator's hand tilts the QR the step's way; false: no simulator
    // Sends imu_orientation and writes it into the parameter file: what went wrong, or empty.
    std::function<std::string(int orientation)> set;
  };
  enum class Phase : uint8_t {
    ready,   // waiting for Enter to start step()
    moving,  // step() runs: the hand moves the QR
    result,  // three answers: the verdict
    set,     // the verdict's imu_orientation sent and written
  };

  explicit OrientationCheck(Hooks hooks) : hooks_(std::move(hooks)) {}

  // From the first step, with the orientation in force now.
  void start();
  // Enter: start the step (again, while it runs); on the verdict, set the orientation it names,
  // or check again.
  void enter();
  void on_rates(const wire::TelemetryRates& rates, uint32_t telemetry_hz);
  void on_mode(wire::Mode mode);

  Phase phase() const { return phase_; }
  size_t step() const { return step_; }
  int in_force() const { return in_force_; }
  // The angle turned in this step so far, deg, per reported axis (roll, pitch, yaw).
  const std::array<double, 3>& turned_deg() const { return turned_deg_; }
  // The latest rates, deg/s, the rest's mean taken out while a step runs.
  const std::array<double, 3>& rates_deg_s() const { return rates_deg_s_; }
  const std::optional<StepResult>& result(size_t step) const { return results_[step]; }
  const MountingVerdict& verdict() const { return verdict_; }
  // On the verdict: the orientation Enter sets, when it is not the one in force.
  std::optional<int> offered() const;

 private:
  void begin_step();
  void finish_step();
  void rest(const std::array<double, 3>& rates_deg_s, size_t keep);

  Hooks hooks_;
  Phase phase_ = Phase::ready;
  size_t step_ = 0;
  int in_force_ = 0;
  bool safe_ = true;
  std::array<std::optional<StepResult>, kCheckStepCount> results_;
  MountingVerdict verdict_;
  std::deque<std::array<double, 3>> rest_;  // the rates before the step, deg/s
  std::array<double, 3> zero_deg_s_{};
  std::array<double, 3> rates_deg_s_{};
  std::array<double, 3> turned_deg_{};
  std::array<double, 3> most_deg_{};
  double still_s_ = 0;
};

}  // namespace qrterm
