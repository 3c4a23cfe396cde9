// The orientation check's screen: the three steps, each with the angle the QR turned about its
// roll, pitch and yaw axes (live while the step runs, the furthest once it is answered), the axis
// and sign the step expects marked, what the QR read, and the verdict with what Enter does next.
#include <cmath>

#include <pc/core/mode_names.hpp>
#include <pc/core/orientation_check.hpp>
#include <pc/ui/screen_draw.hpp>
#include <pc/ui/screens.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {
namespace {

constexpr const char* kAxisNames[] = {"roll", "pitch", "yaw"};
constexpr int kValueColumn = 26;
constexpr int kValueWidth = 12;
constexpr int kAnswerColumn = kValueColumn + 3 * kValueWidth;

// `s` over as many rows as it needs from `row`, broken between words; the rows it took.
int put_wrapped(int row, int width, const std::string& s, short pair, attr_t attributes) {
  int rows = 0;
  size_t from = 0;
  while (from < s.size()) {
    size_t end = s.size();
    if (end - from > static_cast<size_t>(width)) {
      end = s.rfind(' ', from + static_cast<size_t>(width));
      if (end == std::string::npos || end <= from) end = from + static_cast<size_t>(width);
    }
    put(row + rows++, 0, s.substr(from, end - from), pair, attributes);
    from = s.find_first_not_of(' ', end);
    if (from == std::string::npos) break;
  }
  return rows;
}

// One step's row: its title, three angles with the expected one marked "(+)", and the answer.
void draw_step(const OrientationCheck& check, size_t step, int row) {
  const bool current = check.step() == step && check.phase() != OrientationCheck::Phase::result &&
                       check.phase() != OrientationCheck::Phase::set;
  put(row, 0, text("%s%zu %s", current ? ">" : " ", step + 1, kCheckSteps[step].ask), 0, current ? A_BOLD : A_NORMAL);
  const std::optional<StepResult>& result = check.result(step);
  const bool live = current && check.phase() == OrientationCheck::Phase::moving;
  if (!result && !live) return;
  const std::array<double, 3>& angles = result ? result->most_deg : check.turned_deg();
  for (size_t a = 0; a < 3; ++a) {
    const bool expected = a == step;
    put(row, kValueColumn + static_cast<int>(a) * kValueWidth, text("%+7.1f%s", angles[a], expected ? " (+)" : ""),
        expected ? kInfo : 0, expected ? A_BOLD : A_NORMAL);
  }
  if (!result) return;
  const AxisAnswer& answer = result->answer;
  const bool as_expected = answer.axis == static_cast<int>(step) && answer.sign > 0;
  put(row, kAnswerColumn,
      text("%s %c%s", kAxisNames[answer.axis], answer.sign > 0 ? '+' : '-', as_expected ? "  ok" : ""),
      as_expected ? kInfo : kWarning, A_BOLD);
}

// What the step asks of the pilot, the verdict, and what Enter does now, each wrapped to the width.
void draw_next(const Console& console, const OrientationCheck& check, int row, int width) {
  const CheckStep& step = kCheckSteps[check.step() < kCheckStepCount ? check.step() : 0];
  const std::string& file = console.params_file();
  switch (check.phase()) {
    case OrientationCheck::Phase::ready:
      row += put_wrapped(
          row, width,
          text("Enter: step %zu, %s: %s", check.step() + 1, step.ask,
               console.flying_simulator() ? "the simulator's hand moves the QR" : "then move the QR by hand"),
          kWarning, A_BOLD);
      put_wrapped(row, width, text("%s, hold it a moment and set it down as it was", step.how), kDim, A_NORMAL);
      break;
    case OrientationCheck::Phase::moving:
      row += put_wrapped(row, width,
                         text("step %zu: %s, hold it a moment and set it down as it was", check.step() + 1, step.how),
                         kWarning, A_BOLD);
      put_wrapped(row, width, "(Enter starts the step again)", kDim, A_NORMAL);
      break;
    case OrientationCheck::Phase::result: {
      const bool explained = check.verdict().kind == MountingVerdict::Kind::mounting;
      row += put_wrapped(row, width, verdict_text(check.verdict(), check.in_force()), explained ? kInfo : kError,
                         A_BOLD);
      if (const std::optional<int> offered = check.offered()) {
        put_wrapped(row, width,
                    text("Enter: set imu_orientation = %d (sent to the QR, kept in %s), then calibrate again (3)",
                         *offered, file.c_str()),
                    kWarning, A_BOLD);
      } else {
        put_wrapped(row, width, "Enter: check again", kDim, A_NORMAL);
      }
      break;
    }
    case OrientationCheck::Phase::set:
      row += put_wrapped(
          row, width,
          text("imu_orientation = %d sent to the QR and kept in %s", check.verdict().orientation, file.c_str()), kInfo,
          A_BOLD);
      put_wrapped(row, width, "calibrate again (3), level and still; then Enter checks again", kWarning, A_BOLD);
      break;
  }
}

}  // namespace

void draw_orientation_screen(const Console& console, int top, int rows, int width) {
  const OrientationCheck& check = console.orientation_check();
  put(top, 0, "ORIENTATION CHECK", 0, A_BOLD);
  put(top, 18, text("imu_orientation %d in force: %s", check.in_force(), mounting_name(check.in_force()).c_str()),
      kDim);
  put(top + 1, 0, "Is the IMU mounted as the QR takes it? Move the QR as each step says and see.", kDim);
  put(top + 3, 0,
      text("%-*s%*s%*s%*s  %s", kValueColumn, "step (deg turned, from the rates)", kValueWidth - 5, "roll", kValueWidth,
           "pitch", kValueWidth, "yaw", "the QR read"),
      0, A_UNDERLINE);
  for (size_t step = 0; step < kCheckStepCount; ++step) draw_step(check, step, top + 4 + static_cast<int>(step));
  const std::array<double, 3>& rates = check.rates_deg_s();
  const TelemetryModel& t = console.telemetry();
  put(top + 8, 0,
      text("rates now, deg/s:  p %+7.1f   q %+7.1f   r %+7.1f%s", rates[0], rates[1], rates[2],
           check.phase() == OrientationCheck::Phase::moving ? "  (less the rest's mean)"
           : t.flag(wire::kFlagCalibrated)                  ? ""
                                                            : "  (bias in: not calibrated)"),
      kDim);
  if (t.attitude && t.attitude->mode != wire::Mode::safe) {
    put(top + 9, 0, text("the QR is in %s: the check runs in safe (0)", mode_name(t.attitude->mode)), kError, A_BOLD);
  }
  draw_next(console, check, top + 10, width);
  put(top + rows - 2, 0, "Enter start the step / set it   Bksp from step 1   Tab cockpit", kDim);
  draw_prompt_or_log(console, top + rows - 1, width);
}

}  // namespace qrterm
