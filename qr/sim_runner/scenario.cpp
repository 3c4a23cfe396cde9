// One scenario flight: the vehicle the script describes, the standard preflight, the script's
// timed events, the record of truth and estimate every control period, then the figures and
// the bands (scenario_score.cpp).
#include <qr/sim_runner/scenario.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <common/drivers/mpu6050.hpp>
#include <common/task_names.hpp>
#include <qr/boards/sim/devboard_qr.hpp>
#include <qr/boards/sim/flying_qr.hpp>
#include <qr/host/replay.hpp>
#include <qr/sim_runner/flight_record.hpp>
#include <qr/sim_runner/full_line_console.hpp>
#include <qr/sim_runner/pilot.hpp>
#include <qr/sim_runner/preflight.hpp>
#include <qr/sim_runner/scenario_score.hpp>
#include <qr/sim_runner/sensor_faults.hpp>

namespace qrsim {
namespace {

constexpr double kDeg = 180 / std::numbers::pi;
constexpr double kRad = std::numbers::pi / 180;

// ---- the flight plan ------------------------------------------------------------------------
// What the pilot does before the manoeuvre, one phase after the other: the pre-flight every
// runner flies (preflight.hpp), then take-off and a steady hover. A flight still short of its
// manoeuvre after kPreflightLimit fails with the stage's name as its error.
enum class Phase : uint8_t { preflight, take_off, settle, manoeuvre };

constexpr double kHoverHeight = 1.5;                     // m, centre of mass above the ground
constexpr double kSettleSeconds = 1.5;                   // steady hover before the manoeuvre
constexpr double kPreflightLimit = 20;                   // s
constexpr double kPeriodSeconds = 1.0 / qr::kControlHz;  // the pilot's hands move once a control period

int16_t stick(double value) { return static_cast<int16_t>(std::clamp(std::lround(value), -1000L, 1000L)); }

// What the pilot's hands hold after t0, changed by the script's events.
struct Hands {
  double roll_deg = 0, pitch_deg = 0, yaw_rad_s = 0;
  bool hold_height = true;  // else lift_share of the hover lift, open loop
  double height = kHoverHeight;
  double lift_share = 0;
  bool still = false;  // the lift stick stays at still_lift
  uint16_t still_lift = 0;
  HeightThumb thumb;  // also the preflight's take-off and settle

  uint16_t lift(const sim::Quadrotor& plant) {
    if (still) return still_lift;
    return hold_height ? thumb.lift(plant, height, 1, kPeriodSeconds)
                       : static_cast<uint16_t>(std::clamp(std::lround(lift_share * plant.hover_command()), 0L, 1000L));
  }

