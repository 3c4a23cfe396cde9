#include <qr/sim_runner/autotune.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <common/mode.hpp>
#include <qr/core/chain/identification.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/sim_runner/vehicle_axes.hpp>
#include <tune/axis_fit.hpp>
#include <tune/identification_design.hpp>
#include <tune/report_json.hpp>

namespace qrsim {
namespace {

// The sequence's timing, as the firmware runs it: each axis' quiet half second, then its bits.
using Sequence = qr::chain::IdentificationSequence<int32_t, qr::kControlHz>;
using tune::kAxisNames;

// What the firmware logged while in mode autotune, split by the axis being excited.
struct IdentificationLog {
  std::array<tune::AxisRecord, 3> axes;
  uint32_t ticks = 0;  // in mode autotune

  void take(const FirmwareView& v) {
    if (v.mode != static_cast<uint8_t>(wire::Mode::autotune)) return;
    const uint32_t axis = ticks / Sequence::kAxisTicks;
    ++ticks;
    if (axis >= 3) return;
    const int16_t rate_e3[3] = {v.p_e3, v.q_e3, v.r_e3};
    axes[axis].moment.push_back(v.moment_e1[axis] * 0.1);
    axes[axis].rate.push_back(rate_e3[axis] * 1e-3);
  }
};

std::string axes_json(const std::array<tune::AxisModel, 3>& m) {
  return "{\"roll\": " + tune::model_json(m[0]) + ", \"pitch\": " + tune::model_json(m[1]) +
         ", \"yaw\": " + tune::model_json(m[2]) + "}";
}

// The fitted gain over the vehicle's, per axis: the 15 % the issue asks is |ratio - 1| <= 0.15.
std::string ratios_json(const std::array<tune::AxisModel, 3>& fit, const VehicleAxes& truth) {
  const tune::AxisModel* t[3] = {&truth.roll, &truth.pitch, &truth.yaw};
  std::string s = "{";
  for (size_t i = 0; i < 3; ++i) {
    s += std::string(i ? ", " : "") + "\"" + kAxisNames[i] +
         "\": {\"gain\": " + tune::json_number(fit[i].gain / t[i]->gain) +
         ", \"motor_tau_s\": " + tune::json_number(fit[i].motor_tau_s / t[i]->motor_tau_s) + "}";
  }
  return s + "}";
}

int fail(FILE* out, const std::string& why) {
  std::fprintf(stderr, "qrsim: autotune: %s\n", why.c_str());
  std::fprintf(out, "{\"autotune\": {\"error\": \"%s\"}}\n", why.c_str());
  return 1;
}

}  // namespace

int run_autotune(const RunOptions& given, FILE* out) {
  ScenarioScript script;
  std::string error;
  if (!find_scenario("autotune", script, error)) return fail(out, error);
  IdentificationLog log;
  RunOptions options = given;
  options.on_tick = [&log](double, const FirmwareView& v) { log.take(v); };
  const ScenarioResult flight = run_scenario(script, options);
  if (!flight.error.empty()) return fail(out, "the flight: " + flight.error);
  // The mode returns to full control in the tick the sequence ends: its last period is not seen.
  if (log.ticks + 1 < Sequence::kTicks) {
    return fail(out, "the identification ended after " + std::to_string(log.ticks) + " of its " +
                         std::to_string(Sequence::kTicks) + " periods (final mode " + flight.final_mode + ")");
  }

  wire::ParameterValues flown;  // the defaults, then what the pilot uploaded
  for (const auto& [id, raw] : script.parameters) flown.set(static_cast<uint8_t>(id), raw);
  for (const auto& [id, raw] : options.parameters) flown.set(static_cast<uint8_t>(id), raw);
  std::array<tune::AxisRecord, 3> records = log.axes;
  std::string why;
  const std::optional<tune::IdentificationDesign> d = tune::design_from_identification(std::move(records), flown,
                                                                                       qr::kControlHz, &why);
  if (!d) return fail(out, why);

  const sim::VehicleParams vehicle = given.vehicle ? *given.vehicle : sim::default_vehicle();
  const VehicleAxes truth = axes_of(vehicle);
  std::fprintf(
      out,
      "{\"autotune\": {\"vehicle\": \"%s\", \"seed\": %llu, \"model\": %s, \"truth\": %s, \"model_over_truth\": %s, "
      "\"params\": %s, \"margins\": {\"before\": %s, \"after\": %s}, \"keeps_targets\": %s, "
      "\"flight\": {\"max_tilt_deg_truth\": %s, \"final_mode\": \"%s\"}}}\n",
      flight.vehicle.c_str(), static_cast<unsigned long long>(options.seed), axes_json(d->models).c_str(),
      axes_json({truth.roll, truth.pitch, truth.yaw}).c_str(), ratios_json(d->models, truth).c_str(),
      tune::params_json(d->roll_pitch, d->yaw).c_str(), tune::design_json(d->before, d->yaw_then).c_str(),
      tune::design_json(d->after, d->yaw_now).c_str(), d->keeps ? "true" : "false",
      tune::json_number(flight.figure("max_tilt_deg_truth")).c_str(), flight.final_mode.c_str());
  return 0;
}

}  // namespace qrsim
