#include <qr/sim_runner/scenario_score.hpp>

#include <qr/core/control_rate.hpp>
#include <qr/core/safety.hpp>

#include <algorithm>
#include <cmath>

namespace qrsim {
namespace {

// The scenario's attitude step: the first roll or pitch event away from centre, the first later
// event on the same axis back to centre (the release), if any, and the first event from the
// release on that moves the attitude again, which ends the release's settling.
struct StepPlan {
  bool roll = true;
  double amount = 0;  // degrees
  double at_s = 0;
  double release_at_s = kNotMeasured;
  double disturbed_at_s = kNotMeasured;
};

// A push, a hand's turn or a roll or pitch stick: what moves the attitude away from where the
// release left it, so a settling after it is not the release's.
bool disturbs_attitude(const Event& e) {
  switch (e.action) {
    case Action::torque:
    case Action::force:
    case Action::turn:
    case Action::roll:
    case Action::pitch: return true;
    default: return false;
  }
}

bool find_step(const ScenarioScript& script, StepPlan& plan) {
  bool found = false;
  for (size_t i = 0; i < script.events.size(); ++i) {
    const Event& e = script.events[i];
    const bool axis = e.action == Action::roll || e.action == Action::pitch;
    if (!axis) continue;
    if (!found && e.value != 0) {
      plan = {e.action == Action::roll, e.value, e.at_s, kNotMeasured, kNotMeasured};
      found = true;
    } else if (found && (e.action == Action::roll) == plan.roll && e.value == 0) {
      plan.release_at_s = e.at_s;
      // Events are in time order: the first disturbing one at or after the release's time (one
      // written beside it at the same time counts too) ends the window.
      for (size_t j = 0; j < script.events.size(); ++j) {
        const Event& next = script.events[j];
        if (j != i && next.at_s >= e.at_s && disturbs_attitude(next)) {
          plan.disturbed_at_s = next.at_s;
          break;
        }
      }
      break;
    }
  }
  return found;
}

const Event* first_of(const ScenarioScript& script, bool (*wanted)(const Event&)) {
  for (const Event& e : script.events) {
    if (wanted(e)) return &e;
  }
  return nullptr;
}

// The samples of `trace` with t in [t0, t1).
Trace between(const Trace& trace, double t0, double t1) {
  Trace out;
  for (const Sample& s : trace) {
    if (s.t >= t0 && s.t < t1) out.push_back(s);
  }
  return out;
}

// |a - b| sample by sample (the two traces are recorded on the same ticks).
Trace difference(const Trace& a, const Trace& b) {
  Trace out;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) out.push_back({a[i].t, a[i].value - b[i].value});
  return out;
}

// max(|a|, |b|) sample by sample: both axes within a band when this is.
Trace larger_magnitude(const Trace& a, const Trace& b) {
  Trace out;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    out.push_back({a[i].t, std::max(std::abs(a[i].value), std::abs(b[i].value))});
  }
  return out;
}

void step_figures(const ScenarioScript& script, const FlightRecord& rec, std::vector<Figure>& f, double& held_from,
                  double& held_to) {
  StepFigures truth, estimate;
  double release_settle = kNotMeasured;
  StepPlan plan;
  if (find_step(script, plan) && rec.t0 >= 0) {
    const Trace& sp = plan.roll ? rec.roll_sp : rec.pitch_sp;
    const Trace& real = plan.roll ? rec.roll_true : rec.pitch_true;
    const Trace& est = plan.roll ? rec.roll_est : rec.pitch_est;
    const double half = 0.5 * std::abs(plan.amount);
    // The step starts when the firmware's set-point moves (the stick's frame has arrived), and
    // the hold ends when it moves back.
    double t_step = kNotMeasured, target = 0, t_release = rec.t_end + 1;
    for (const Sample& s : sp) {
      if (std::isnan(t_step) && s.t >= rec.t0 + plan.at_s && std::abs(s.value) > half) {
        t_step = s.t;
        target = s.value;
      } else if (!std::isnan(t_step) && !std::isnan(plan.release_at_s) && s.t >= rec.t0 + plan.release_at_s &&
                 std::abs(s.value) < half) {
        t_release = s.t;
        break;
      }
    }
    if (!std::isnan(t_step)) {
      const Trace real_held = between(real, rec.t0, t_release);
      const Trace est_held = between(est, rec.t0, t_release);
      truth = step_response(real_held, t_step, mean(real, rec.t0, t_step), target, 1.0);
      estimate = step_response(est_held, t_step, mean(est, rec.t0, t_step), target, 1.0);
      f.push_back({"step_setpoint_deg", target});
      f.push_back({"step_delay_s", t_step - rec.t0 - plan.at_s});
      held_from = t_step + kSettleAllowanceS;
      held_to = std::min(t_release, rec.t_end + 1);
      if (t_release <= rec.t_end) {
        // Up to the next event that moves the attitude (or the window's end): a push after the
        // release is the push's recovery, not the release's settling. A window that next event
        // leaves empty measures nothing.
        const double until = std::isnan(plan.disturbed_at_s) ? rec.t_end + 1 : rec.t0 + plan.disturbed_at_s;
        const Trace after = between(difference(real, sp), t_release, until);
        release_settle = after.empty() ? kNotMeasured : recovery_time(after, t_release, 1.0);
      }
    }
  }
  f.push_back({"rise_s", truth.rise_s});
  f.push_back({"overshoot_pct", truth.overshoot_pct});
  f.push_back({"settle_s", truth.settle_s});
  f.push_back({"rise_s_est", estimate.rise_s});
  f.push_back({"overshoot_pct_est", estimate.overshoot_pct});
  f.push_back({"settle_s_est", estimate.settle_s});
  f.push_back({"release_settle_s", release_settle});
}