  Sticks sticks(const sim::Quadrotor& plant, const wire::ParameterValues& p) {
    // Full control: roll and pitch sticks are angle set-points, full stick max_tilt_mrad; the yaw
    // stick is a rate, full stick max_yaw_rate_rad_s (Q10 rad/s).
    const double per_degree = kRad * 1000 / (p.get(wire::ParamId::max_tilt_mrad) * 1e-3);
    const double max_rate = std::ldexp(p.get(wire::ParamId::max_yaw_rate_rad_s), -10);
    Sticks s;
    s.lift = lift(plant);
    s.roll = stick(roll_deg * per_degree);
    s.pitch = stick(pitch_deg * per_degree);
    s.yaw = stick(yaw_rad_s / max_rate * 1000);
    return s;
  }
};

// The vehicle as flown: the base (the --vehicle file, else the scenario's, else the default),
// the scenario's modifiers, the sweep's draw, and --no-noise last.
sim::VehicleParams vehicle_for(const ScenarioScript& script, const RunOptions& options, VehicleDraw& flown) {
  sim::VehicleParams v = options.vehicle ? *options.vehicle : script.vehicle ? *script.vehicle : sim::default_vehicle();
  const double tau_ratio = v.motor_tau_down_s / v.motor_tau_up_s;
  flown.mass = script.mass_scale * options.draw.mass;
  flown.inertia = script.inertia_scale * options.draw.inertia;
  flown.noise = script.noise_scale * options.draw.noise;
  flown.vibration = script.vibration_scale * options.draw.vibration;
  v.mass_kg *= flown.mass;
  v.inertia_kgm2 = v.inertia_kgm2 * flown.inertia;
  if (!std::isnan(script.motor_tau_ms)) v.motor_tau_up_s = script.motor_tau_ms * 1e-3;
  v.motor_tau_up_s *= options.draw.motor_tau;
  v.motor_tau_down_s = v.motor_tau_up_s * tau_ratio;
  flown.motor_tau = v.motor_tau_up_s * 1e3;  // reported in ms
  if (!std::isnan(script.battery_pct)) v.battery_initial_soc = script.battery_pct / 100;
  if (script.wiring != sim::Wiring{}) v.wiring = script.wiring;
  v.gyro_noise_dps_rthz *= flown.noise;
  v.accel_noise_ug_rthz *= flown.noise;
  v.battery_sense_noise_mv *= flown.noise;
  v.vibration_accel_g = v.vibration_accel_g * flown.vibration;
  v.vibration_gyro_dps = v.vibration_gyro_dps * flown.vibration;
  if (!options.sensor_noise) {
    v.gyro_noise_dps_rthz = v.accel_noise_ug_rthz = 0;
    v.gyro_bias_dps = v.accel_bias_xy_mg = v.accel_bias_z_mg = v.scale_error = 0;
    v.vibration_accel_g = v.vibration_gyro_dps = {};
    v.battery_sense_noise_mv = 0;
    v.baro_noise_pa = v.baro_temp_coeff_pa_per_k = 0;
  }
  return v;
}

// A roll or pitch event beyond full stick: the pilot's stick stops at full (Hands::sticks), so the
// firmware holds max_tilt_mrad, not the angle the file asks for. Said rather than clamped in
// silence; empty when the stick reaches the angle. `uploaded`: the parameters the pilot has
// uploaded so far over the defaults, the max_tilt_mrad in effect.
std::string beyond_full_stick(const Event& e, const wire::ParameterValues& uploaded) {
  if (e.action != Action::roll && e.action != Action::pitch) return {};
  const double full_deg = uploaded.get(wire::ParamId::max_tilt_mrad) * 1e-3 * kDeg;
  if (std::abs(e.value) <= full_deg) return {};
  char text[192];
  std::snprintf(text, sizeof text,
                "at %g s: %s %g deg asks for more than max_tilt_mrad allows (%.3g deg): the set-point is %.3g deg",
                e.at_s, e.action == Action::roll ? "roll" : "pitch", e.value, full_deg,
                std::copysign(full_deg, e.value));
  return text;
}

// The pushes (torque, force events) acting at `since`, summed.
void apply_pushes(const ScenarioScript& script, double since, sim::Quadrotor& plant) {
  sim::Vec3 torque, force;
  for (const Event& e : script.events) {
    if (since < e.at_s || since >= e.at_s + e.duration_s) continue;
    if (e.action == Action::torque) torque += e.vector;
    if (e.action == Action::force) force += e.vector;
  }
  plant.set_disturbance(torque, force);
}

void apply(const Event& e, Hands& hands, Pilot& pilot, FullLineConsole* console, sim::Quadrotor& plant) {
  switch (e.action) {
    case Action::roll: hands.roll_deg = e.value; break;
    case Action::pitch: hands.pitch_deg = e.value; break;
    case Action::yaw: hands.yaw_rad_s = e.value; break;
    case Action::lift_still:
      hands.still_lift = hands.lift(plant);
      hands.still = true;
      break;
    case Action::lift_hold:
      hands.still = false;
      hands.hold_height = true;
      hands.height = kHoverHeight;
      break;
    case Action::lift_height:
      hands.still = false;
      hands.hold_height = true;
      hands.height = e.value;
      break;
    case Action::lift_share:
      hands.still = false;
      hands.hold_height = false;
      hands.lift_share = e.value;
      break;
    case Action::mode: pilot.request_mode(e.mode); break;
    case Action::param: pilot.set_parameter(e.param, e.raw); break;
    case Action::torque:
    case Action::force: break;  // apply_pushes, every tick while they last
    case Action::turn: break;   // the flight's loop starts it, to report a refusal
    case Action::wind: plant.set_wind(e.vector); break;
    case Action::link:
      pilot.go_silent(e.value == 0);
      if (console != nullptr) console->go_silent(e.value == 0);
      break;
    case Action::console:
      if (console != nullptr) console->set_full(e.value != 0);
      break;
    case Action::log_start: pilot.request(wire::LogStart{}); break;
    case Action::log_stop: pilot.request(wire::LogStop{}); break;
    case Action::download:
      pilot.request(wire::LogDownload{0, e.value == 0 ? wire::LogKind::sensor : wire::LogKind::telemetry, 0, 0});
      break;
    case Action::nack:
    case Action::sda_stuck:
    case Action::imu_identity:
    case Action::prom_bad:
    case Action::baro_slow:
    case Action::fifo_overflow:
    case Action::imu_self_test: break;  // on the board: inject_sensor_fault, apply_chip_faults
  }
}

void write_trace_header(FILE* trace) {
  std::fprintf(trace,
               "t_s,mode,roll_deg,pitch_deg,yaw_deg,roll_est_deg,pitch_est_deg,yaw_est_deg,roll_sp_deg,pitch_sp_deg,"
               "p_rad_s,q_rad_s,r_rad_s,p_est_rad_s,q_est_rad_s,r_est_rad_s,engine0,engine1,engine2,engine3,"
               "height_m,north_m,east_m,battery_v,roll_est_e4,pitch_est_e4,yaw_est_e4,flying,height_est_m,"
               "climb_est_m_s,ground_clearance_m\n");
}

// The devboard's frames carry no yaw estimate, estimated rates or height estimate
// (FirmwareView::has_rates): its trace leaves those columns empty.
void write_trace_line(FILE* trace, double t, uint8_t mode, FlyingQr& qr) {
  const sim::Quadrotor& plant = qr.world().plant();
  const sim::PlantState& ps = plant.state();
  const sim::Euler e = sim::to_euler(ps.attitude);
  const FirmwareView ch = qr.view();
  const qr::EngineCommand& eng = qr.board().engines();
  char yaw[16] = "", p[16] = "", q[16] = "", r[16] = "", yaw_e4[16] = "", flying[4] = "", height[16] = "",
       climb[16] = "";
  if (ch.has_rates) {
    std::snprintf(yaw, sizeof yaw, "%.4f", ch.yaw_e4 * 1e-4 * kDeg);
    std::snprintf(p, sizeof p, "%.4f", ch.p_e3 * 1e-3);
    std::snprintf(q, sizeof q, "%.4f", ch.q_e3 * 1e-3);
    std::snprintf(r, sizeof r, "%.4f", ch.r_e3 * 1e-3);
    std::snprintf(yaw_e4, sizeof yaw_e4, "%d", ch.yaw_e4);
    std::snprintf(height, sizeof height, "%.3f", ch.height_mm * 1e-3);
    std::snprintf(climb, sizeof climb, "%.3f", ch.climb_mm_s * 1e-3);
  }
  std::snprintf(flying, sizeof flying, "%d", ch.flying ? 1 : 0);
  std::fprintf(trace,
               "%.3f,%u,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%s,%s,%u,%u,%u,%u,%.3f,%."
               "3f,%.3f,%.3f,%d,%d,%s,%s,%s,%s,%.3f\n",
               t, mode, e.roll * kDeg, e.pitch * kDeg, e.yaw * kDeg, ch.roll_e4 * 1e-4 * kDeg,
               ch.pitch_e4 * 1e-4 * kDeg, yaw, ch.roll_setpoint_e4 * 1e-4 * kDeg, ch.pitch_setpoint_e4 * 1e-4 * kDeg,
               ps.rate.x, ps.rate.y, ps.rate.z, p, q, r, eng.value[0], eng.value[1], eng.value[2], eng.value[3],
               -ps.position.z, ps.position.x, ps.position.y, plant.battery_volts(), ch.roll_e4, ch.pitch_e4, yaw_e4,
               flying, height, climb, -plant.deepest_contact());
}

// The firmware's flying/landed verdict against the truth (docs/simulator.md section 6.5).
void record_belief(FlightRecord& rec, double t, uint8_t mode, const FirmwareView& qr, const sim::Quadrotor& plant,
                   bool was_in_air, bool in_air) {
  if (!was_in_air && in_air && std::isnan(rec.left_ground_at)) rec.left_ground_at = t;
  if (!std::isnan(rec.left_ground_at) && qr.flying && std::isnan(rec.flying_seen_at)) rec.flying_seen_at = t;
  if (rec.belief_seen && !rec.believed_flying && qr.flying && !in_air) {
    // Thrust below the weight: the rotors' mean square speed below the hover speed's square.
    double squares = 0;
    for (double w : plant.state().rotor_speed) squares += w * w / 4;
    const double hover = plant.vehicle().hover_speed();
    if (squares < hover * hover) ++rec.false_takeoffs;
  }
  // A landing declared while the engines still had lift to give (not the pilot's stick put down;
  // a landing's touchdown ends its panic in the same tick, so last tick's mode says who flew).
  const bool pilot_stopped = qr.controls.lift == 0 && rec.belief_mode != static_cast<uint8_t>(wire::Mode::panic) &&
                             rec.belief_mode != static_cast<uint8_t>(wire::Mode::height_hold);
  if (rec.belief_seen && rec.believed_flying && !qr.flying && !pilot_stopped) {
    const double clearance = std::max(0.0, -plant.deepest_contact());
    rec.declared_clearance = std::isnan(rec.declared_clearance) ? clearance
                                                                : std::max(rec.declared_clearance, clearance);
  }
  rec.belief_seen = true;
  rec.believed_flying = qr.flying;
  rec.belief_mode = mode;
}

// The modes whose attitude loops fly the pilot's roll and pitch set-points: full control and
// height hold (which holds the height with the lift and flies the attitude as full control does).
// Not a panic's descent, which levels the vehicle by its own set-points, nor yaw control.
bool attitude_loops_fly(uint8_t mode) {
  return mode == static_cast<uint8_t>(wire::Mode::full_control) ||
         mode == static_cast<uint8_t>(wire::Mode::height_hold);
}

// One control period of the record, from t0 on.
void record_tick(FlightRecord& rec, double t, uint8_t mode, FlyingQr& qr, uint16_t idle, bool& airborne,
                 double& last_down_speed) {
  const sim::Quadrotor& plant = qr.world().plant();
  const sim::PlantState& s = plant.state();
  const sim::Euler e = sim::to_euler(s.attitude);
  const FirmwareView chain = qr.view();
  const double roll_est = chain.roll_e4 * 1e-4 * kDeg, pitch_est = chain.pitch_e4 * 1e-4 * kDeg;
  const double roll_sp = chain.roll_setpoint_e4 * 1e-4 * kDeg;
  const double pitch_sp = chain.pitch_setpoint_e4 * 1e-4 * kDeg;
  const double roll = e.roll * kDeg, pitch = e.pitch * kDeg;
  rec.roll_est.push_back({t, roll_est});
  rec.pitch_est.push_back({t, pitch_est});
  rec.roll_true.push_back({t, roll});
  rec.pitch_true.push_back({t, pitch});
  rec.roll_sp.push_back({t, roll_sp});
  rec.pitch_sp.push_back({t, pitch_sp});
  rec.r_true.push_back({t, s.rate.z});
  const sim::Vec3 body_down = sim::rotate(s.attitude, {0, 0, 1});
  // A tilt the hand turns the vehicle through (a gyro scale measurement) is not a tilt it flew.
  if (!qr.world().held()) rec.tilt.push_back({t, std::acos(std::clamp(body_down.z, -1.0, 1.0)) * kDeg});
  const double er = roll - roll_sp, ep = pitch - pitch_sp;
  rec.worst_err.push_back({t, std::max(std::abs(er), std::abs(ep))});
  if (attitude_loops_fly(mode)) {
    rec.att_err.push_back({t, std::sqrt((er * er + ep * ep) / 2)});
    rec.axis_err.push_back({t, std::max(std::abs(er), std::abs(ep))});
    const double xr = roll_est - roll, xp = pitch_est - pitch;
    rec.est_err.push_back({t, std::sqrt((xr * xr + xp * xp) / 2)});
    rec.est_err_axis.push_back({t, std::max(std::abs(xr), std::abs(xp))});
  }
  const double rested = plant.battery().open_circuit_volts();
  if (mode == static_cast<uint8_t>(wire::Mode::panic) && !rec.entered_panic) {
    rec.entered_panic = true;
    rec.panic_at = t;
    rec.rested_v_at_panic = rested;
  }
  if (rec.entered_panic && mode == static_cast<uint8_t>(wire::Mode::safe) && std::isnan(rec.safe_at)) rec.safe_at = t;
  rec.battery_v_min = std::isnan(rec.battery_v_min) ? plant.battery_volts()
                                                    : std::min(rec.battery_v_min, plant.battery_volts());
  rec.rested_v_min = std::isnan(rec.rested_v_min) ? rested : std::min(rec.rested_v_min, rested);
  // Touchdown: the first tick with a contact point on the ground after one with none. The speed
  // is the last airborne tick's (at most one control period, 0.01 m/s of free fall, earlier):
  // the contact's damper stops the vehicle within a millisecond.
  // A vehicle in a hand (a turn event) is neither flying nor landing when it is set down.
  const bool in_air = plant.deepest_contact() < 0 && !qr.world().held();
  record_belief(rec, t, mode, chain, plant, airborne, in_air);
  // Saturation is a flying vehicle's: on the ground, armed with the lift stick down, every engine
  // sits at or below idle by design, and that is no engine out of authority.
  if (in_air && mode == static_cast<uint8_t>(wire::Mode::full_control)) {
    bool at_limit = false;
    for (uint16_t v : qr.board().engines().value) at_limit = at_limit || v >= 1000 || v <= idle;
    rec.saturated.push_back({t, at_limit ? 100.0 : 0.0});
  }
  if (airborne && !in_air && std::isnan(rec.touchdown_speed)) {
    rec.touchdown_speed = last_down_speed;
    rec.touchdown_at = t;
  }
  airborne = in_air;
  bool engines_still = true;
  for (uint16_t v : qr.board().engines().value) engines_still = engines_still && v == 0;
  if (!std::isnan(rec.touchdown_at) && engines_still && std::isnan(rec.engines_stopped_at)) rec.engines_stopped_at = t;
  if (rec.entered_panic && engines_still && std::isnan(rec.panic_engines_zero_at)) rec.panic_engines_zero_at = t;
  rec.max_clearance = std::max(rec.max_clearance, -plant.deepest_contact());
  // Height hold: the true height against the one at entry, and how long a lift change took to end it.
  const bool holding = mode == static_cast<uint8_t>(wire::Mode::height_hold);
  if (holding && std::isnan(rec.hold_entry_height)) rec.hold_entry_height = -s.position.z;
  if (holding) rec.hold_height_err.push_back({t, -s.position.z - rec.hold_entry_height});
  const uint16_t lift_read = chain.controls.lift;
  if (holding && rec.hold_lift < 0) rec.hold_lift = lift_read;
  if (rec.hold_lift >= 0 && std::isnan(rec.hold_lift_changed_at) && lift_read != rec.hold_lift) {
    rec.hold_lift_changed_at = t;
  }
  if (!std::isnan(rec.hold_entry_height) && !holding && std::isnan(rec.hold_left_at)) rec.hold_left_at = t;
  last_down_speed = std::abs(s.velocity.z);
}

// The cause of the first panic the firmware announced on its debug text from `from` on ("mode:
// panic (battery low)", Flight::announce_mode): the record cannot see the safety machine's state
// on the devboard's binary, but both builds say why they panic, and the pilot hears it.
std::string first_panic_cause(const std::string& text, size_t from) {
  const std::string said = std::string("mode: ") + wire::mode_name(wire::Mode::panic) + " (";
  const size_t at = text.find(said, from);
  if (at == std::string::npos) return {};
  const size_t begin = at + said.size();
  const size_t end = text.find(')', begin);
  return end == std::string::npos ? std::string() : text.substr(begin, end - begin);
}

// What the QR told the pilot of its sensors: its fault lines (sensor_fault_report.hpp), whether
// the first panic was the IMU lost (docs/safety.md rule 20), the last refusal's reason.
void add_sensor_report_figures(const ConsoleView& view, const FlightRecord& rec, std::vector<Figure>& f) {
  double lines = 0;
  for (const char* prefix : {"imu fault: ", "barometer fault: "}) {
    for (size_t at = view.debug_text.find(prefix); at != std::string::npos; at = view.debug_text.find(prefix, at + 1)) {
      ++lines;
    }
  }
  f.push_back({"sensor_fault_lines", lines});
  // Those naming the IMU's self-test (the driver's verdict at power-up, common/drivers/mpu6050.hpp).
  const std::string self_test = std::string("imu fault: ") +
                                drivers::kMpu6050FaultNames[static_cast<size_t>(drivers::Mpu6050Fault::self_test)];
  double self_test_lines = 0;
  for (size_t at = view.debug_text.find(self_test); at != std::string::npos;
       at = view.debug_text.find(self_test, at + 1)) {
    ++self_test_lines;
  }
  f.push_back({"self_test_fault_lines", self_test_lines});
  const char* lost = qr::kPanicCauseNames[static_cast<uint8_t>(qr::PanicCause::imu_lost)];
  f.push_back({"imu_lost_panic", rec.entered_panic && rec.panic_cause == lost ? 1.0 : 0.0});
  f.push_back({"last_nack_reason", static_cast<double>(view.last_nack)});
  // The sign check (docs/safety.md rule 21): its cut, and a calibration the QR would not take.
  const char* wrong = qr::kPanicCauseNames[static_cast<uint8_t>(qr::PanicCause::wrong_sign)];
  f.push_back({"wrong_sign_panic", rec.entered_panic && rec.panic_cause.rfind(wrong, 0) == 0 ? 1.0 : 0.0});
  f.push_back({"calibration_refused", view.debug_text.find("calibration refused") != std::string::npos ? 1.0 : 0.0});
}

// The binary's own cost in this flight, from the scheduler's statistics the board reported (RV32
// instructions, exact under QEMU's -icount): the tick, then each task that ran.
void add_instruction_figures(const DevboardQr& devboard, std::vector<Figure>& f) {
  const std::vector<InstructionStats>& rows = devboard.instructions();
  const auto add = [&](const std::string& name, const InstructionStats& s) {
    f.push_back({"instr_" + name + "_mean", s.reported ? s.mean() : kNotMeasured});
    f.push_back({"instr_" + name + "_max", s.reported ? static_cast<double>(s.max) : kNotMeasured});
  };
  add("tick", rows.back());
  for (uint8_t task = 0; task + 1u < rows.size(); ++task) {
    if (rows[task].runs > 0) add(wire::task_name(task), rows[task]);
  }
  f.push_back({"ground_bytes_refused", static_cast<double>(devboard.ground_bytes_refused())});
  if (devboard.core_mhz() != 0) f.push_back({"core_mhz", static_cast<double>(devboard.core_mhz())});
}

// The files a flight writes as it flies (--trace, --record), closed when it ends.
struct FileCloser {
  void operator()(FILE* file) const { std::fclose(file); }
};
using OutputFile = std::unique_ptr<FILE, FileCloser>;

OutputFile open_output(const std::string& path) {
  return OutputFile(path.empty() ? nullptr : std::fopen(path.c_str(), "w"));
}

// The host build of the firmware, or the devboard's binary when the options name one.
std::unique_ptr<FlyingQr> make_flying_qr(const sim::VehicleParams& vehicle, const RunOptions& options) {
  if (options.devboard_elf.empty()) return std::make_unique<HostQr>(vehicle, sim::WorldConfig{.seed = options.seed});
  return std::make_unique<DevboardQr>(vehicle, sim::WorldConfig{.seed = options.seed}, options.devboard_elf,
                                      options.devboard_core_mhz);
}

// The scenario's pre-flight: the scenario's parameters then --param's go up; a "start: safe"
// flight stays on the ground unarmed, its script arming what it flies.
PreflightPlan preflight_plan(const ScenarioScript& script, const RunOptions& options) {
  PreflightPlan plan;
  plan.parameters = script.parameters;
  plan.parameters.insert(plan.parameters.end(), options.parameters.begin(), options.parameters.end());
  plan.radio = options.radio;
  plan.arm = script.start != Start::safe;
  return plan;
}

// What only the flight's end knows: the battery panic level, the yaw-rate set-point, and where
// the yaw loop's P term alone would settle, its moment balancing the rotor drag's yaw damping:
//  yaw_p (r_sp - r) k_m w_max^2 / 1000 = c_rd l^2 (sum of rotor speeds) r
// (thrust units: w_i = e_i^2 / 1000, so a thrust unit is k_m w_max^2 / 1000 of yaw torque,
// engine_mixer.hpp; w_max = speed per volt x battery volts).
EndState end_state(FlyingQr& qr) {
  const sim::Quadrotor& plant = qr.world().plant();
  EndState end;
  end.battery_panic_volts = qr.parameters().get(wire::ParamId::battery_panic_mv) * 1e-3;
  end.yaw_rate_setpoint = qr.view().yaw_rate_setpoint_e3 * 1e-3;
  const double yaw_p = qr.parameters().get(wire::ParamId::yaw_p) / 16.0;
  const sim::VehicleParams& v = plant.vehicle();
  const double w_max = v.speed_per_volt() * plant.battery_volts();
  double speeds = 0;
  for (double w : plant.state().rotor_speed) speeds += w;
  const double gain = yaw_p * v.torque_coeff * w_max * w_max / 1000;
  const double damping = v.rotor_drag_coeff * v.arm_m * v.arm_m * speeds;
  end.yaw_rate_p_only = end.yaw_rate_setpoint * gain / (gain + damping);
  return end;
}

// The firmware divides each gyro axis by 1 + ppm 1e-6 (qr/core/chain/sensor_units.hpp); what is
// left of the IMU's drawn factor is the error it flies with, the worst axis's.
double gyro_scale_error_ppm(FlyingQr& qr) {
  constexpr wire::ParamId kScale[3] = {wire::ParamId::gyro_scale_x_ppm, wire::ParamId::gyro_scale_y_ppm,
                                       wire::ParamId::gyro_scale_z_ppm};
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    const double corrected = 1 + qr.parameters().get(kScale[i]) * 1e-6;
    worst = std::max(worst, std::abs(qr.world().imu().gyro_scale()[i] / corrected - 1) * 1e6);
  }
  return worst;
}

// --sensors drivers: how the drivers read the chips over the board's bus (null when direct).
double i2c_busy_pct(FlyingQr& qr, double sim_s) {
  return sim_s > 0 ? 100.0 * 1e-9 * static_cast<double>(qr.board().i2c().busy_ns()) / sim_s : 0;
}

// Where the drivers run: the host build's stage, or the devboard's counts over its sensor link
// (its stage's time on this host is not the board's: null there).
void add_sensor_figures(FlyingQr& qr, double sim_s, std::vector<Figure>& f) {
  const std::optional<qr::SensorCounts> counts = qr.sensor_counts();
  const qr::SensorStage<SimBoard>* stage = qr.sensor_stage();
  const auto count = [&](qr::SensorCounts::Count c) {
    return counts ? static_cast<double>(counts->value[c]) : kNotMeasured;
  };
  const auto healthy = [&](uint8_t bit) { return counts ? ((counts->healthy & bit) != 0 ? 1.0 : 0.0) : kNotMeasured; };
  using C = qr::SensorCounts;
  f.push_back({"imu_samples", count(C::imu_samples)});
  f.push_back({"imu_faults", count(C::imu_faults)});
  f.push_back({"baro_readings", count(C::baro_readings)});
  f.push_back({"baro_faults", count(C::baro_faults)});
  f.push_back({"i2c_busy_pct", counts ? i2c_busy_pct(qr, sim_s) : kNotMeasured});
  f.push_back(
      {"sensor_stage_ns_mean", counts && stage != nullptr ? static_cast<double>(stage->stats().mean()) : kNotMeasured});
  f.push_back({"imu_lost", count(C::imu_lost)});
  f.push_back({"baro_adc_zero", count(C::baro_adc_zero)});
  f.push_back({"imu_healthy_at_end", healthy(C::kImuHealthy)});
  f.push_back({"baro_healthy_at_end", healthy(C::kBarometerHealthy)});
}

// The ESCs' side (frames taken, frames dropped for their check) and the front engine's speed as
// the QR last reported it from the ESC's answer, beside the truth. Special command frames (the
// lost-model beacon, docs/safety.md rule 18), and those that came while an ESC's motor ran (none
// may).
void add_esc_figures(FlyingQr& qr, const ConsoleView& heard, std::vector<Figure>& f) {
  uint64_t accepted = 0, rejected = 0, commands = 0, commands_turning = 0;
  for (const SimEsc& esc : qr.board().escs()) {
    accepted += esc.accepted();
    rejected += esc.rejected();
    commands += esc.commands();
    commands_turning += esc.commands_while_turning();
  }
  f.push_back({"esc_frames", static_cast<double>(accepted)});
  f.push_back({"esc_frames_rejected", static_cast<double>(rejected)});
  f.push_back({"esc_commands", static_cast<double>(commands)});
  f.push_back({"esc_commands_while_turning", static_cast<double>(commands_turning)});
  f.push_back({"rpm_front_reported", static_cast<double>(heard.rpm[0])});
  f.push_back({"rpm_front_truth", std::abs(qr.world().plant().state().rotor_speed[0]) * 60.0 / (2.0 * M_PI)});
}

// When the run began, on the wall and on this process's CPU, for its speed figures.
struct RunClock {
  std::chrono::steady_clock::time_point wall_start = std::chrono::steady_clock::now();
  std::clock_t cpu_start = std::clock();
};

// What the run cost and on what it flew: simulated, wall and CPU time, the rate, the seed and
// the vehicle's draw.
void add_run_figures(const RunClock& clock, FlyingQr& qr, const RunOptions& options, const VehicleDraw& flown,
                     std::vector<Figure>& f) {
  const double sim_seconds = static_cast<double>(qr.world().now_us()) * 1e-6;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock.wall_start).count();
  f.push_back({"sim_seconds", sim_seconds});
  f.push_back({"wall_seconds", wall});
  f.push_back({"speedup", sim_seconds / wall});
  // CPU time of this process: on a machine busy with other work the wall figures understate
  // what the simulator does; this one does not.
  const double cpu = static_cast<double>(std::clock() - clock.cpu_start) / CLOCKS_PER_SEC;
  f.push_back({"cpu_seconds", cpu});
  f.push_back({"speedup_cpu", cpu > 0 ? sim_seconds / cpu : kNotMeasured});
  f.push_back({"control_hz", static_cast<double>(qr::kControlHz)});
  f.push_back({"seed", static_cast<double>(options.seed)});
  f.push_back({"mass_scale", flown.mass});
  f.push_back({"inertia_scale", flown.inertia});
  f.push_back({"motor_tau_ms", flown.motor_tau});
  f.push_back({"noise_scale", flown.noise});
  f.push_back({"vibration_scale", flown.vibration});
}

