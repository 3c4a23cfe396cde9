// qrterm's options: defaults, values in both spellings, and clear complaints.
#include <gtest/gtest.h>

#include <pc/core/command_line.hpp>

namespace {

using qrterm::parse_command_line;

TEST(Console, CommandLineDefaultsFlyTheSimulatorWithAJoystick) {
  const qrterm::ParsedCommandLine parsed = parse_command_line({});
  ASSERT_EQ(parsed.error, "");
  EXPECT_FALSE(parsed.options.port);
  EXPECT_EQ(parsed.options.baud, 115200u);
  EXPECT_EQ(parsed.options.joystick, "/dev/input/js0");
  EXPECT_FALSE(parsed.options.no_joystick);
  EXPECT_EQ(parsed.options.params, "./qrterm-params.txt");
  EXPECT_FALSE(parsed.options.joystick_wizard);
  EXPECT_TRUE(parse_command_line({"--joystick-wizard"}).options.joystick_wizard);
}

TEST(Console, CommandLineTakesValuesBothWays) {
  const qrterm::ParsedCommandLine parsed = parse_command_line(
      {"--port", "/dev/ttyUSB0", "--baud=9600", "--no-joystick", "--log-dir", "here", "--sim-arg", "-v"});
  ASSERT_EQ(parsed.error, "");
  EXPECT_EQ(parsed.options.port, "/dev/ttyUSB0");
  EXPECT_EQ(parsed.options.baud, 9600u);
  EXPECT_TRUE(parsed.options.no_joystick);
  EXPECT_EQ(parsed.options.log_dir, "here");
  EXPECT_EQ(parsed.options.sim_arguments, std::vector<std::string>{"-v"});
}

TEST(Console, CommandLineComplainsClearly) {
  EXPECT_EQ(parse_command_line({"--prot", "x"}).error, "unknown option \"--prot\" (qrterm --help lists them)");
  EXPECT_EQ(parse_command_line({"--port"}).error, "--port needs a value: --port PATH");
  EXPECT_EQ(parse_command_line({"--baud", "fast"}).error, "--baud: \"fast\" is not a number");
  EXPECT_EQ(parse_command_line({"--no-joystick=yes"}).error, "--no-joystick takes no value");
  EXPECT_NE(parse_command_line({"--port", "a", "--sim", "b"}).error.find("exclude each other"), std::string::npos);
  EXPECT_EQ(parse_command_line({"--joystick-wizard", "--no-joystick"}).error,
            "--joystick-wizard and --no-joystick exclude each other: the wizard maps a joystick");
}

TEST(Console, CellsAreANumberOfCells) {
  EXPECT_EQ(parse_command_line({}).options.battery_cells, 0) << "counted at connection";
  EXPECT_EQ(parse_command_line({"--cells", "4"}).options.battery_cells, 4);
  EXPECT_EQ(parse_command_line({"--cells=0"}).error, "--cells: \"0\" is not a number of cells, 1..8");
  EXPECT_EQ(parse_command_line({"--cells", "9"}).error, "--cells: \"9\" is not a number of cells, 1..8");
  EXPECT_EQ(parse_command_line({"--cells", "3S"}).error, "--cells: \"3S\" is not a number of cells, 1..8");
}

TEST(Console, HelpListsEveryOption) {
  EXPECT_TRUE(parse_command_line({"-h"}).options.help);
  const std::string usage = qrterm::usage_text();
  for (const char* option : {"--port", "--baud", "--sim", "--sim-arg", "--joystick", "--no-joystick", "--joystick-map",
                             "--joystick-wizard", "--params", "--log-dir", "--cells", "--help"}) {
    EXPECT_NE(usage.find(std::string("  ") + option + " "), std::string::npos) << option;
  }
}

}  // namespace
