// What a newcomer tripped over (issue 17), each fixed: a held key's repeated warning collapsed, a
// line speed no port takes refused as a bad option, rx.hex kept from growing without end.
#include <gtest/gtest.h>

#include <sstream>
#include <vector>

#include <pc/core/command_line.hpp>
#include <pc/core/console.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/log_room.hpp>
#include <pc/core/param_file.hpp>
#include <pc/core/parameter_editor.hpp>
#include <pc/core/session_settings.hpp>

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

// rx.hex grew by some 70 MB an hour: past its part size it starts again, the full part moved aside
// (the platform renames it rx.hex.1: Platform.RxHexStartsAgainKeepingOnePreviousFile), so the newest bytes are always on disk and never more than
// two parts.
TEST(Console, RxHexStartsAgainWhenFull) {
  std::vector<std::unique_ptr<std::ostringstream>> parts;
  parts.push_back(std::make_unique<std::ostringstream>());
  ConsoleFiles files;
  files.rx_hex = parts.back().get();
  files.restart_rx_hex = [&parts]() -> std::ostream* {
    parts.push_back(std::make_unique<std::ostringstream>());
    return parts.back().get();
  };
  Console::Setup setup;
  setup.rx_hex_part_bytes = 1000;
  ConsoleLog log;
  Console console(log, std::move(files), setup, 0);
  const std::vector<uint8_t> bytes(20, 0x4D);  // one read: a line of 9 + 3 x 20 + 1 characters
  for (uint32_t t = 1; t <= 50; ++t) console.receive(bytes.data(), bytes.size(), t);
  ASSERT_EQ(parts.size(), 4u) << "50 lines of 70 bytes, 14 to a part of at most 1000";
  for (const auto& part : parts) EXPECT_LE(part->str().size(), 1000u);
  EXPECT_EQ(parts[0]->str().size() + parts[1]->str().size() + parts[2]->str().size() + parts[3]->str().size(),
            50u * parts[0]->str().find('\n') + 50u)
      << "every read recorded once";
  EXPECT_NE(log.find_last("rx.hex full"), nullptr);
}

// The simulator's log filled in 18 s without a word: the room is said at the start, and one warning
// comes when a report crosses half, with the time left at the divider in force; a divider that
// gives a minute is offered.
TEST(LogRoom, SaysTheRoomAndWarnsOnceBeforeTheLogFills) {
  wire::LogStatus status;
  status.capacity_lines = 1820;
  EXPECT_EQ(log_room_text(status, 10, 1000),
            "room for 1820 lines: 18 s at log_divider 10 (100 lines/s); log_divider 33 logs 60 s (parameter screen)");
  EXPECT_EQ(log_room_text(status, 40, 1000), "room for 1820 lines: 73 s at log_divider 40 (25 lines/s)");
  EXPECT_DOUBLE_EQ(log_seconds(1820, 1, 1000), 1.82);

  wire::LogStatus before = status, now = status;
  before.telemetry_lines = 900;
  now.telemetry_lines = 920;  // 50.5 %
  const std::string warning = log_filling_warning(before, now, 10, 1000);
  EXPECT_NE(warning.find("QR log 50 % full: about 9 s left at log_divider 10"), std::string::npos) << warning;
  before = now;
  now.telemetry_lines = 1000;
  EXPECT_EQ(log_filling_warning(before, now, 10, 1000), "") << "once, not at every report";
  now.telemetry_lines = 1820;
  now.flags = wire::kLogStatusFull;
  EXPECT_EQ(log_filling_warning(wire::LogStatus{.capacity_lines = 1820}, now, 10, 1000), "")
      << "full already: the console's log-full warning says it";
}

// Gains moved by stray keys came back at the next start with no way back but editing the file: the
// parameter screen's ! puts every parameter to its default (what differs is sent), and what
// changed since the file is said at exit.
TEST(ParameterEditor, EveryParameterBackToItsDefault) {
  wire::ParameterValues file;
  ASSERT_EQ(file.set(static_cast<uint8_t>(wire::ParamId::yaw_p), 310 * 16), wire::NackReason::none);  // Q4
  ParameterSync sync(file, [](Severity, const std::string&) {});
  const ParameterEditor editor(file, "qrterm-params.txt");
  EXPECT_EQ(editor.reset_all_defaults(sync), 1u) << "only yaw_p differed from its default";
  for (const wire::ParameterSpec& spec : wire::kParameterTable)
    EXPECT_EQ(sync.wanted().get(spec.id), spec.default_value) << spec.name;
  EXPECT_TRUE(sync.pending(wire::ParamId::yaw_p)) << "sent to the QR";
  EXPECT_EQ(editor.reset_all_defaults(sync), 0u);
  EXPECT_EQ(undo_lines(file, sync.wanted()),
            (std::vector<std::string>{"yaw_p 310 -> 300                    undo: yaw_p = 310"}));
  EXPECT_TRUE(undo_lines(file, file).empty());
}

// The file column showed values when there was no parameter file (the defaults stood for it):
// without a file it is empty, until a file is written (the orientation check's) or saved.
TEST(ParameterEditor, NoFileNoFileColumn) {
  wire::ParameterValues defaults;
  ParameterSync sync(defaults, [](Severity, const std::string&) {});
  ParameterEditor editor(defaults, "qrterm-params.txt", /*file_exists=*/false);
  ASSERT_EQ(sync.set(wire::ParamId::yaw_p, 310 * 16), wire::NackReason::none);
  EXPECT_FALSE(editor.file_exists());
  EXPECT_EQ(editor.file_difference(sync, wire::ParamId::yaw_p), std::nullopt) << "no file, no file value";
  editor.file_written("qrterm-params.txt", wire::ParamId::imu_orientation, 1);
  EXPECT_TRUE(editor.file_exists());
  EXPECT_EQ(editor.file_difference(sync, wire::ParamId::yaw_p), 300 * 16) << "the file written holds the default";
  const ParameterEditor with_file(defaults, "qrterm-params.txt");
  EXPECT_EQ(with_file.file_difference(sync, wire::ParamId::yaw_p), 300 * 16);
}

}  // namespace
}  // namespace qrterm