// One scenario flight as it flies: the QR and its pilot, where the pilot is in the flight plan
// and what its hands hold, the script's next event, the record, and the files it writes.
class ScenarioFlight {
 public:
  ScenarioFlight(const ScenarioScript& script, const RunOptions& options, FlyingQr& qr, ScenarioResult& result);

  // Control period after control period until the scored window ends, the firmware stops or the
  // flight fails (result.error).
  void fly();
  // The figures of the flight, after the run's own (add_run_figures), and the final mode.
  void add_figures();

 private:
  bool fly_plan(double t);  // false: the flight ends (its error said)
  void enter(Phase next, double t);
  void begin_manoeuvre(double t);
  bool play_events(double t);
  bool preflight_overdue(double t, uint8_t mode);
  void write_replay_input();
  void add_end_figures(std::vector<Figure>& f);

  const ScenarioScript& script_;
  const RunOptions& options_;
  FlyingQr& qr_;
  sim::Quadrotor& plant_;
  ScenarioResult& result_;
  const double seconds_;  // the scored window
  Pilot pilot_;
  std::unique_ptr<FullLineConsole> console_;
  Preflight preflight_;
  Phase phase_ = Phase::preflight;
  double phase_start_ = 0;
  Hands hands_;
  size_t next_event_ = 0;
  FlightRecord rec_;
  bool airborne_ = false;
  double last_down_speed_ = 0;
  size_t text_at_t0_ = 0;  // how much debug text the pilot had heard at t0
  OutputFile record_;
  bool recording_ = false;  // from the first calibration tick on
  OutputFile trace_;
  const uint16_t idle_;  // the firmware's default idle level, for the record's saturation
  // The parameters as the pilot uploads them, over the defaults: the scenario's, --param, then the
  // param events as they come (for the notes on what a stick event can ask for).
  wire::ParameterValues uploaded_;
};

