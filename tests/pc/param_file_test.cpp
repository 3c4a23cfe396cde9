// The parameter file: exact round trips of every parameter in its real unit, and each kind of bad
// line named with its line number.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <random>

#include <pc/core/param_file.hpp>
#include <pc/core/settings_text.hpp>

namespace {

using qrterm::parse_param_file;

const wire::ParameterSpec& spec_of(wire::ParamId id) { return *wire::find_parameter(static_cast<uint8_t>(id)); }

TEST(ParamFile, RoundTripOfEveryParameterIsExact) {
  std::mt19937 random(4073);
  for (int round = 0; round < 200; ++round) {
    wire::ParameterValues values;
    for (const wire::ParameterSpec& spec : wire::kParameterTable) {
      std::uniform_int_distribution<int32_t> pick(spec.min, spec.max);
      int32_t raw = pick(random);
      if (round == 0) raw = spec.min;
      if (round == 1) raw = spec.max;
      ASSERT_EQ(values.set(static_cast<uint8_t>(spec.id), raw), wire::NackReason::none);
    }
    const qrterm::ParamFileContents back = parse_param_file(qrterm::format_param_file(values));
    ASSERT_TRUE(back.errors.empty()) << qrterm::describe("text", back.errors);
    for (const wire::ParameterSpec& spec : wire::kParameterTable) {
      ASSERT_EQ(back.values.get(spec.id), values.get(spec.id)) << spec.name;
    }
    EXPECT_EQ(back.listed.size(), wire::kParameterCount);
  }
}

TEST(ParamFile, ValuesAreInTheTablesRealUnits) {
  EXPECT_EQ(qrterm::format_real(spec_of(wire::ParamId::roll_pitch_p1), 1088), "4.25");
  EXPECT_EQ(qrterm::format_real(spec_of(wire::ParamId::yaw_p), 1600), "100");
  EXPECT_EQ(qrterm::format_real(spec_of(wire::ParamId::max_yaw_rate_rad_s), 1), "0.0009765625");
  EXPECT_EQ(qrterm::format_real(spec_of(wire::ParamId::yaw_p), -8), "-0.5");
  const qrterm::ParamFileContents file = parse_param_file(
      "roll_pitch_p1 = 4.25\nyaw_p=100.5\nmax_yaw_rate_rad_s = 2\n");
  ASSERT_TRUE(file.errors.empty());
  EXPECT_EQ(file.values.get(wire::ParamId::roll_pitch_p1), 1088);
  EXPECT_EQ(file.values.get(wire::ParamId::yaw_p), 1608);
  EXPECT_EQ(file.values.get(wire::ParamId::max_yaw_rate_rad_s), 2048);
}

TEST(ParamFile, ValueBetweenStepsGoesToTheNearest) {
  const qrterm::ParamFileContents file = parse_param_file("roll_pitch_p1 = 4.3\n");  // 4.3 * 256 = 1100.8
  ASSERT_TRUE(file.errors.empty());
  EXPECT_EQ(file.values.get(wire::ParamId::roll_pitch_p1), 1101);
}

TEST(ParamFile, ParametersTheFileDoesNotNameKeepTheirDefaults) {
  const qrterm::ParamFileContents file = parse_param_file("# only one\n\n   attitude_c1 = 128   # halved\n");
  ASSERT_TRUE(file.errors.empty());
  EXPECT_EQ(file.values.get(wire::ParamId::attitude_c1), 128);
  EXPECT_EQ(file.values.get(wire::ParamId::attitude_c2), spec_of(wire::ParamId::attitude_c2).default_value);
  ASSERT_EQ(file.listed.size(), 1u);
}

TEST(ParamFile, BadLinesAreNamedWithTheirLineNumbers) {
  const qrterm::ParamFileContents file = parse_param_file(
      "yaw_p = 100\n"
      "yawp = 3\n"
      "roll_pitch_p1 4\n"
      "roll_pitch_p2 = fast\n"
      "attitude_c1 = 0\n"
      "yaw_p = 90\n"
      "roll_pitch_p1 =\n"
      "telemetry_rate_hz = 1e2\n");
  ASSERT_EQ(file.errors.size(), 7u);
  const std::pair<size_t, const char*> expected[] = {
      {2, "unknown parameter \"yawp\" (known: yaw_p, roll_pitch_p1,"},
      {3, "expected \"name = value\", found \"roll_pitch_p1 4\""},
      {4, "roll_pitch_p2: \"fast\" is not a number"},
      {5, "attitude_c1 = 0 is outside 1 .. 65535 samples"},
      {6, "yaw_p is set twice"},
      {7, "no value for roll_pitch_p1"},
      {8, "telemetry_rate_hz: \"1e2\" is not a number"},
  };
  for (size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(file.errors[i].line, expected[i].first);
    EXPECT_NE(file.errors[i].message.find(expected[i].second), std::string::npos) << file.errors[i].message;
  }
  EXPECT_EQ(qrterm::describe("params.txt", {file.errors[0]}).rfind("params.txt:2: unknown parameter", 0), 0u);
}

// A file saved before the names carried their units is refused, and the message gives each new name.
TEST(ParamFile, FormerNamesAreRefusedWithTheirNewNames) {
  const qrterm::ParamFileContents file = parse_param_file("p1 = 4\nlink_timeout = 300\nc2 = 5\n");
  ASSERT_EQ(file.errors.size(), 3u);
  EXPECT_NE(file.errors[0].message.find("\"p1\" is now called roll_pitch_p1"), std::string::npos)
      << file.errors[0].message;
  EXPECT_NE(file.errors[1].message.find("is now called link_timeout_ms"), std::string::npos) << file.errors[1].message;
  EXPECT_NE(file.errors[2].message.find("is now called attitude_c2"), std::string::npos) << file.errors[2].message;
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    const qrterm::ParamFileContents current = parse_param_file(std::string(spec.name) + " = 1\n");
    for (const qrterm::LineError& e : current.errors)
      EXPECT_EQ(e.message.find("now called"), std::string::npos) << spec.name;
  }
}

