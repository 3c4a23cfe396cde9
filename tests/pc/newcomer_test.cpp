// What a newcomer tripped over (issue 17), each fixed: a held key's repeated warning collapsed, a
// line speed no port takes refused as a bad option.
#include <gtest/gtest.h>

#include <sstream>

#include <pc/core/command_line.hpp>
#include <pc/core/console_log.hpp>

namespace qrterm {
namespace {

TEST(ConsoleLog, ALineRepeatedRightAfterIsCountedNotAdded) {
  std::ostringstream file;
  ConsoleLog log(500, &file);
  log.add(10, Severity::info, "roll_pitch_p1 = 20");
  for (uint32_t i = 0; i < 23; ++i) log.add(20 + i, Severity::warning, "roll_pitch_p1 = 20 is at the end of its range");
  log.add(50, Severity::info, "asking for mode manual");
  log.add(60, Severity::warning, "roll_pitch_p1 = 20 is at the end of its range");
  ASSERT_EQ(log.lines().size(), 4u);
  EXPECT_EQ(log.lines()[1].repeats, 22u) << "shown once, with (x23)";
  EXPECT_EQ(log.lines()[1].time_ms, 42u) << "the time of the last";
  EXPECT_EQ(log.lines()[3].repeats, 0u) << "not right after: a line of its own";
  EXPECT_EQ(log.total(), 26u);
  size_t file_lines = 0;
  for (char c : file.str()) file_lines += c == '\n' ? 1 : 0;
  EXPECT_EQ(file_lines, 26u) << "the file keeps every line";
}

TEST(CommandLine, ALineSpeedNoPortTakesIsABadOption) {
  const ParsedCommandLine parsed = parse_command_line({"--baud", "1234"});
  EXPECT_NE(parsed.error.find("--baud: 1234 is not a serial line speed"), std::string::npos) << parsed.error;
  EXPECT_TRUE(parse_command_line({"--baud", "921600"}).error.empty());
}

}  // namespace
}  // namespace qrterm