ScenarioFlight::ScenarioFlight(const ScenarioScript& script, const RunOptions& options, FlyingQr& qr,
                               ScenarioResult& result)
    : script_(script), options_(options), qr_(qr), plant_(qr.world().plant()), result_(result),
      seconds_(options.seconds > 0 ? options.seconds : script.seconds), pilot_(qr.board()),
      preflight_(preflight_plan(script, options)), record_(open_output(options.record_path)),
      trace_(open_output(options.trace_path)),
      idle_(static_cast<uint16_t>(qr.parameters().get(wire::ParamId::idle_level))) {
  // Only a script that asks for it pays for the console's watch over every byte of the line.
  for (const Event& e : script.events) {
    if (e.action == Action::console && console_ == nullptr)
      console_ = std::make_unique<FullLineConsole>(qr.board(), pilot_);
  }
  rec_.t_end = 1e9;
  if (record_ != nullptr) std::fprintf(record_.get(), "%s\n", qr::host::replay_input_header().c_str());
  if (trace_ != nullptr) write_trace_header(trace_.get());
  for (const auto& [id, raw] : script.parameters) uploaded_.set(static_cast<uint8_t>(id), raw);
  for (const auto& [id, raw] : options.parameters) uploaded_.set(static_cast<uint8_t>(id), raw);
  apply_power_up_faults(script, qr.board());  // before the first tick: the chip is powered with them
}

