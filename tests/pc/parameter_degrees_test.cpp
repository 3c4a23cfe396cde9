// Angles on the parameter screen in degrees beside their mrad: a pilot who wanted a 45 deg stick got
// a 40 deg set-point without knowing, since full stick asks for max_tilt_mrad (at most 698 mrad).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <common/parameter_table.hpp>
#include <pc/core/param_file.hpp>
#include <pc/core/parameter_editor.hpp>

namespace qrterm {
namespace {

const wire::ParameterSpec& spec_of(wire::ParamId id) { return *wire::find_parameter(static_cast<uint8_t>(id)); }

TEST(ParameterDegrees, AnglesInMradAreShownInDegrees) {
  const wire::ParameterSpec& max_tilt = spec_of(wire::ParamId::max_tilt_mrad);
  ASSERT_TRUE(degrees_of(max_tilt, 524));
  EXPECT_NEAR(*degrees_of(max_tilt, 524), 30.02, 0.01);
  EXPECT_NEAR(*degrees_of(max_tilt, max_tilt.max), 39.99, 0.01) << "the stick's largest angle: 40 deg, not 45";
  EXPECT_NEAR(*degrees_of(spec_of(wire::ParamId::tilt_limit_mrad), 785), 44.98, 0.01);
  EXPECT_FALSE(degrees_of(spec_of(wire::ParamId::yaw_p), 4800));
  EXPECT_FALSE(degrees_of(spec_of(wire::ParamId::max_yaw_rate_rad_s), 2048)) << "a rate is not an angle";
  // Every parameter named in mrad is an angle with degrees, and no other.
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    EXPECT_EQ(degrees_of(spec, spec.default_value).has_value(), std::string(spec.name).ends_with("_mrad")) << spec.name;
  }
}

TEST(ParameterDegrees, TheDegreesStandBesideTheValueAndTheColumnsStayPut) {
  EXPECT_EQ(name_and_value(spec_of(wire::ParamId::max_tilt_mrad), 524, 30), "max_tilt_mrad   (30.0 deg) 524");
  EXPECT_EQ(name_and_value(spec_of(wire::ParamId::max_tilt_mrad), 698, 30), "max_tilt_mrad   (40.0 deg) 698");
  EXPECT_EQ(name_and_value(spec_of(wire::ParamId::tilt_limit_mrad), 785, 30), "tilt_limit_mrad (45.0 deg) 785");
  // Four digits leave no room for the decimal beside the longer name: whole degrees.
  EXPECT_EQ(name_and_value(spec_of(wire::ParamId::tilt_limit_mrad), 1396, 30), "tilt_limit_mrad  (80 deg) 1396");
  // Every row at its minimum, maximum and default: the value ends in the value column's last
  // place, as the screen's header has it ("%-19s %10s"), and the rows without an angle are as
  // before.
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    for (int32_t raw : {spec.min, spec.max, spec.default_value}) {
      const std::string row = name_and_value(spec, raw, 30);
      const std::string value = format_real(spec, raw);
      ASSERT_EQ(row.size(), 30u) << spec.name;
      EXPECT_EQ(row.substr(30 - value.size()), value) << spec.name;
      EXPECT_EQ(row.rfind(spec.name, 0), 0u) << spec.name;
      if (!degrees_of(spec, raw)) {
        char old_row[64];
        std::snprintf(old_row, sizeof old_row, "%-19.19s %10.10s", spec.name, value.c_str());
        EXPECT_EQ(row, old_row);
      } else {
        EXPECT_NE(row.find(" deg) "), std::string::npos) << row;
      }
    }
  }
}

TEST(ParameterDegrees, TheMeaningLineAndTheRefusalSayTheDegrees) {
  EXPECT_EQ(unit_with_degrees(spec_of(wire::ParamId::max_tilt_mrad), 698), "mrad, now 40.0 deg");
  EXPECT_EQ(unit_with_degrees(spec_of(wire::ParamId::yaw_p), 4800), "thrust units per rad/s");

  wire::ParameterValues values;
  ParameterSync sync(values, [](Severity, const std::string&) {});
  ParameterEditor editor(values, "qrterm-params.txt");
  while (editor.selected().id != wire::ParamId::max_tilt_mrad) editor.move(1);
  EXPECT_EQ(editor.set_typed(sync, "785"), "max_tilt_mrad = 785 is outside 87 .. 698 mrad (5.0 .. 40.0 deg)");
  EXPECT_EQ(editor.set_typed(sync, "698"), "");
  EXPECT_EQ(sync.wanted().get(wire::ParamId::max_tilt_mrad), 698);
}

}  // namespace
}  // namespace qrterm
