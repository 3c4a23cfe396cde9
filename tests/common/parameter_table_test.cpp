// The shared parameter table: ids, ranges and defaults hang together, and the defaults the issue
// names are the ones in the table.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <utility>

#include <common/parameter_table.hpp>

using wire::find_parameter;
using wire::kParameterTable;
using wire::NackReason;
using wire::ParamId;
using wire::ParameterSpec;

namespace {
int32_t default_of(ParamId id) { return find_parameter(static_cast<uint8_t>(id))->default_value; }
}  // namespace

TEST(ParameterTable, IdsRunFromOneInTableOrderAndNamesAreUnique) {
  std::set<std::string> names;
  for (size_t row = 0; row < wire::kParameterCount; ++row) {
    const ParameterSpec& spec = kParameterTable[row];
    EXPECT_EQ(static_cast<size_t>(spec.id), row + 1) << spec.name;
    EXPECT_TRUE(names.insert(spec.name).second) << spec.name;
    EXPECT_EQ(find_parameter(static_cast<uint8_t>(spec.id)), &spec);
  }
  EXPECT_EQ(find_parameter(0), nullptr);
  EXPECT_EQ(find_parameter(static_cast<uint8_t>(wire::kParameterCount + 1)), nullptr);
  EXPECT_EQ(find_parameter(0xFF), nullptr) << "0xFF means 'all' in param_get";
}

TEST(ParameterTable, RangesAreSaneAndDefaultsInside) {
  for (const ParameterSpec& spec : kParameterTable) {
    EXPECT_LE(spec.min, spec.max) << spec.name;
    EXPECT_TRUE(wire::in_range(spec, spec.default_value)) << spec.name;
    EXPECT_LE(spec.frac_bits, 30) << spec.name;
    EXPECT_GT(std::string(spec.unit).size(), 0u) << spec.name;
    EXPECT_GT(std::string(spec.meaning).size(), 0u) << spec.name;
  }
}

TEST(ParameterTable, DefaultsTheSafetyRulesName) {
  EXPECT_EQ(default_of(ParamId::link_timeout_ms), 250);
  EXPECT_EQ(default_of(ParamId::battery_panic_mv), 10500);
  EXPECT_GT(default_of(ParamId::battery_warning_mv), default_of(ParamId::battery_panic_mv));
  // 45 degrees in mrad: 1000 * pi / 4 = 785.4.
  EXPECT_EQ(default_of(ParamId::tilt_limit_mrad), 785);
  // The cut holds below the flying lift (the vehicle sinks), the landing descends gently.
  EXPECT_LT(default_of(ParamId::panic_level), 100);
  EXPECT_LE(default_of(ParamId::panic_descent_mm_s), 1000);
}

TEST(ParameterTable, EveryParameterTheIssueListsIsThere) {
  for (const char* name : {"yaw_p", "roll_pitch_p1", "roll_pitch_p2", "attitude_c1", "attitude_c2", "filter_cutoff_hz",
                           "telemetry_rate_hz", "link_timeout_ms", "battery_panic_mv", "battery_warning_mv",
                           "tilt_limit_mrad", "panic_hold_ms", "panic_level", "roll_pitch_i", "roll_pitch_d"}) {
    bool found = false;
    for (const ParameterSpec& spec : kParameterTable) found = found || std::string(spec.name) == name;
    EXPECT_TRUE(found) << name;
  }
}

// A name says its unit: every parameter in one of these units ends in the unit's suffix, and no
// name carries a suffix its unit does not match.
TEST(ParameterTable, NamesEndInTheirUnit) {
  const std::pair<const char*, const char*> suffixes[] = {
      {"ms", "_ms"}, {"Hz", "_hz"}, {"mV", "_mv"}, {"mrad", "_mrad"}, {"rad/s", "_rad_s"}};
  const auto ends_with = [](const std::string& text, const std::string& end) {
    return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
  };
  for (const ParameterSpec& spec : kParameterTable) {
    for (const auto& [unit, suffix] : suffixes) {
      EXPECT_EQ(std::string(spec.unit) == unit, ends_with(spec.name, suffix)) << spec.name << " [" << spec.unit << "]";
    }
  }
}