void ScenarioFlight::fly() {
  for (;;) {
    const double t = static_cast<double>(qr_.world().now_us()) * 1e-6;
    const uint8_t mode = qr_.view().mode;
    if (!fly_plan(t)) break;
    if (phase_ == Phase::manoeuvre && !play_events(t)) break;
    if (preflight_overdue(t, mode)) break;
    pilot_.step();
    if (console_ != nullptr) console_->step();

    if (rec_.t0 >= 0) record_tick(rec_, t, mode, qr_, idle_, airborne_, last_down_speed_);
    if (trace_ != nullptr) write_trace_line(trace_.get(), t, mode, qr_);
    if (options_.on_tick) options_.on_tick(t, qr_.view());
    if (t >= rec_.t_end) break;
    recording_ = recording_ || mode == static_cast<uint8_t>(wire::Mode::calibration);
    if (!qr_.tick()) break;  // the firmware stopped
    if (record_ != nullptr && recording_) write_replay_input();
  }
  record_.reset();
  trace_.reset();
  if (!qr_.error().empty() && result_.error.empty()) result_.error = "devboard: " + qr_.error();
  if (rec_.entered_panic) rec_.panic_cause = first_panic_cause(pilot_.view().debug_text, text_at_t0_);
}

// The pilot before the manoeuvre: the pre-flight, then off the ground to the hover height and a
// steady hover, or straight to the manoeuvre on the ground, lift stick down, for a flight that
// starts there (armed or not).
bool ScenarioFlight::fly_plan(double t) {
  switch (phase_) {
    case Phase::preflight:
      // A scenario that starts in safe goes on without a calibration (its bands judge the
      // refusal); any other needs one, and the flight ends with that error.
      if (preflight_.refused()) {
        if (script_.start != Start::safe) {
          result_.error = "the QR refused the calibration (its debug text says why)";
          return false;
        }
        hands_.hold_height = false;
        begin_manoeuvre(t);
        break;
      }
      if (!preflight_.step(t, pilot_.view().mode, pilot_)) break;
      if (script_.start == Start::hover) {
        enter(Phase::take_off, t);
      } else {
        hands_.hold_height = false;
        begin_manoeuvre(t);
      }
      break;
    case Phase::take_off: {
      pilot_.set_sticks({hands_.thumb.lift(plant_, kHoverHeight, (t - phase_start_) / 1.0, kPeriodSeconds), 0, 0, 0});
      const sim::PlantState& s = plant_.state();
      if (std::abs(-s.position.z - kHoverHeight) < 0.1 && std::abs(s.velocity.z) < 0.1) enter(Phase::settle, t);
      break;
    }
    case Phase::settle:
      pilot_.set_sticks({hands_.thumb.lift(plant_, kHoverHeight, 1, kPeriodSeconds), 0, 0, 0});
      if (t - phase_start_ >= kSettleSeconds) begin_manoeuvre(t);
      break;
    case Phase::manoeuvre: break;
  }
  return true;
}

