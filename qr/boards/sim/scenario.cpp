#include <qr/boards/sim/scenario.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>

#include <qr/boards/sim/manoeuvres.hpp>
#include <qr/boards/sim/pilot.hpp>
#include <qr/boards/sim/scoring.hpp>
#include <qr/boards/sim/sim_qr.hpp>
#include <qr/host/replay.hpp>

namespace qrsim {
namespace {

constexpr double kDeg = 180 / std::numbers::pi;

// ---- the flight plan ------------------------------------------------------------------------
// What the pilot does before the manoeuvre, one phase after the other. Each phase has a time
// limit; a flight that overruns one fails with the phase's name as its error.
enum class Phase : uint8_t { power_up, calibrate, arm, take_off, settle, manoeuvre };

constexpr double kHoverHeight = 1.5;    // m, centre of mass above the ground
constexpr double kSettleSeconds = 1.5;  // steady hover before the manoeuvre
constexpr double kPreflightLimit = 20;  // s

// The pilot's thumb on the lift stick, watching the vehicle: lift for the weight (what the pilot
// knows this vehicle hovers at, for its battery now) corrected for the height and climb rate
// the pilot sees and for the tilt. Slow next to the attitude loops, as a person is.
uint16_t lift_for_height(const sim::Quadrotor& plant, double target, double ramp) {
  const sim::PlantState& s = plant.state();
  const double height = -s.position.z, climb = -s.velocity.z;
  const double accel = std::clamp(2.0 * (target - height) - 2.5 * climb, -3.0, 3.0);
  const sim::Vec3 body_down = sim::rotate(s.attitude, {0, 0, 1});
  const double cos_tilt = std::max(0.5, body_down.z);
  const double thrust_ratio = std::max(0.0, (sim::kGravity + accel) / (sim::kGravity * cos_tilt));
  const double lift = plant.hover_command() * std::sqrt(thrust_ratio) * std::clamp(ramp, 0.0, 1.0);
  return static_cast<uint16_t>(std::clamp(std::lround(lift), 0L, 1000L));
}

// What is recorded every control period.
struct Record {
  Trace roll_est, pitch_est, roll_true, pitch_true, roll_sp, pitch_sp;  // degrees
  Trace r_true;                                                         // rad/s
  Trace att_err, est_err;                                               // degrees, both axes
  Trace tilt;                                                           // degrees
  Trace saturated;                                                      // 0 or 100
};

}  // namespace

double ScenarioResult::figure(const std::string& name) const {
  for (const Figure& f : figures) {
    if (f.name == name) return f.value;
  }
  return kNotMeasured;
}

ScenarioResult run_scenario(const ScenarioOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  ScenarioResult result;
  result.scenario = options.name;
  result.vehicle = options.vehicle_name;
  const ScenarioSpec* spec = find_scenario(options.name);
  if (spec == nullptr) {
    result.error = "no scenario " + options.name;
    return result;
  }
  const double seconds = options.seconds > 0 ? options.seconds : spec->default_seconds;

  sim::VehicleParams vehicle = options.vehicle;
  if (!options.sensor_noise) {
    vehicle.gyro_noise_dps_rthz = vehicle.accel_noise_ug_rthz = 0;
    vehicle.gyro_bias_dps = vehicle.accel_bias_xy_mg = vehicle.accel_bias_z_mg = vehicle.scale_error = 0;
    vehicle.vibration_accel_g = vehicle.vibration_gyro_dps = {};
    vehicle.battery_sense_noise_mv = 0;
    vehicle.baro_noise_pa = vehicle.baro_temp_coeff_pa_per_k = 0;
  }
  std::unique_ptr<SimQr> qr = make_qr(vehicle, {.seed = options.seed});
  sim::Quadrotor& plant = qr->world.plant();
  Pilot pilot(qr->board);

  Phase phase = Phase::power_up;
  double phase_start = 0, t0 = -1, t_end = 1e9;
  double yaw_p = 0, yaw_steady_from = 0;
  bool entered_panic = false;
  bool manoeuvre_started = false;
  double panic_at = kNotMeasured, safe_at = kNotMeasured;
  int calibration_requests = 0;
  Record rec;
  FILE* record = options.record_path.empty() ? nullptr : std::fopen(options.record_path.c_str(), "w");
  if (record != nullptr) std::fprintf(record, "%s\n", qr::host::replay_input_header().c_str());
  bool recording = false;
  FILE* trace = options.trace_path.empty() ? nullptr : std::fopen(options.trace_path.c_str(), "w");
  if (trace != nullptr) {
    std::fprintf(trace,
                 "t_s,mode,roll_deg,pitch_deg,yaw_deg,roll_est_deg,pitch_est_deg,yaw_est_deg,roll_sp_deg,pitch_sp_deg,"
                 "p_rad_s,q_rad_s,r_rad_s,p_est_rad_s,q_est_rad_s,r_est_rad_s,engine0,engine1,engine2,engine3,"
                 "height_m,north_m,east_m,battery_v,roll_est_e4,pitch_est_e4,yaw_est_e4\n");
  }
  const auto idle = static_cast<uint16_t>(qr->firmware.parameters().get(wire::ParamId::idle_level));

  for (;;) {
    const double t = static_cast<double>(qr->world.now_us()) * 1e-6;
    const uint8_t mode = static_cast<uint8_t>(qr->firmware.mode());
    const ConsoleView& view = pilot.view();
    const auto enter = [&](Phase next) {
      phase = next;
      phase_start = t;
    };

    // ---- the pilot ----
    switch (phase) {
      case Phase::power_up:  // sensors settle, parameters go up
        if (t - phase_start >= 0.3) {
          for (const auto& [id, raw] : options.parameters) pilot.set_parameter(id, raw);
          enter(Phase::calibrate);
        }
        break;
      case Phase::calibrate:
        if (!pilot.request_pending(wire::MessageType::mode_change) && calibration_requests == 0) {
          pilot.request_mode(wire::Mode::calibration);
          ++calibration_requests;
        }
        if (view.heard && (view.flags & wire::kFlagCalibrated) != 0 && view.mode == wire::Mode::safe &&
            !pilot.request_pending(wire::MessageType::param_set)) {
          pilot.request_mode(wire::Mode::full_control);
          enter(Phase::arm);
        }
        break;
      case Phase::arm:
        if (view.mode == wire::Mode::full_control) enter(Phase::take_off);
        break;
      case Phase::take_off: {
        pilot.set_sticks({lift_for_height(plant, kHoverHeight, (t - phase_start) / 1.0), 0, 0, 0});
        const sim::PlantState& s = plant.state();
        if (std::abs(-s.position.z - kHoverHeight) < 0.1 && std::abs(s.velocity.z) < 0.1) enter(Phase::settle);
        break;
      }
      case Phase::settle:
        pilot.set_sticks({lift_for_height(plant, kHoverHeight, 1), 0, 0, 0});
        if (t - phase_start >= kSettleSeconds) {
          enter(Phase::manoeuvre);
          t0 = t;
          t_end = t0 + seconds;
          yaw_p = qr->firmware.parameters().get(wire::ParamId::yaw_p) / 16.0;
        }
        break;
      case Phase::manoeuvre: {
        const double since = t - t0;
        Sticks s{lift_for_height(plant, kHoverHeight, 1), 0, 0, 0};
        ManoeuvreStep step{*spec, since, !manoeuvre_started, s, pilot, plant, qr->firmware.parameters()};
        fly_manoeuvre(step);
        manoeuvre_started = true;
        pilot.set_sticks(s);
        break;
      }
    }
    if (phase != Phase::manoeuvre && t > kPreflightLimit) {
      static const char* const kPhaseNames[] = {"power up", "calibration", "arming", "take-off", "settling"};
      result.error = std::string("preflight did not finish: stuck in ") + kPhaseNames[static_cast<int>(phase)] +
                     " (mode " + mode_name(mode) + ")";
      break;
    }
    pilot.step();

    // ---- the record (from the manoeuvre on) ----
    if (t0 >= 0) {
      const sim::PlantState& s = plant.state();
      const sim::Euler e = sim::to_euler(s.attitude);
      const auto& chain = qr->firmware.chain();
      const double roll_est = chain.roll_e4() * 1e-4 * kDeg, pitch_est = chain.pitch_e4() * 1e-4 * kDeg;
      const double roll_sp = chain.roll_setpoint_e4() * 1e-4 * kDeg;
      const double pitch_sp = chain.pitch_setpoint_e4() * 1e-4 * kDeg;
      const double roll = e.roll * kDeg, pitch = e.pitch * kDeg;
      rec.roll_est.push_back({t, roll_est});
      rec.pitch_est.push_back({t, pitch_est});
      rec.roll_true.push_back({t, roll});
      rec.pitch_true.push_back({t, pitch});
      rec.roll_sp.push_back({t, roll_sp});
      rec.pitch_sp.push_back({t, pitch_sp});
      rec.r_true.push_back({t, s.rate.z});
      const sim::Vec3 body_down = sim::rotate(s.attitude, {0, 0, 1});
      rec.tilt.push_back({t, std::acos(std::clamp(body_down.z, -1.0, 1.0)) * kDeg});
      if (mode == static_cast<uint8_t>(wire::Mode::full_control)) {
        const double er = roll - roll_sp, ep = pitch - pitch_sp;
        rec.att_err.push_back({t, std::sqrt((er * er + ep * ep) / 2)});
        const double xr = roll_est - roll, xp = pitch_est - pitch;
        rec.est_err.push_back({t, std::sqrt((xr * xr + xp * xp) / 2)});
        const qr::EngineCommand& eng = qr->board.engines();
        bool at_limit = false;
        for (uint16_t v : eng.value) at_limit = at_limit || v >= 1000 || v <= idle;
        rec.saturated.push_back({t, at_limit ? 100.0 : 0.0});
      }
      if (mode == static_cast<uint8_t>(wire::Mode::panic) && !entered_panic) {
        entered_panic = true;
        panic_at = t;
      }
      if (entered_panic && mode == static_cast<uint8_t>(wire::Mode::safe) && std::isnan(safe_at)) safe_at = t;
    }

    if (trace != nullptr) {
      const sim::PlantState& ps = plant.state();
      const sim::Euler e = sim::to_euler(ps.attitude);
      const auto& ch = qr->firmware.chain();
      const qr::EngineCommand& eng = qr->board.engines();
      std::fprintf(trace,
                   "%.3f,%u,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%u,%u,%u,%u,%.3f,%."
                   "3f,%.3f,%.3f,%d,%d,%d\n",
                   t, mode, e.roll * kDeg, e.pitch * kDeg, e.yaw * kDeg, ch.roll_e4() * 1e-4 * kDeg,
                   ch.pitch_e4() * 1e-4 * kDeg, ch.yaw_e4() * 1e-4 * kDeg, ch.roll_setpoint_e4() * 1e-4 * kDeg,
                   ch.pitch_setpoint_e4() * 1e-4 * kDeg, ps.rate.x, ps.rate.y, ps.rate.z, ch.p_e3() * 1e-3,
                   ch.q_e3() * 1e-3, ch.r_e3() * 1e-3, eng.value[0], eng.value[1], eng.value[2], eng.value[3],
                   -ps.position.z, ps.position.x, ps.position.y, plant.battery_volts(), ch.roll_e4(), ch.pitch_e4(),
                   ch.yaw_e4());
    }
    if (t >= t_end) break;
    recording = recording || mode == static_cast<uint8_t>(wire::Mode::calibration);
    if (!qr->tick()) break;  // the firmware stopped
    if (record != nullptr && recording) {
      const qr::SensorSample& in = qr->board.read_sensors();  // what this tick ran on
      const qr::ControlInput& c = qr->firmware.controls();
      std::fprintf(record, "%u,%d,%d,%d,%d,%d,%d,%u,%u,%d,%d,%d,%d\n", qr->board.now_us(), in.gyro[0], in.gyro[1],
                   in.gyro[2], in.accel[0], in.accel[1], in.accel[2], in.battery_mv, c.lift, c.roll, c.pitch, c.yaw,
                   in.pressure_pa);
    }
  }

  if (trace != nullptr) std::fclose(trace);
  if (record != nullptr) std::fclose(record);

  // ---- figures ----
  const double sim_seconds = static_cast<double>(qr->world.now_us()) * 1e-6;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const uint8_t final_mode = static_cast<uint8_t>(qr->firmware.mode());
  result.final_mode = mode_name(final_mode);
  uint16_t engines_max = 0;
  for (uint16_t v : qr->board.engines().value) engines_max = std::max(engines_max, v);

  auto& f = result.figures;
  f.push_back({"sim_seconds", sim_seconds});
  f.push_back({"wall_seconds", wall});
  f.push_back({"speedup", sim_seconds / wall});
  // CPU time of this process: on a machine busy with other work the wall figures understate
  // what the simulator does; this one does not.
  f.push_back({"cpu_seconds", static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC});
  f.push_back({"control_hz", static_cast<double>(qr::kControlHz)});
  f.push_back({"seed", static_cast<double>(options.seed)});
  f.push_back({"att_rms_deg_truth", rms(rec.att_err, t0, t_end)});
  f.push_back({"est_err_rms_deg", rms(rec.est_err, t0, t_end)});
  f.push_back({"max_tilt_deg", peak_abs(rec.tilt, t0, t_end)});
  f.push_back({"att_rms_deg_last_s", rms(rec.att_err, t_end - 1, t_end)});  // how it ended

  StepFigures step;
  if (spec->manoeuvre == Manoeuvre::roll_step || spec->manoeuvre == Manoeuvre::pitch_step) {
    const bool roll = spec->manoeuvre == Manoeuvre::roll_step;
    const Trace& sp = roll ? rec.roll_sp : rec.pitch_sp;
    const Trace& est = roll ? rec.roll_est : rec.pitch_est;
    // The step starts when the firmware's set-point moves (the stick's frame has arrived).
    double t_step = kNotMeasured, target = 0;
    for (const Sample& s : sp) {
      if (std::abs(s.value) > 0.5 * spec->amount) {
        t_step = s.t;
        target = s.value;
        break;
      }
    }
    if (!std::isnan(t_step)) {
      Trace held;
      for (const Sample& s : est) {
        if (s.t <= t0 + spec->hold_s) held.push_back(s);
      }
      step = step_response(held, t_step, mean(est, t0, t_step), target, 1.0);
      f.push_back({"step_setpoint_deg", target});
      f.push_back({"step_delay_s", t_step - t0});
    }
  }
  f.push_back({"rise_s", step.rise_s});
  f.push_back({"overshoot_pct", step.overshoot_pct});
  f.push_back({"settle_s", step.settle_s});

  if (spec->manoeuvre == Manoeuvre::yaw_rate_step && t0 >= 0) {
    // Steady state over the last 40 % of the window, on the truth, against the pilot's set-point
    // (the yaw loop's integral holds it there against the rotor drag's yaw damping). Beside it,
    // what the P term alone would settle at, where its moment balances that damping:
    //   yaw_p (r_sp - r) k_m w_max^2 / 1000 = c_rd l^2 (sum of rotor speeds) r
    // (thrust units: w_i = e_i^2 / 1000, so a thrust unit is k_m w_max^2 / 1000 of yaw torque,
    // engine_mixer.hpp; w_max = speed per volt x battery volts).
    yaw_steady_from = t0 + 0.6 * seconds;
    const double r = mean(rec.r_true, yaw_steady_from, t_end);
    const double r_sp = qr->firmware.chain().yaw_rate_setpoint_e3() * 1e-3;
    const sim::VehicleParams& v = plant.vehicle();
    const double w_max = v.speed_per_volt() * plant.battery_volts();
    double speeds = 0;
    for (double w : plant.state().rotor_speed) speeds += w;
    const double gain = yaw_p * v.torque_coeff * w_max * w_max / 1000;
    const double damping = v.rotor_drag_coeff * v.arm_m * v.arm_m * speeds;
    f.push_back({"yaw_rate_setpoint_rad_s", r_sp});
    f.push_back({"yaw_rate_rad_s", r});
    f.push_back({"yaw_rate_p_only_rad_s", r_sp * gain / (gain + damping)});
    f.push_back({"yaw_rate_error_pct", std::abs(r / r_sp - 1) * 100});
  }

  if (spec->manoeuvre == Manoeuvre::torque_impulse && t0 >= 0) {
    f.push_back({"peak_error_deg", peak_abs(rec.att_err, t0, t_end) * std::sqrt(2.0)});
    Trace worst;  // the larger of the two axes' errors
    for (size_t i = 0; i < rec.roll_true.size(); ++i) {
      const double er = rec.roll_true[i].value - rec.roll_sp[i].value;
      const double ep = rec.pitch_true[i].value - rec.pitch_sp[i].value;
      worst.push_back({rec.roll_true[i].t, std::max(std::abs(er), std::abs(ep))});
    }
    f.push_back({"recovery_s", recovery_time(worst, t0, 1.0)});
  }

  if (spec->manoeuvre == Manoeuvre::link_loss || spec->manoeuvre == Manoeuvre::panic_request) {
    f.push_back({"entered_panic", entered_panic ? 1.0 : 0.0});
    f.push_back({"panic_after_s", panic_at - t0});
    f.push_back({"safe_after_s", safe_at - t0});
  }

  f.push_back({"engine_saturation_pct", mean(rec.saturated, t0, t_end)});
  f.push_back({"engines_at_end_max", static_cast<double>(engines_max)});
  f.push_back({"deadline_misses", static_cast<double>(qr->scheduler.stats().deadline_misses)});
  f.push_back({"final_mode", static_cast<double>(final_mode)});
  f.push_back({"battery_v_end", plant.battery_volts()});
  f.push_back({"height_m_end", -plant.state().position.z});
  f.push_back({"drift_m_end", std::hypot(plant.state().position.x, plant.state().position.y)});
  f.push_back({"speed_m_s_end", sim::norm(plant.state().velocity)});
  f.push_back({"requests_given_up", static_cast<double>(pilot.view().requests_given_up)});
  f.push_back({"nacks", static_cast<double>(pilot.view().nacks)});

  // ---- judgement ----
  result.pass = result.error.empty();
  for (const Band& band : spec->bands) {
    if (band.figure == nullptr) break;
    const double value = result.figure(band.figure);
    bool ok = false;
    std::string text = band.figure;
    char limit[32];
    if (std::string(band.figure) == "final_mode") {
      std::snprintf(limit, sizeof limit, "%s", mode_name(static_cast<uint8_t>(band.limit)));
    } else {
      std::snprintf(limit, sizeof limit, "%g", band.limit);
    }
    switch (band.compare) {
      case Compare::below:
        ok = value < band.limit;
        text += std::string(" < ") + limit;
        break;
      case Compare::at_most:
        ok = value <= band.limit;
        text += std::string(" <= ") + limit;
        break;
      case Compare::equal:
        ok = value == band.limit;
        text += std::string(" == ") + limit;
        break;
    }
    result.checks.push_back({text, ok});
    result.pass = result.pass && ok;
  }
  return result;
}

}  // namespace qrsim