// Height hold, on the truth: how well it held the height it was entered at, until the pilot's lift
// changed (or the window's end), and how many control periods the firmware took to leave it after
// reading a changed lift (0: in the tick that read it).
void height_hold_figures(const FlightRecord& rec, std::vector<Figure>& f) {
  if (rec.hold_height_err.empty()) {
    for (const char* name : {"height_hold_s", "height_hold_rms_m", "height_hold_drift_m", "height_hold_exit_periods"}) {
      f.push_back({name, kNotMeasured});
    }
    return;
  }
  const double begin = rec.hold_height_err.front().t;
  const double end = std::isnan(rec.hold_lift_changed_at) ? rec.hold_height_err.back().t : rec.hold_lift_changed_at;
  f.push_back({"height_hold_s", end - begin});
  f.push_back({"height_hold_rms_m", rms(rec.hold_height_err, begin, end)});
  f.push_back({"height_hold_drift_m", std::abs(mean(rec.hold_height_err, end - 1.0, end))});
  f.push_back({"height_hold_exit_periods", (rec.hold_left_at - rec.hold_lift_changed_at) * qr::kControlHz});
}

// Leaving the ground and coming back to it: the touchdown, the cuts, the take-off and the
// firmware's landed/flying verdicts against the truth.
void ground_figures(const FlightRecord& rec, std::vector<Figure>& f) {
  f.push_back({"touchdown_speed_m_s", rec.touchdown_speed});
  f.push_back({"engines_stop_s", rec.engines_stopped_at - rec.touchdown_at});
  f.push_back({"panic_engines_zero_s", rec.panic_engines_zero_at - rec.panic_at});
  f.push_back({"cut_after_liftoff_s", rec.panic_engines_zero_at - rec.left_ground_at});
  f.push_back({"max_clearance_m_truth", rec.max_clearance});
  // Left the ground but never seen flying: not measured, so a band on it fails.
  f.push_back({"takeoff_seen_s", rec.flying_seen_at - rec.left_ground_at});
  f.push_back({"false_takeoffs", rec.belief_seen ? static_cast<double>(rec.false_takeoffs) : kNotMeasured});
  f.push_back({"touchdown_declared_clearance_m_max", rec.declared_clearance});
}

}  // namespace