void ScenarioFlight::enter(Phase next, double t) {
  phase_ = next;
  phase_start_ = t;
}

// t0: the scored window opens.
void ScenarioFlight::begin_manoeuvre(double t) {
  enter(Phase::manoeuvre, t);
  rec_.t0 = t;
  rec_.t_end = t + seconds_;
  airborne_ = plant_.deepest_contact() < 0;
  text_at_t0_ = pilot_.view().debug_text.size();
}

// The script's events due by now, the pushes acting, and the sticks the hands hold. False when
// a turn was refused: the flight ends with that as its error.
bool ScenarioFlight::play_events(double t) {
  const double since = t - rec_.t0;
  while (next_event_ < script_.events.size() && script_.events[next_event_].at_s <= since + 1e-9) {
    const Event& e = script_.events[next_event_++];
    apply(e, hands_, pilot_, console_.get(), plant_);
    if (e.action == Action::param) uploaded_.set(static_cast<uint8_t>(e.param), e.raw);
    if (std::string note = beyond_full_stick(e, uploaded_); !note.empty()) result_.notes.push_back(std::move(note));
    if (is_sensor_fault(e.action)) {
      if (std::string note = inject_sensor_fault(e, qr_.board(), qr_.world().now_us()); !note.empty()) {
        result_.notes.push_back(std::move(note));
      }
    }
    const std::string refused = e.action == Action::turn ? qr_.world().start_hand_turn(e.turn) : "";
    if (!refused.empty()) {
      result_.error = script_.origin + ":" + std::to_string(e.line) + ": the turn was refused: " + refused;
      return false;
    }
  }
  apply_pushes(script_, since, plant_);
  apply_chip_faults(script_, since, qr_.board());
  pilot_.set_sticks(hands_.sticks(plant_, qr_.parameters()));
  return true;
}

