#include <tune/identification_design.hpp>

#include <span>

namespace tune {

std::optional<IdentificationDesign> design_from_identification(std::array<AxisRecord, 3> records,
                                                               const wire::ParameterValues& flown, double control_hz,
                                                               std::string* why) {
  DesignLimits limits;
  limits.control_hz = control_hz;
  limits.filter_cutoff_hz = flown.get(wire::ParamId::filter_cutoff_hz);
  IdentificationDesign d;
  for (size_t i = 0; i < 3; ++i) {
    AxisRecord& record = records[i];
    record.sample_hz = control_hz;
    record.filter_cutoff_hz = limits.filter_cutoff_hz;
    record.yaw = i == 2;
    std::string fit_why;
    const std::optional<AxisModel> m = fit_axis(record, &fit_why);
    if (!m) {
      if (why != nullptr) *why = std::string(kAxisNames[i]) + "'s fit: " + fit_why;
      return std::nullopt;
    }
    d.models[i] = *m;
  }
  d.roll_pitch = design_roll_pitch(std::span<const AxisModel>(d.models.data(), 2), limits);
  d.yaw = design_yaw(d.models[2], limits).gains;
  d.roll_pitch_before = roll_pitch_gains(flown);
  d.yaw_before = yaw_gains(flown);
  d.before = evaluate(d.models[0], d.roll_pitch_before, limits);
  d.after = evaluate(d.models[0], d.roll_pitch, limits);
  d.after_pitch = evaluate(d.models[1], d.roll_pitch, limits);
  d.yaw_then = evaluate(d.models[2], d.yaw_before, limits);
  d.yaw_now = evaluate(d.models[2], d.yaw, limits);
  d.keeps = keeps_targets(d.after, limits) && keeps_targets(d.after_pitch, limits) && keeps_targets(d.yaw_now, limits);
  return d;
}

}  // namespace tune