TEST(ParamFile, HugeNumbersAreOutOfRangeNotUndefined) {
  const qrterm::ParamFileContents file = parse_param_file(
      "attitude_c2 = 99999999999999999999999\nattitude_c1 = -1e400\n");
  ASSERT_EQ(file.errors.size(), 2u);
  const std::string c2_max = std::to_string(
      wire::find_parameter(static_cast<uint8_t>(wire::ParamId::attitude_c2))->max);
  EXPECT_NE(file.errors[0].message.find("is outside 1 .. " + c2_max), std::string::npos) << file.errors[0].message;
  EXPECT_NE(file.errors[1].message.find("not a number"), std::string::npos) << "no exponents";
}

TEST(ParamFile, SavedFileReplacesTheOldOneWhole) {
  char folder[] = "/tmp/qrterm-params-XXXXXX";
  ASSERT_NE(::mkdtemp(folder), nullptr);
  const std::string path = std::string(folder) + "/params.txt";
  EXPECT_EQ(qrterm::write_file_atomically(path, "old\n"), "");
  EXPECT_EQ(qrterm::write_file_atomically(path, "roll_pitch_p1 = 4\n"), "");
  std::string text;
  ASSERT_TRUE(qrterm::read_file(path, text));
  EXPECT_EQ(text, "roll_pitch_p1 = 4\n");
  EXPECT_NE(qrterm::write_file_atomically(std::string(folder) + "/no/such/folder/p.txt", "x").find("cannot write"),
            std::string::npos);
  std::remove(path.c_str());
  ::rmdir(folder);
}

// One parameter written into the file the moment it is known (the orientation check's
// imu_orientation): the file's other values kept, a missing file made from the defaults, a file
// that does not read left as it is.
TEST(ParamFile, OneParameterWrittenKeepsTheRest) {
  const std::string path = ::testing::TempDir() + "param_file_one.txt";
  std::remove(path.c_str());
  ASSERT_EQ(qrterm::write_param_to_file(path, wire::ParamId::imu_orientation, 1), "");
  std::string text;
  ASSERT_TRUE(qrterm::read_file(path, text));
  qrterm::ParamFileContents read = parse_param_file(text);
  EXPECT_EQ(read.values.get(wire::ParamId::imu_orientation), 1);
  EXPECT_EQ(read.values.get(wire::ParamId::yaw_p), spec_of(wire::ParamId::yaw_p).default_value);

  ASSERT_EQ(qrterm::write_file_atomically(path, "yaw_p = 250\nimu_orientation = 3\n"), "");
  ASSERT_EQ(qrterm::write_param_to_file(path, wire::ParamId::imu_orientation, 5), "");
  ASSERT_TRUE(qrterm::read_file(path, text));
  read = parse_param_file(text);
  EXPECT_EQ(read.values.get(wire::ParamId::imu_orientation), 5);
  EXPECT_EQ(read.values.get(wire::ParamId::yaw_p), 250 * (1 << spec_of(wire::ParamId::yaw_p).frac_bits));

  ASSERT_EQ(qrterm::write_file_atomically(path, "yaw_p = 250\nyawp = 3\n"), "");
  const std::string refused = qrterm::write_param_to_file(path, wire::ParamId::imu_orientation, 2);
  EXPECT_EQ(refused.rfind(path + ":2: unknown parameter \"yawp\"", 0), 0u) << refused;
  ASSERT_TRUE(qrterm::read_file(path, text));
  EXPECT_EQ(text, "yaw_p = 250\nyawp = 3\n") << "left as it was";
  std::remove(path.c_str());
}

}  // namespace
