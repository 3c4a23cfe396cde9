#include <tune/report_json.hpp>

#include <cmath>
#include <cstdio>

namespace tune {

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

std::string model_json(const AxisModel& m) {
  return "{\"gain\": " + json_number(m.gain) + ", \"motor_tau_s\": " + json_number(m.motor_tau_s) +
         ", \"delay_s\": " + json_number(m.delay_s) + ", \"lead_s\": " + json_number(m.lead_s) +
         ", \"damping_per_s\": " + json_number(m.damping_per_s) + ", \"residual\": " + json_number(m.residual) + "}";
}

std::string margins_json(const Margins& m) {
  return "{\"phase_margin_deg\": " + json_number(m.phase_margin_deg) +
         ", \"gain_margin_db\": " + json_number(m.gain_margin_db) +
         ", \"crossover_hz\": " + json_number(m.crossover_hz) + "}";
}

std::string step_json(const StepFigures& s) {
  return "{\"rise_s\": " + json_number(s.rise_s) + ", \"overshoot_pct\": " + json_number(s.overshoot_pct) +
         ", \"settle_s\": " + json_number(s.settle_s) + ", \"peak_moment\": " + json_number(s.peak_moment) + "}";
}

std::string design_json(const AxisDesign& rp, const YawDesign& yaw) {
  return "{\"roll_pitch\": {\"p1\": " + json_number(rp.gains.p1) + ", \"p2\": " + json_number(rp.gains.p2) +
         ", \"i\": " + json_number(rp.gains.i) + ", \"d\": " + json_number(rp.gains.d) +
         ", \"inner\": " + margins_json(rp.inner) + ", \"outer\": " + margins_json(rp.outer) +
         ", \"step\": " + step_json(rp.step) + "}, \"yaw\": {\"p\": " + json_number(yaw.gains.p) +
         ", \"i\": " + json_number(yaw.gains.i) + ", \"loop\": " + margins_json(yaw.loop) +
         ", \"step\": " + step_json(yaw.step) + "}}";
}

std::string params_json(const RollPitchGains& rp, const YawGains& yaw) {
  std::string s = "{";
  const auto add = [&](const RawParameter& p) {
    s += (s.size() > 1 ? ", \"" : "\"") + std::string(p.name()) + "\": " + p.text();
  };
  for (const RawParameter& p : raw_parameters(rp)) add(p);
  for (const RawParameter& p : raw_parameters(yaw)) add(p);
  return s + "}";
}

}  // namespace tune
