#include <pc/core/joystick_wizard.hpp>

#include <algorithm>

namespace qrterm {
namespace {

constexpr int32_t kAxisMax = 32767;  // the driver's full deflection
constexpr int32_t kPermille = 1000;
// Found: an axis that travelled half its range (-32767..32767) in the step. A stick only nudged, or
// one axis wobbling while another is moved, stays well below.
constexpr int32_t kMinTravel = kAxisMax;
// Which way round: the side of the first excursion of a quarter of the range from where the step
// began. Found axes always make one (half the range from any start reaches a quarter one way).
constexpr int32_t kExcursion = (kAxisMax + 1) / 2;
// Short of full deflection (a note, not an error): the map reads ±32767 as full, so a stick whose
// driver stops at ±20000 never gives full roll.
constexpr int32_t kFullReach = kAxisMax * 9 / 10;
// A control reading more than this at rest was not let go (or the throttle not closed).
constexpr int32_t kMaxRestPermille = 250;
// The deadband is twice the highest reading at rest, and at least this: a centring spring does not
// bring the stick back to exactly where it rested, which keeping still cannot show.
constexpr int32_t kMinDeadband = 20;
constexpr int32_t kMaxDeadband = 500;  // as the map file allows

struct StepRow {
  WizardStep step;
  const char* name;
  const char* instruction;
  const char* positive;  // the direction asked for first, which reads positive in the map
  const char* how;       // moving the control as its step asks, for a refusal
  const char* at_rest;   // what the pilot does with the control while resting
  AxisBinding JoystickMap::*binding;
  bool from_closed_end;  // the throttle: read 0..1000 from closed, not from a centre
};

constexpr StepRow kSteps[] = {
    {WizardStep::rest, "rest",
     "Let go of the stick and the twist so that they centre, and close the throttle. Then press Enter and keep "
     "still for a second.",
     nullptr, nullptr, nullptr, nullptr, false},
    {WizardStep::roll, "roll", "Move the stick fully RIGHT, then fully left, then let it centre. Enter when done.",
     "right", "move the stick fully right and left", "let go of the stick", &JoystickMap::roll, false},
    {WizardStep::pitch, "pitch",
     "Pull the stick fully BACK (towards you), then push it fully forward, then let it centre. Enter when done.",
     "back", "pull the stick fully back and push it forward", "let go of the stick", &JoystickMap::pitch, false},
    {WizardStep::yaw, "yaw", "Twist the stick fully RIGHT, then fully left, then let it centre. Enter when done.",
     "right", "twist the stick fully right and left", "let go of the twist", &JoystickMap::yaw, false},
    {WizardStep::lift, "lift", "Push the throttle fully OPEN, then close it fully. Enter when done.", "open",
     "push the throttle fully open and close it", "close the throttle", &JoystickMap::lift, true},
    {WizardStep::fire, "fire",
     "Press the fire button (the trigger): in flight it aborts, as ESC does. (Enter if the stick has none.)", nullptr,
     nullptr, nullptr, nullptr, false},
    {WizardStep::review, "review", "Check what was found.", nullptr, nullptr, nullptr, nullptr, false},
};
static_assert(sizeof kSteps / sizeof kSteps[0] == kWizardSteps);
constexpr bool rows_in_step_order() {
  for (size_t i = 0; i < kWizardSteps; ++i) {
    if (static_cast<size_t>(kSteps[i].step) != i) return false;
  }
  return true;
}
static_assert(rows_in_step_order(), "kSteps is indexed by WizardStep");

constexpr WizardStep kControls[] = {WizardStep::roll, WizardStep::pitch, WizardStep::yaw, WizardStep::lift};

const StepRow& row(WizardStep step) { return kSteps[static_cast<size_t>(step)]; }
bool is_control(WizardStep step) { return row(step).binding != nullptr; }

int64_t clamped(int32_t raw) { return std::clamp<int64_t>(raw, -kAxisMax, kAxisMax); }
int32_t ceil_div(int64_t a, int64_t b) { return static_cast<int32_t>((a + b - 1) / b); }

std::string describe(WizardStep step, const ControlFound& found) {
  return "axis " + std::to_string(found.axis) + ", " + std::to_string(found.min) + ".." + std::to_string(found.max) +
         ", " + row(step).positive + " reads " + (found.invert ? "- (inverted)" : "+");
}

}  // namespace

void JoystickWizard::follow(Travel& travel, int32_t value) {
  if (!travel.seen) travel = Travel{true, value, value, value, 0};  // first reported in the middle of a step
  travel.min = std::min(travel.min, value);
  travel.max = std::max(travel.max, value);
  const int32_t away = value - travel.start;
  if (travel.first_sign == 0 && (away >= kExcursion || away <= -kExcursion)) travel.first_sign = away > 0 ? 1 : -1;
}

void JoystickWizard::event(const js_event& event) {
  const uint8_t type = event.type & static_cast<uint8_t>(~JS_EVENT_INIT);
  const bool initial = (event.type & JS_EVENT_INIT) != 0;
  if (type == JS_EVENT_AXIS && event.number < kMaxAxes) {
    value_[event.number] = event.value;
    seen_[event.number] = true;
    if (resting_) follow(rest_[event.number], event.value);
    if (is_control(step_)) follow(travel_[event.number], event.value);
  } else if (type == JS_EVENT_BUTTON && step_ == WizardStep::fire && event.value != 0 && !initial) {
    fire_button_ = event.number;
    review();
  }
}

void JoystickWizard::next(uint32_t now_ms) {
  if (step_ == WizardStep::rest && !resting_) {
    // The rest starts from where every axis is now: a still stick sends nothing.
    resting_ = true;
    rest_start_ms_ = now_ms;
    from_here(rest_);
  } else if (is_control(step_)) {
    found_[static_cast<size_t>(step_)] = most_moved(travel_);
    begin(static_cast<WizardStep>(static_cast<size_t>(step_) + 1));
  } else if (step_ == WizardStep::fire) {
    review();  // without a button: refused there
  }
}

void JoystickWizard::tick(uint32_t now_ms) {
  if (resting_ && now_ms - rest_start_ms_ >= kRestMs) {
    resting_ = false;
    begin(WizardStep::roll);
  }
}

void JoystickWizard::restart() {
  resting_ = false;
  found_ = {};
  fire_button_.reset();
  errors_.clear();
  notes_.clear();
  map_ = JoystickMap{};
  step_ = WizardStep::rest;
}

int32_t JoystickWizard::rest_done_permille(uint32_t now_ms) const {
  if (!resting_) return step_ == WizardStep::rest ? 0 : kPermille;
  return static_cast<int32_t>(std::min<uint32_t>(now_ms - rest_start_ms_, kRestMs) * kPermille / kRestMs);
}

const char* JoystickWizard::name(WizardStep step) { return row(step).name; }
const char* JoystickWizard::instruction(WizardStep step) { return row(step).instruction; }

void JoystickWizard::begin(WizardStep step) {
  step_ = step;
  from_here(travel_);
}

void JoystickWizard::from_here(Travels& travels) const {
  for (size_t axis = 0; axis < kMaxAxes; ++axis) {
    travels[axis] = seen_[axis] ? Travel{true, value_[axis], value_[axis], value_[axis], 0} : Travel{};
  }
}

ControlFound JoystickWizard::most_moved(const Travels& travels) const {
  ControlFound best;
  int32_t best_travel = 0;
  for (size_t axis = 0; axis < kMaxAxes; ++axis) {
    const Travel& t = travels[axis];
    if (!t.seen || t.max - t.min <= best_travel) continue;  // a tie goes to the lower axis
    best_travel = t.max - t.min;
    best.axis = static_cast<uint8_t>(axis);
    best.min = t.min;
    best.max = t.max;
    best.invert = t.first_sign < 0;
    best.moved = best_travel >= kMinTravel && t.first_sign != 0;
  }
  return best;
}

ControlFound JoystickWizard::leading() const { return is_control(step_) ? most_moved(travel_) : ControlFound{}; }

const ControlFound& JoystickWizard::found(WizardStep control) const { return found_[static_cast<size_t>(control)]; }

std::string JoystickWizard::summary(WizardStep control) const {
  const ControlFound& f = found(control);
  return f.moved ? describe(control, f) : "nothing moved through half its range";
}

// The highest reading of the control's axis while resting, as the map reads it before the
// deadband: per mille of deflection from the centre, or from closed for the throttle.
std::optional<int32_t> JoystickWizard::rest_reading(WizardStep control, const ControlFound& found) const {
  const Travel& rest = rest_[found.axis];
  if (!rest.seen) return std::nullopt;
  if (row(control).from_closed_end) {
    const int64_t most_open = found.invert ? -clamped(rest.min) : clamped(rest.max);
    return ceil_div((most_open + kAxisMax) * kPermille, 2 * kAxisMax);
  }
  const int64_t farthest = std::max(-clamped(rest.min), clamped(rest.max));
  return ceil_div(std::max<int64_t>(farthest, 0) * kPermille, kAxisMax);
}

void JoystickWizard::check_control(WizardStep control) {
  ControlFound& f = found_[static_cast<size_t>(control)];
  const StepRow& r = row(control);
  const std::string name = r.name;
  if (!f.moved) {
    errors_.push_back(name + ": no axis moved through half its range or more (" + r.how + " in its step)");
    return;
  }
  (map_.*r.binding) = AxisBinding{f.axis, f.invert};
  const std::string axis = "axis " + std::to_string(f.axis);
  f.rest_permille = rest_reading(control, f);
  if (!f.rest_permille) {
    errors_.push_back(name + ": " + axis + " had not reported its position at the rest (was the joystick in?)");
  } else if (*f.rest_permille > kMaxRestPermille) {
    errors_.push_back(name + ": " + axis + " read " + std::to_string(*f.rest_permille) +
                      " per mille at the rest, more than " + std::to_string(kMaxRestPermille) + " (" + r.at_rest +
                      " while resting)");
  }
  if (f.min > -kFullReach || f.max < kFullReach) {
    notes_.push_back(name + ": " + axis + " reached only " + std::to_string(f.min) + ".." + std::to_string(f.max) +
                     " of -32767..32767: the driver's calibration may be off (jscal), or it was not moved fully");
  }
}

void JoystickWizard::review() {
  step_ = WizardStep::review;
  errors_.clear();
  notes_.clear();
  map_ = JoystickMap{};
  int32_t highest_rest = 0;
  for (WizardStep control : kControls) {
    check_control(control);
    highest_rest = std::max(highest_rest, found(control).rest_permille.value_or(0));
  }
  for (size_t i = 0; i < std::size(kControls); ++i) {
    for (size_t j = i + 1; j < std::size(kControls); ++j) {
      const ControlFound& a = found(kControls[i]);
      const ControlFound& b = found(kControls[j]);
      if (!a.moved || !b.moved || a.axis != b.axis) continue;
      errors_.push_back(std::string(name(kControls[i])) + " and " + name(kControls[j]) + " both moved axis " +
                        std::to_string(a.axis) + " most (in each step move only the control it asks for)");
    }
  }
  if (!fire_button_) {
    errors_.push_back("fire: no button was pressed");
  } else if (*fire_button_ >= kMaxAxes) {
    errors_.push_back("fire: button " + std::to_string(*fire_button_) + " is past 63, more than the map can name");
  } else {
    map_.abort_button = *fire_button_;
  }
  map_.deadband_permille = std::min(std::max(kMinDeadband, 2 * highest_rest), kMaxDeadband);
}

std::string JoystickWizard::map_text() const {
  std::string text = "# written by qrterm --joystick-wizard; what each control did in its step:\n";
  for (WizardStep control : kControls) text += std::string("#   ") + name(control) + ": " + summary(control) + "\n";
  if (fire_button_) text += "#   fire: button " + std::to_string(*fire_button_) + "\n";
  text += "#   deadband: " + deadband_reason() + "\n";
  return text + format_joystick_map(map_);
}

std::string JoystickWizard::deadband_reason() const {
  WizardStep most = kControls[0];
  for (WizardStep control : kControls) {
    if (found(control).rest_permille.value_or(0) > found(most).rest_permille.value_or(0)) most = control;
  }
  const int32_t reading = found(most).rest_permille.value_or(0);
  if (2 * reading <= kMinDeadband) {
    return "the least, " + std::to_string(kMinDeadband) + ": no control read more than " +
           std::to_string(kMinDeadband / 2) + " per mille at rest";
  }
  return "twice the " + std::to_string(reading) + " per mille " + name(most) + " read at rest";
}

std::vector<std::pair<uint8_t, int32_t>> JoystickWizard::axes() const {
  std::vector<std::pair<uint8_t, int32_t>> out;
  for (size_t axis = 0; axis < kMaxAxes; ++axis) {
    if (seen_[axis]) out.emplace_back(static_cast<uint8_t>(axis), value_[axis]);
  }
  return out;
}

}  // namespace qrterm
