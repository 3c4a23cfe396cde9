// docs/safety.md rule 19: the ranges of the parameters that bound a safety behaviour are rules of
// their own. Each range must stay inside its bound, for the reason given beside it, and the page
// states each range as the parameter table has it. A range opened by an edit (a battery panic
// allowed down to 0 mV, a link timeout up to a minute) fails here, by name, before any flight.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <common/parameter_table.hpp>

namespace wire {
namespace {

struct SafetyRange {
  ParamId id;
  int32_t lowest_min;   // the range's min may not be below this (raw)
  int32_t highest_max;  // its max may not be above this (raw)
  const char* why;
};

// The bounds and their reasons (the pack: 3S LiPo, 3.0 V a cell empty, 4.2 V full).
constexpr SafetyRange kSafetyRanges[] = {
    {ParamId::battery_panic_mv, 9000, 12600,
     "3.0 V a cell at the least (below it a LiPo is damaged), a full pack at most"},
    {ParamId::battery_warning_mv, 9000, 12600, "the same bounds as the panic's"},
    {ParamId::battery_sag_mv, 0, 3000,
     "the sag model may add 3 V at full load at most: more would read an empty pack full"},
    {ParamId::link_timeout_ms, 50, 2000, "a lost link panics within 2 s (20 m at 10 m/s); 50 ms is 2.5 control frames"},
    {ParamId::tilt_limit_mrad, 87, 1396, "80 deg at most: a limit past 90 deg trips only once the vehicle is over"},
    {ParamId::tilt_time_ms, 0, 2000, "a lost vehicle panics within 2 s of its tilt"},
    {ParamId::panic_level, 0, 100, "the cut holds at most the lift that flew (more would climb)"},
    {ParamId::panic_hold_ms, 0, 10000, "with the ramp, the cut's engines stop within 20 s"},
    {ParamId::panic_ramp_ms, 0, 10000, "with the hold, the cut's engines stop within 20 s"},
    {ParamId::idle_level, 0, 500,
     "the idle floor stays below the hover (535 for the default vehicle): idle never lifts"},
    {ParamId::panic_descent_mm_s, 100, 2000, "a landing touches down at 2 m/s at most, and from 30 m within 5 minutes"},
    {ParamId::takeoff_mg, 1000, 4000,
     "at rest the accelerometer reads 1 g: a lower threshold calls a resting vehicle climbing"},
    {ParamId::max_tilt_mrad, 87, 698,
     "full stick asks 40 deg at most, inside the tilt limit's default 45: a stick alone never panics"},
};

const ParameterSpec& spec(ParamId id) {
  for (const ParameterSpec& s : kParameterTable) {
    if (s.id == id) return s;
  }
  std::abort();
}

TEST(SafetyRanges, EachSafetyRangeKeepsItsRule) {
  for (const SafetyRange& r : kSafetyRanges) {
    const ParameterSpec& s = spec(r.id);
    EXPECT_GE(s.min, r.lowest_min) << s.name << ": " << r.why;
    EXPECT_LE(s.max, r.highest_max) << s.name << ": " << r.why;
  }
  EXPECT_LE(spec(ParamId::panic_hold_ms).max + spec(ParamId::panic_ramp_ms).max, 20000)
      << "the cut's engines stop within 20 s";
}

// docs/safety.md's rule 19 table: | `name` | min | max | unit | why |, one row per range above.
TEST(SafetyRanges, TheSafetyPageStatesEachRange) {
  std::ifstream in(QR_SAFETY_DOC);
  ASSERT_TRUE(in) << QR_SAFETY_DOC;
  const std::regex row(R"(^\| `([a-z0-9_]+)` \| (-?[0-9]+) \| (-?[0-9]+) \| ([^|]+) \| [^|]+ \|$)");
  std::string line;
  std::map<std::string, std::string> rows;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, row)) rows[m[1].str()] = m[2].str() + " " + m[3].str() + " " + m[4].str();
  }
  for (const SafetyRange& r : kSafetyRanges) {
    const ParameterSpec& s = spec(r.id);
    ASSERT_EQ(s.frac_bits, 0) << s.name << ": the page states raw values";
    const auto it = rows.find(s.name);
    if (it == rows.end()) {
      ADD_FAILURE() << s.name << " has no row in docs/safety.md's table of safety ranges";
      continue;
    }
    std::ostringstream want;
    want << s.min << " " << s.max << " " << s.unit;
    EXPECT_EQ(it->second, want.str()) << s.name;
    rows.erase(it);
  }
  for (const auto& [name, cells] : rows) ADD_FAILURE() << name << " is on the page but not a safety range here";
}

}  // namespace
}  // namespace wire
