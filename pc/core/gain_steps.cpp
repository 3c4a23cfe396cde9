#include <pc/core/gain_steps.hpp>

#include <algorithm>

namespace qrterm {

const GainStep* find_gain_step(Action action) {
  for (const GainStep& step : kGainSteps) {
    if (step.action == action) return &step;
  }
  return nullptr;
}

int32_t stepped(const GainStep& step, int32_t raw) {
  const wire::ParameterSpec* spec = wire::find_parameter(static_cast<uint8_t>(step.id));
  int64_t value = int64_t{raw} + step.add;
  if (step.multiply > 1) value *= step.multiply;
  if (step.multiply < -1) value /= -step.multiply;
  return static_cast<int32_t>(std::clamp<int64_t>(value, spec->min, spec->max));
}

}  // namespace qrterm