void add_flight_figures(const ScenarioScript& script, const FlightRecord& rec, const EndState& end,
                        std::vector<Figure>& f) {
  const double t0 = rec.t0, t_end = rec.t_end;
  f.push_back({"att_rms_deg_truth", rms(rec.att_err, t0, t_end)});
  f.push_back({"att_rms_deg_last_s", rms(rec.att_err, t_end - 1, t_end)});  // how it ended
  double held_from = t0, held_to = t_end + 1;
  std::vector<Figure> step;
  step_figures(script, rec, step, held_from, held_to);
  // An empty held part (a window that ends before the step could settle) is not measured.
  const Trace held = between(rec.axis_err, held_from, std::min(held_to, t_end + 1e-9));
  f.push_back({"att_err_deg_truth_max_after_settle", held.empty() ? kNotMeasured : peak_abs(held, held_from, held_to)});
  f.push_back({"max_tilt_deg_truth", peak_abs(rec.tilt, t0, t_end)});
  f.push_back({"est_err_rms_deg", rms(rec.est_err, t0, t_end)});
  f.push_back({"est_err_max_deg", peak_abs(rec.est_err_axis, t0, t_end)});
  f.insert(f.end(), step.begin(), step.end());

  if (const Event* yaw = first_of(script, [](const Event& e) { return e.action == Action::yaw && e.value != 0; });
      yaw != nullptr && t0 >= 0) {
    // Steady state over the last 40 % of the window from the yaw stick on, on the truth, against
    // the set-point.
    const double t_yaw = t0 + yaw->at_s;
    const double r = mean(rec.r_true, t_yaw + 0.6 * (t_end - t_yaw), t_end);
    f.push_back({"yaw_rate_setpoint_rad_s", end.yaw_rate_setpoint});
    f.push_back({"yaw_rate_rad_s", r});
    f.push_back({"yaw_rate_p_only_rad_s", end.yaw_rate_p_only});
    f.push_back({"yaw_rate_error_pct", std::abs(r / end.yaw_rate_setpoint - 1) * 100});
  }

  const Event* push = first_of(script,
                               [](const Event& e) { return e.action == Action::torque || e.action == Action::force; });
  if (push != nullptr && t0 >= 0) {
    const double t_push = t0 + push->at_s;
    f.push_back({"peak_error_deg", peak_abs(rec.att_err, t_push, t_end) * std::sqrt(2.0)});
    f.push_back({"recovery_s", recovery_time(between(rec.worst_err, t_push, t_end + 1), t_push, 1.0)});
    f.push_back({"recovery_2deg_s", recovery_time(between(rec.worst_err, t_push, t_end + 1), t_push, 2.0)});
    // From the push's end: recovery_s counts the time the push was still pushing, which a longer
    // push lengthens whatever the loops do; these count only what the loops take once it stops.
    // The estimate is judged on every tick as the truth is (not only where the attitude loops fly:
    // a panic after the push must not cut its trace short), on both axes.
    const double t_push_end = t_push + push->duration_s;
    double push_end_recovery = kNotMeasured, est_recovery = kNotMeasured;
    if (t_push_end <= t_end) {
      const Trace truth_after = between(rec.worst_err, t_push_end, t_end + 1);
      const Trace est_after = between(
          larger_magnitude(difference(rec.roll_est, rec.roll_true), difference(rec.pitch_est, rec.pitch_true)),
          t_push_end, t_end + 1);
      if (!truth_after.empty()) push_end_recovery = recovery_time(truth_after, t_push_end, 1.0);
      if (!est_after.empty()) est_recovery = recovery_time(est_after, t_push_end, 1.0);
    }
    f.push_back({"push_end_recovery_s", push_end_recovery});
    f.push_back({"est_recovery_s", est_recovery});
  }

  f.push_back({"entered_panic", rec.entered_panic ? 1.0 : 0.0});
  f.push_back({"panic_after_s", rec.panic_at - t0});
  f.push_back({"safe_after_s", rec.safe_at - t0});
  {
    // A battery panic only (a link loss or the pilot's stop says nothing about the battery), by
    // the cause the firmware announced; one whose cause was not heard is not measured.
    const char* battery = qr::kPanicCauseNames[static_cast<uint8_t>(qr::PanicCause::battery_low)];
    double rested_above = 0;
    if (rec.entered_panic && rec.panic_cause.empty()) {
      rested_above = kNotMeasured;
    } else if (rec.entered_panic && rec.panic_cause == battery) {
      rested_above = rec.rested_v_at_panic > end.battery_panic_volts ? 1.0 : 0.0;
    }
    f.push_back({"panic_while_rested_above_threshold", rested_above});
  }
  f.push_back({"battery_v_min", rec.battery_v_min});
  f.push_back({"battery_rested_v_min", rec.rested_v_min});
  ground_figures(rec, f);
  height_hold_figures(rec, f);
}

void judge(const ScenarioScript& script, ScenarioResult& result) {
  result.pass = result.error.empty();
  for (const Band& band : script.bands) {
    const double value = result.figure(band.figure);
    bool ok = false;
    switch (band.compare) {
      case Compare::below: ok = value < band.limit; break;
      case Compare::at_most: ok = value <= band.limit; break;
      case Compare::equal: ok = value == band.limit; break;
      case Compare::above: ok = value > band.limit; break;
      case Compare::at_least: ok = value >= band.limit; break;
    }
    result.checks.push_back({band_text(band), ok});
    result.pass = result.pass && ok;
  }
}

}  // namespace qrsim
