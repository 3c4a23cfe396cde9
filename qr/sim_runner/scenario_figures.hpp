// Every figure a scenario flight reports, with its meaning: the names a band may judge (a band
// naming anything else is an error in the scenario file) and the figure table of
// docs/simulator.md (ScenarioDocument.* keeps the two equal). A figure that a flight did not
// measure is NaN (null in the JSON), and a band on it fails.
#pragma once

#include <iterator>
#include <string_view>

namespace qrsim {

struct FigureSpec {
  const char* name;
  const char* meaning;
};

inline constexpr FigureSpec kFigureTable[] = {
    {"sim_seconds", "simulated time, preflight included"},
    {"wall_seconds", "wall-clock time of the run"},
    {"speedup", "sim_seconds / wall_seconds"},
    {"cpu_seconds", "CPU time of the process (the fair benchmark on a busy machine)"},
    {"speedup_cpu", "sim_seconds / cpu_seconds (the speed-up a busy machine measures reproducibly)"},
    {"control_hz", "the build's control rate"},
    {"seed", "the seed of every random source"},
    {"mass_scale", "vehicle mass over the vehicle file's (scenario modifier times sweep draw)"},
    {"inertia_scale", "inertia over the vehicle file's"},
    {"motor_tau_ms", "motor spin-up time constant flown"},
    {"noise_scale", "sensor white-noise densities over the vehicle file's"},
    {"vibration_scale", "vibration amplitudes over the vehicle file's"},
    {"att_rms_deg_truth", "RMS over the window of the true attitude minus the set-point, both axes"},
    {"att_rms_deg_last_s", "the same over the window's last second"},
    {"att_err_deg_truth_max_after_settle",
     "largest absolute truth minus set-point of either axis in the held part: from 0.8 s after the "
     "step's set-point moved to the release (a step), or over the whole window (no step)"},
    {"max_tilt_deg_truth", "largest true tilt (body z from vertical) in the window, the hand's turns left out"},
    {"est_err_rms_deg", "RMS of the estimate minus the truth, both axes"},
    {"est_err_max_deg", "largest absolute estimate minus truth of either axis"},
    {"step_setpoint_deg", "the step's set-point as the firmware holds it"},
    {"step_delay_s", "from the stick event to the set-point moving (the link)"},
    {"rise_s", "truth: 10 % to 90 % of the step, first crossings"},
    {"overshoot_pct", "truth: peak beyond the set-point in % of the step"},
    {"settle_s", "truth: from the step until it stays within 1 deg of the set-point to the release"},
    {"rise_s_est", "the same three on the firmware's estimate"},
    {"overshoot_pct_est", "estimate: overshoot"},
    {"settle_s_est", "estimate: settling time"},
    {"release_settle_s",
     "truth: from the stick's return to centre until within 1 deg of level for good, up to the next push, turn or "
     "roll or pitch stick event"},
    {"yaw_rate_setpoint_rad_s", "the firmware's yaw-rate set-point at the end"},
    {"yaw_rate_rad_s", "mean true yaw rate over the last 40 % of the window"},
    {"yaw_rate_p_only_rad_s", "where the yaw loop's P term alone would settle"},
    {"yaw_rate_error_pct", "absolute yaw_rate_rad_s / set-point - 1, in %"},
    {"peak_error_deg", "push: the largest error, both axes combined"},
    {"recovery_s", "push: from its start until the larger axis error stays within 1 deg"},
    {"recovery_2deg_s", "push: the same within 2 deg"},
    {"push_end_recovery_s",
     "push: from its end (at + for) until the larger axis error, truth minus set-point, stays within 1 deg"},
    {"est_recovery_s", "push: from its end until the estimate minus the truth stays within 1 deg on both axes"},
    {"entered_panic", "1 when the firmware entered panic in the window"},
    {"panic_after_s", "when (from t0) it entered panic"},
    {"safe_after_s", "when, after the panic, it entered safe"},
    {"panic_while_rested_above_threshold",
     "1 when it entered a battery panic (the cause it announced) while the battery's resting voltage was above "
     "battery_panic_mv; 0 for another cause or no panic; null when the cause was not heard"},
    {"battery_v_min", "lowest terminal voltage in the window (what the sensor sees)"},
    {"battery_rested_v_min", "lowest resting (open-circuit) voltage in the window"},
    {"touchdown_speed_m_s", "vertical speed at the first ground contact after being airborne in the window"},
    {"engines_stop_s", "from the touchdown until every engine is zero (a landing's end)"},
    {"panic_engines_zero_s",
     "from the first panic until every engine is zero (a cut that stops them at once: one tick); null without a panic"},
    {"cut_after_liftoff_s",
     "from the truth's first leaving the ground in the window to the first tick of a panic with every engine at 0 "
     "(a cut in the air: the sign check's); null without either"},
    {"max_clearance_m_truth", "truth: the highest the lowest foot rose above the ground from t0 (0: never left it)"},
    {"takeoff_seen_s",
     "from the truth's first leaving the ground in the window to the firmware's first flying verdict"},
    {"false_takeoffs",
     "the firmware's landed-to-flying verdicts while the vehicle was on the ground with its thrust below its weight"},
    {"touchdown_declared_clearance_m_max",
     "the largest true height of the lowest point above the ground at a landed verdict made with lift on"},
    {"height_hold_s", "how long height hold held, from its first tick to the pilot's lift change (or the end)"},
    {"height_hold_rms_m", "truth: RMS of the height minus the height at entry while it held"},
    {"height_hold_drift_m", "truth: the height's mean over the hold's last second minus the height at entry"},
    {"height_hold_exit_periods",
     "control periods from the tick the firmware read a changed lift stick to the first tick out of height hold"},
    {"final_upright", "1 when body z is within 30 deg of vertical at the end"},
    {"gyro_scale_error_ppm_max",
     "truth: the gyro's largest per-axis scale error the firmware flies with at the end, its gyro_scale_*_ppm "
     "parameters divided out (ppm)"},
    {"engine_saturation_pct",
     "share of the ticks airborne in full control with an engine at 1000 or at or below idle (on the ground idle "
     "is no saturation); null without such a tick"},
    {"engines_at_end_max", "the largest engine value at the end"},
    {"deadline_misses", "the scheduler's count"},
    {"final_mode", "the mode at the end (a band compares the mode key: safe, panic, full, ...)"},
    {"battery_v_end", "terminal voltage at the end"},
    {"height_m_end", "height of the centre of mass at the end"},
    {"drift_m_end", "horizontal distance from the start"},
    {"speed_m_s_end", "speed at the end"},
    {"requests_given_up", "pilot requests never answered"},
    {"nacks", "pilot requests refused"},
    {"sensor_fault_lines", "debug text lines the QR said about sensor faults (imu fault:, barometer fault:)"},
    {"self_test_fault_lines", "those of them about the IMU's self-test (imu fault: self-test)"},
    {"imu_lost_panic", "1 when the first panic after t0 was the IMU lost, else 0"},
    {"last_nack_reason", "the reason of the last request the QR refused (docs/protocol.md), 0 for none"},
    {"wrong_sign_panic",
     "1 when the first panic after t0 was the sign check's (wrong sign: AXIS, docs/safety.md rule 21), else 0"},
    {"calibration_refused",
     "1 when the QR said it refused a calibration (the accelerometer read gravity off body z), else 0"},
    // With a console event (full_line_console.hpp); null without one.
    {"line_full_s", "seconds the console sent at the line's full rate"},
    {"line_idle_ms", "time the line towards the QR stood idle while the console sent at the full rate"},
    {"line_frames_sent", "frames that went up the line whole, the pilot's and the console's"},
    {"line_frames_uncounted",
     "frames sent that the QR's telemetry_link did not count, at its last report composed while none arrived"},
    {"line_rx_faults", "the QR's last telemetry_link: check failures, unknown types, bytes skipped and overruns"},
    {"line_requests", "the console's requests at the full rate: a mode_change to the mode shown, every 100 ms"},
    {"line_requests_unanswered", "those with no answer by the end, though due by line_answer_bound_ms"},
    {"line_answer_ms_median", "from a request's last byte at the QR to its answer's last byte at the console"},
    {"line_answer_ms_max", "the latest answer, measured the same way"},
    {"line_answer_bound_ms", "two control periods plus the QR's 32-byte transmit buffer and the ack's 5 bytes"},
    {"line_answers_late", "answers later than line_answer_bound_ms"},
    // With the sensors read by the firmware's drivers (qrsim --sensors drivers, the default); null
    // when direct or on the devboard.
    {"imu_samples", "MPU-6050 bursts the driver read good"},
    {"imu_faults", "the MPU-6050 driver's faults, every kind"},
    {"baro_readings", "MS5611 pressures the driver compensated"},
    {"baro_faults", "the MS5611 driver's faults, every kind"},
    {"i2c_busy_pct", "share of the flight's time the I2C wire was busy"},
    {"sensor_stage_ns_mean", "the sensor stage's mean time a tick on this host, ns"},
    {"imu_lost", "times the MPU-6050 driver declared the chip lost (10 failed reads in a row)"},
    {"baro_adc_zero", "MS5611 ADC reads of 0 (read too early) the driver discarded"},
    {"imu_healthy_at_end", "1 when the IMU streams at the end of the flight, else 0"},
    {"baro_healthy_at_end", "1 when the barometer measures at the end of the flight, else 0"},
};

constexpr bool is_figure(std::string_view name) {
  for (const FigureSpec& f : kFigureTable) {
    if (name == f.name) return true;
  }
  return false;
}

}  // namespace qrsim
