// The scenarios: one row each, what the pilot does after take-off and the bands the flight is
// judged by. Bands from issue 6. Every flying scenario must also end where it flew, in full
// control (a tilt panic or a refused mode fails it); the stops must end in safe, engines still.
#include <common/mode.hpp>
#include <qr/boards/sim/scenario.hpp>

namespace qrsim {
namespace {

constexpr double kFull = 5, kSafe = 0;

const std::vector<ScenarioSpec> kScenarios = {
    {"hover",
     "hover with sensor noise and vibration",
     Manoeuvre::none,
     0,
     0,
     30,
     {{"att_rms_deg_truth", Compare::below, 1.0},
      {"engine_saturation_pct", Compare::at_most, 0},
      {"final_mode", Compare::equal, kFull}}},
    {"step-roll",
     "10 deg roll step from hover, held 2 s",
     Manoeuvre::roll_step,
     10,
     2,
     3,
     {{"rise_s", Compare::below, 0.35},
      {"overshoot_pct", Compare::below, 10},
      {"settle_s", Compare::below, 1.0},
      {"final_mode", Compare::equal, kFull}}},
    {"step-pitch",
     "10 deg pitch step from hover, held 2 s",
     Manoeuvre::pitch_step,
     10,
     2,
     3,
     {{"rise_s", Compare::below, 0.35},
      {"overshoot_pct", Compare::below, 10},
      {"settle_s", Compare::below, 1.0},
      {"final_mode", Compare::equal, kFull}}},
    {"full-stick-30",
     "30 deg roll step from hover (full stick at the default max_tilt_mrad), held 2 s",
     Manoeuvre::roll_step,
     30,
     2,
     3,
     {{"rise_s", Compare::below, 0.35},
      {"overshoot_pct", Compare::below, 10},
      {"settle_s", Compare::below, 1.0},
      {"final_mode", Compare::equal, kFull}}},
    {"yaw-rate",
     "1 rad/s yaw-rate step from hover",
     Manoeuvre::yaw_rate_step,
     1.0,
     0,
     5,
     {{"yaw_rate_error_pct", Compare::below, 10},
      {"max_tilt_deg", Compare::below, 2},
      {"final_mode", Compare::equal, kFull}}},
    {"yaw-full-stick",
     "full yaw stick (2 rad/s at the default max_yaw_rate_rad_s) from hover",
     Manoeuvre::yaw_rate_step,
     2.0,
     0,
     5,
     {{"yaw_rate_error_pct", Compare::below, 10},
      {"max_tilt_deg", Compare::below, 2},
      {"final_mode", Compare::equal, kFull}}},
    {"disturbance",
     "0.15 N m roll and pitch torque for 50 ms in hover",
     Manoeuvre::torque_impulse,
     0.15,
     0.05,
     3,
     {{"recovery_s", Compare::below, 1.0}, {"final_mode", Compare::equal, kFull}}},
    {"large-push",
     "1.0 N m roll and pitch torque for 0.2 s in hover: an upset past the tilt limit that recovers",
     Manoeuvre::torque_impulse,
     1.0,
     0.2,
     3,
     {{"recovery_s", Compare::below, 1.0}, {"final_mode", Compare::equal, kFull}}},
    {"link-loss",
     "the pilot's link goes silent in hover",
     Manoeuvre::link_loss,
     0,
     0,
     5,
     {{"entered_panic", Compare::equal, 1},
      {"final_mode", Compare::equal, kSafe},
      {"engines_at_end_max", Compare::equal, 0}}},
    {"panic",
     "the pilot hits the emergency stop in hover",
     Manoeuvre::panic_request,
     0,
     0,
     4,
     {{"entered_panic", Compare::equal, 1},
      {"final_mode", Compare::equal, kSafe},
      {"engines_at_end_max", Compare::equal, 0}}},
};

}  // namespace

const char* mode_name(uint8_t mode) { return wire::mode_key(static_cast<wire::Mode>(mode)); }

const std::vector<ScenarioSpec>& scenarios() { return kScenarios; }

const ScenarioSpec* find_scenario(const std::string& name) {
  for (const ScenarioSpec& s : kScenarios) {
    if (name == s.name) return &s;
  }
  return nullptr;
}

}  // namespace qrsim