// A flight still short of its manoeuvre after kPreflightLimit fails, naming where it stuck.
bool ScenarioFlight::preflight_overdue(double t, uint8_t mode) {
  if (phase_ == Phase::manoeuvre || t <= kPreflightLimit) return false;
  const char* stuck = phase_ == Phase::preflight  ? preflight_.stage_name()
                      : phase_ == Phase::take_off ? "take-off"
                                                  : "settling";
  result_.error = std::string("preflight did not finish: stuck in ") + stuck + " (mode " + mode_name(mode) + ")";
  return true;
}

// The sensor sample this tick ran on and the sticks it read, a line of the replay's input.
void ScenarioFlight::write_replay_input() {
  const qr::SensorSample in = qr_.sensor_sample();
  const qr::ControlInput c = qr_.view().controls;
  std::fprintf(record_.get(), "%u,%d,%d,%d,%d,%d,%d,%u,%u,%d,%d,%d,%d\n", qr_.board().now_us(), in.gyro[0], in.gyro[1],
               in.gyro[2], in.accel[0], in.accel[1], in.accel[2], in.battery_mv, c.lift, c.roll, c.pitch, c.yaw,
               in.pressure_pa);
}

void ScenarioFlight::add_figures() {
  std::vector<Figure>& f = result_.figures;
  add_flight_figures(script_, rec_, end_state(qr_), f);
  add_end_figures(f);
  if (console_ != nullptr) console_->add_figures(f);
  add_sensor_figures(qr_, static_cast<double>(qr_.world().now_us()) * 1e-6, f);
  if (const auto* devboard = dynamic_cast<const DevboardQr*>(&qr_)) add_instruction_figures(*devboard, f);
  if (options_.dshot) add_esc_figures(qr_, pilot_.view(), f);
  if (options_.radio) f.push_back({"radio_flags", static_cast<double>(pilot_.view().radio_flags)});
}

