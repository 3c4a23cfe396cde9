#include <pc/core/autotune_proposal.hpp>

#include <cmath>
#include <cstdio>

namespace qrterm {
namespace {

// "61.2->55.0": a figure before and after; "inf" where a margin is unbounded.
std::string before_after(double before, double after, const char* number) {
  auto one = [&](double x) {
    if (!std::isfinite(x)) return std::string("inf");
    char text[32];
    std::snprintf(text, sizeof text, number, x);
    return std::string(text);
  };
  return one(before) + "->" + one(after);
}

// One axis' predicted figures, before and after, in 80 columns: PM phase margin, GM gain margin,
// the rise of a step (10 % to 90 %), OS its overshoot.
std::string figures(const char* axis, const tune::Margins& m0, const tune::Margins& m1, const tune::StepFigures& s0,
                    const tune::StepFigures& s1) {
  return std::string(axis) + " PM " + before_after(m0.phase_margin_deg, m1.phase_margin_deg, "%.1f") + " deg  GM " +
         before_after(m0.gain_margin_db, m1.gain_margin_db, "%.1f") + " dB  rise " +
         before_after(s0.rise_s, s1.rise_s, "%.3f") + " s  OS " +
         before_after(s0.overshoot_pct, s1.overshoot_pct, "%.1f") + " %";
}

// "roll 0.1761/38.4ms": an axis' fitted gain (rad/s2 per thrust unit) and motor lag.
std::string models_line(const std::array<tune::AxisModel, 3>& models) {
  std::string line = "model gain/lag:";
  for (size_t axis = 0; axis < 3; ++axis) {
    char text[48];
    std::snprintf(text, sizeof text, " %s %.4g/%.1fms", tune::kAxisNames[axis], models[axis].gain,
                  models[axis].motor_tau_s * 1e3);
    line += text;
  }
  return line;
}

std::string change_text(const GainChange& c) {
  const wire::ParameterSpec* spec = wire::find_parameter(static_cast<uint8_t>(c.id));
  if (spec == nullptr) return "?";
  const double unit = std::ldexp(1.0, -spec->frac_bits);
  char text[64];
  std::snprintf(text, sizeof text, "%-14s %8.3f %8.3f", spec->name, c.before * unit, c.after * unit);
  return text;
}

}  // namespace

AutotuneProposal::Outcome AutotuneProposal::compute(const std::array<tune::AxisRecord, 3>& records,
                                                    const wire::ParameterValues& flown, double control_hz) {
  Outcome outcome;
  outcome.design = tune::design_from_identification(records, flown, control_hz, &outcome.why);
  return outcome;
}

void AutotuneProposal::take(const Outcome& outcome, const wire::ParameterValues& flown) {
  design_ = outcome.design;
  changes_.clear();
  if (!design_) return refuse("autotune refused: " + outcome.why);
  why_.clear();
  standing_ = Standing::proposed;
  for (const tune::RawParameter& p : tune::raw_parameters(design_->roll_pitch))
    changes_.push_back({p.id, flown.get(p.id), p.raw});
  for (const tune::RawParameter& p : tune::raw_parameters(design_->yaw))
    changes_.push_back({p.id, flown.get(p.id), p.raw});
}

void AutotuneProposal::refuse(const std::string& why) {
  standing_ = Standing::refused;
  why_ = why;
  design_.reset();
  changes_.clear();
}

bool AutotuneProposal::send(ParameterSync& parameters, bool after) {
  if (changes_.empty()) return false;
  for (const GainChange& c : changes_) parameters.set(c.id, after ? c.after : c.before);
  standing_ = after ? Standing::accepted : Standing::back;
  return true;
}

bool AutotuneProposal::accept(ParameterSync& parameters) { return send(parameters, true); }
bool AutotuneProposal::back(ParameterSync& parameters) { return send(parameters, false); }

std::vector<std::string> AutotuneProposal::lines() const {
  if (standing_ == Standing::none) return {};
  if (standing_ == Standing::refused) return {why_};
  char header[96];
  std::snprintf(header, sizeof header, "%-14s %8s %8s     | %-14s %8s %8s", "autotune", "before", "new", "", "before",
                "new");
  std::vector<std::string> out = {models_line(design_->models), header};
  // Two gains a row: roll_pitch_p1 and p2, i and d, yaw_p and yaw_i.
  for (size_t i = 0; i + 1 < changes_.size(); i += 2)
    out.push_back(change_text(changes_[i]) + "     | " + change_text(changes_[i + 1]));
  out.push_back(
      figures("roll", design_->before.inner, design_->after.inner, design_->before.step, design_->after.step));
  out.push_back(
      figures("yaw ", design_->yaw_then.loop, design_->yaw_now.loop, design_->yaw_then.step, design_->yaw_now.step));
  static const char* const kStanding[] = {"", "", "proposed: ^T sends the new gains",
                                          "the new gains sent: ^R goes back",
                                          "the gains before sent again: ^T takes the new ones"};
  out.push_back(std::string(kStanding[static_cast<size_t>(standing_)]) +
                (design_->keeps ? "" : " (the new gains miss a target)"));
  return out;
}

}  // namespace qrterm
