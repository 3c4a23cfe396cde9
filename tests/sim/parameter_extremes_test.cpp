// No parameter inside its range grounds the vehicle (docs/safety.md, rule 13). For every row of
// the parameter table and each end of its range: calibrated and in safe on the ground, the pilot
// sets the parameter to that end, leaves it there for a second, sets the default back, arms full
// control, takes off and makes a 10 deg roll step. Judged on the simulator's truth: no panic,
// the step's rise, overshoot and settle bands, upright and still in full control at the end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <common/parameter_table.hpp>
#include <qr/sim_runner/scenario.hpp>

namespace {

struct Extreme {
  const wire::ParameterSpec* spec;
  bool at_max;
};

std::vector<Extreme> extremes() {
  std::vector<Extreme> all;
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    all.push_back({&spec, false});
    all.push_back({&spec, true});
  }
  return all;
}

// The value in the parameter's unit, as a scenario file writes it (exact: raw / 2^frac).
std::string real_text(const wire::ParameterSpec& spec, int32_t raw) {
  char text[64];
  std::snprintf(text, sizeof text, "%.10g", std::ldexp(static_cast<double>(raw), -spec.frac_bits));
  return text;
}

std::string scenario_text(const Extreme& e) {
  const wire::ParameterSpec& spec = *e.spec;
  const std::string name = spec.name;
  return "seconds: 9\n"
         "start: safe\n"
         "at 0 param " +
         name + " " + real_text(spec, e.at_max ? spec.max : spec.min) + "\n" + "at 1 param " + name + " " +
         real_text(spec, spec.default_value) + "\n" +
         "at 1.5 mode full\n"
         "at 2 lift hold\n"
         "at 6 roll 10\n"
         "at 8 roll 0\n"
         "band entered_panic == 0\n"
         "band rise_s < 0.3\n"
         "band overshoot_pct < 8\n"
         "band settle_s < 0.8\n"
         "band final_upright == 1\n"
         "band final_mode == full\n";
}

void PrintTo(const Extreme& e, std::ostream* out) {
  *out << e.spec->name << (e.at_max ? " at its maximum" : " at its minimum");
}

class ParameterExtremes : public ::testing::TestWithParam<Extreme> {};

TEST_P(ParameterExtremes, SetInSafeAndRestoredTheVehicleStillFlies) {
  const Extreme& e = GetParam();
  qrsim::ScenarioScript script;
  std::string error;
  const std::string name = std::string(e.spec->name) + (e.at_max ? "-max" : "-min");
  ASSERT_TRUE(qrsim::parse_scenario(scenario_text(e), name, name, script, error)) << error;
  const qrsim::ScenarioResult r = qrsim::run_scenario(script, {});
  std::printf("%s\n", qrsim::to_json(r).c_str());
  ASSERT_TRUE(r.error.empty()) << r.error;
  for (const qrsim::CheckResult& c : r.checks) EXPECT_TRUE(c.pass) << name << ": " << c.band;
}

std::string test_name(const ::testing::TestParamInfo<Extreme>& info) {
  return std::string(info.param.spec->name) + (info.param.at_max ? "_max" : "_min");
}

INSTANTIATE_TEST_SUITE_P(EveryParameter, ParameterExtremes, ::testing::ValuesIn(extremes()), test_name);

}  // namespace