// The enumerators are spelled as the names: the table's rows make both from one identifier, and
// these spot checks fail if that ever stops being so.
TEST(ParameterTable, EnumeratorsAreTheNames) {
  EXPECT_STREQ(find_parameter(static_cast<uint8_t>(ParamId::roll_pitch_p1))->name, "roll_pitch_p1");
  EXPECT_STREQ(find_parameter(static_cast<uint8_t>(ParamId::attitude_c2))->name, "attitude_c2");
  EXPECT_STREQ(find_parameter(static_cast<uint8_t>(ParamId::link_timeout_ms))->name, "link_timeout_ms");
  EXPECT_STREQ(find_parameter(static_cast<uint8_t>(ParamId::tilt_limit_mrad))->name, "tilt_limit_mrad");
  static_assert(wire::ids_follow_rows());
}

// The attitude filter's bias loop is s^2 + s / (C1 dt) + 1 / (C2 dt^2): damping sqrt(C2) / (2 C1).
// The defaults make it critically damped, and the range lets C2 = 4 C1^2 reach well past them
// (docs/signal-chain.md: C1 of seconds for free flight).
TEST(ParameterTable, AttitudeFilterDefaultsAreCriticallyDampedAndTheRangeAllowsIt) {
  const int64_t c1 = default_of(ParamId::attitude_c1), c2 = default_of(ParamId::attitude_c2);
  EXPECT_EQ(c2, 4 * c1 * c1);
  const int64_t c2_max = find_parameter(static_cast<uint8_t>(ParamId::attitude_c2))->max;
  EXPECT_GE(c2_max, 4 * (2 * c1) * (2 * c1)) << "C1 twice the default still damped";
}

// The rate loop's integral and derivative share the gains' conventions: raw integers in the
// parameter's Q format, 0 switching the term off, the controllers' thrust units.
TEST(ParameterTable, RateLoopIntegralAndDerivativeGains) {
  const ParameterSpec& i = *find_parameter(static_cast<uint8_t>(ParamId::roll_pitch_i));
  const ParameterSpec& d = *find_parameter(static_cast<uint8_t>(ParamId::roll_pitch_d));
  EXPECT_EQ(i.min, 0);
  EXPECT_EQ(d.min, 0);
  EXPECT_EQ(i.frac_bits, 4);
  EXPECT_EQ(d.frac_bits, 8);
  EXPECT_GT(i.default_value, 0);
  EXPECT_GT(d.default_value, 0);
  EXPECT_EQ(std::string(i.unit), "thrust units per rad");
  EXPECT_EQ(std::string(d.unit), "thrust units per rad/s^2");
  // D x fs is formed as an int32 product of the raw value and the sample rate (controllers.hpp).
  EXPECT_LE(int64_t{d.max} * 1000, int64_t{INT32_MAX});
}

TEST(ParameterValues, StartAtDefaultsAndAcceptOnlyKnownIdsInRange) {
  wire::ParameterValues values;
  for (const ParameterSpec& spec : kParameterTable) EXPECT_EQ(values.get(spec.id), spec.default_value);

  const ParameterSpec& tilt = *find_parameter(static_cast<uint8_t>(ParamId::tilt_limit_mrad));
  EXPECT_EQ(values.set(static_cast<uint8_t>(ParamId::tilt_limit_mrad), tilt.max), NackReason::none);
  EXPECT_EQ(values.get(ParamId::tilt_limit_mrad), tilt.max);
  EXPECT_EQ(values.set(static_cast<uint8_t>(ParamId::tilt_limit_mrad), tilt.max + 1), NackReason::bad_value);
  EXPECT_EQ(values.set(static_cast<uint8_t>(ParamId::tilt_limit_mrad), tilt.min - 1), NackReason::bad_value);
  EXPECT_EQ(values.get(ParamId::tilt_limit_mrad), tilt.max) << "a refused value changes nothing";
  EXPECT_EQ(values.set(0, 1), NackReason::unknown_parameter);
  EXPECT_EQ(values.set(200, 1), NackReason::unknown_parameter);
}