// How the flight ended: upright or not, the engines, the mode, the battery, where the vehicle
// is and how fast it goes, and what the pilot's requests met.
void ScenarioFlight::add_end_figures(std::vector<Figure>& f) {
  const uint8_t final_mode = qr_.view().mode;
  result_.final_mode = mode_name(final_mode);
  uint16_t engines_max = 0;
  for (uint16_t v : qr_.board().engines().value) engines_max = std::max(engines_max, v);
  const sim::PlantState& s = plant_.state();
  const sim::Vec3 body_down = sim::rotate(s.attitude, {0, 0, 1});
  f.push_back({"final_upright", body_down.z >= std::cos(30 * kRad) ? 1.0 : 0.0});
  f.push_back({"gyro_scale_error_ppm_max", gyro_scale_error_ppm(qr_)});
  f.push_back({"engine_saturation_pct", mean(rec_.saturated, rec_.t0, rec_.t_end)});
  f.push_back({"engines_at_end_max", static_cast<double>(engines_max)});
  f.push_back({"deadline_misses", static_cast<double>(qr_.view().deadline_misses)});
  f.push_back({"final_mode", static_cast<double>(final_mode)});
  f.push_back({"battery_v_end", plant_.battery_volts()});
  f.push_back({"height_m_end", -s.position.z});
  f.push_back({"drift_m_end", std::hypot(s.position.x, s.position.y)});
  f.push_back({"speed_m_s_end", sim::norm(s.velocity)});
  f.push_back({"requests_given_up", static_cast<double>(pilot_.view().requests_given_up)});
  f.push_back({"nacks", static_cast<double>(pilot_.view().nacks)});
  add_sensor_report_figures(pilot_.view(), rec_, f);
}

}  // namespace

double ScenarioResult::figure(const std::string& name) const {
  for (const Figure& f : figures) {
    if (f.name == name) return f.value;
  }
  return kNotMeasured;
}

const char* mode_name(uint8_t mode) { return wire::mode_key(static_cast<wire::Mode>(mode)); }

ScenarioResult run_scenario(const ScenarioScript& script, const RunOptions& options) {
  const RunClock clock;
  ScenarioResult result;
  result.scenario = script.name;
  result.known_failure = script.known_failure;
  result.vehicle = options.vehicle  ? options.vehicle_name
                   : script.vehicle ? script.vehicle_file
                                    : std::string(sim::default_vehicle_name());
  VehicleDraw flown;
  const sim::VehicleParams vehicle = vehicle_for(script, options, flown);
  const std::unique_ptr<FlyingQr> qr = make_flying_qr(vehicle, options);
  result.firmware = qr->firmware();
  if (options.radio && !options.devboard_elf.empty()) {
    result.error = "--rc crsf flies the host firmware only: the devboard's sensor link carries no radio";
    return result;
  }
  if (options.sensor_drivers) qr->board().use_sensor_drivers();
  // The simulated motors have the pole pairs the QR's motor_poles parameter says by default.
  if (options.dshot) qr->board().use_dshot(static_cast<uint8_t>(qr->parameters().get(wire::ParamId::motor_poles) / 2));
  ScenarioFlight flight(script, options, *qr, result);
  flight.fly();
  add_run_figures(clock, *qr, options, flown, result.figures);
  flight.add_figures();
  judge(script, result);
  return result;
}

}  // namespace qrsim
