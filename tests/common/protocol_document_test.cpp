// docs/protocol.md is the contract for other clients: its message table, nack reasons, mode
// numbers and link budget must say what the code does. (Golden frames: golden_frames_test; the
// parameters: docs/parameters.md, Docs.ParametersMatchTheTable; the task numbers: tests/qr.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include <common/log_records.hpp>
#include <common/message_table.hpp>
#include <common/nack_reason.hpp>
#include <common/observable_table.hpp>
#include <common/parameter_table.hpp>
#include <common/requests.hpp>

#include "../support/source_text.hpp"

namespace {

std::vector<std::string> document_lines() {
  const std::vector<std::string> lines = test_support::lines_of(QR_PROTOCOL_DOC);
  EXPECT_FALSE(lines.empty()) << "cannot read " << QR_PROTOCOL_DOC;
  return lines;
}

// The matches point into `storage`, which holds the document's lines: give each call its own.
std::vector<std::smatch> rows_matching(const std::regex& row, std::vector<std::string>& storage) {
  storage = document_lines();
  std::vector<std::smatch> rows;
  for (const std::string& l : storage) {
    std::smatch m;
    if (std::regex_match(l, m, row)) rows.push_back(m);
  }
  return rows;
}

std::string hex_byte(unsigned v) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02X", v);
  return text;
}

}  // namespace

TEST(ProtocolDocument, MessageTableMatchesTheCode) {
  std::vector<std::string> lines;
  const auto rows = rows_matching(
      std::regex(R"(^\| (0x[0-9A-F]{2}) \| (\w+) \| (PC→QR|QR→PC) \| (\d+) \| (yes|no) \| (yes|no) \| (\d+) \|$)"),
      lines);
  ASSERT_EQ(rows.size(), wire::kMessageCount);
  for (size_t i = 0; i < rows.size(); ++i) {
    const wire::MessageSpec& spec = wire::kMessageTable[i];
    const std::smatch& r = rows[i];
    EXPECT_EQ(r[1].str(), hex_byte(wire::type_byte(spec.type)));
    EXPECT_EQ(r[2].str(), spec.name);
    EXPECT_EQ(r[3].str(), spec.direction == wire::Direction::pc_to_qr ? "PC→QR" : "QR→PC") << spec.name;
    EXPECT_EQ(std::stoi(r[4].str()), spec.payload_length) << spec.name;
    EXPECT_EQ(r[5].str(), spec.acked ? "yes" : "no") << spec.name;
    EXPECT_EQ(r[6].str(), spec.guarded ? "yes" : "no") << spec.name;
    EXPECT_EQ(std::stoi(r[7].str()), wire::frame_length(spec)) << spec.name;
  }
}

TEST(ProtocolDocument, NackReasonsMatchTheCode) {
  // The enum's values run 1..N without gaps, each with one row in the code's table.
  const int last = static_cast<int>(wire::kNackReasons[std::size(wire::kNackReasons) - 1].reason);
  for (int value = 1; value <= 255; ++value) {
    const wire::NackReasonSpec* spec = wire::find_nack_reason(static_cast<wire::NackReason>(value));
    EXPECT_EQ(spec != nullptr, value <= last) << value;
  }
  EXPECT_EQ(wire::find_nack_reason(wire::NackReason::none), nullptr) << "0 is never sent";

  std::vector<std::string> lines;
  const auto rows = rows_matching(std::regex(R"(^\| (\d+) \| ([a-z_]+) \| [^|]+ \|$)"), lines);
  ASSERT_EQ(rows.size(), std::size(wire::kNackReasons));
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(std::stoi(rows[i][1].str()), static_cast<int>(wire::kNackReasons[i].reason));
    EXPECT_EQ(rows[i][2].str(), wire::kNackReasons[i].name);
  }
  // The nack's reason field gives the same range as the table.
  std::vector<std::string> field_lines;
  const auto field = rows_matching(std::regex(R"(^\| 2 \| u8 \| reason \| (\d+)\.\.(\d+), table below.*\|$)"),
                                   field_lines);
  ASSERT_EQ(field.size(), 1u) << "the nack's reason row";
  EXPECT_EQ(std::stoi(field[0][1].str()), 1);
  EXPECT_EQ(std::stoi(field[0][2].str()), last);
}

// Section 13.1's table of observables is the code's, row for row: id, name, unit, type, scale and
// meaning (a row added to the code and not to the document, or the other way, fails).
TEST(ProtocolDocument, ObservableTableMatchesTheCode) {
  std::vector<std::string> lines;
  const auto rows = rows_matching(
      std::regex(R"(^\| (\d+) \| `([a-z0-9_]+)` \| ([^ |]+) \| (i16|u16) \| (-?\d+) \| ([^|]+) \|$)"), lines);
  ASSERT_EQ(rows.size(), size_t{wire::kObservableCount});
  for (size_t i = 0; i < rows.size(); ++i) {
    const wire::ObservableSpec& spec = wire::kObservableTable[i];
    EXPECT_EQ(std::stoi(rows[i][1].str()), static_cast<int>(spec.id)) << spec.name;
    EXPECT_EQ(rows[i][2].str(), spec.name);
    EXPECT_EQ(rows[i][3].str(), spec.unit) << spec.name;
    EXPECT_EQ(rows[i][4].str(), spec.type == wire::ObservableType::i16 ? "i16" : "u16") << spec.name;
    EXPECT_EQ(std::stoi(rows[i][5].str()), spec.scale) << spec.name;
    EXPECT_EQ(rows[i][6].str(), wire::kObservableMeanings[i]) << spec.name;
  }
}

// The mode numbers the document lists are the modes; every other number is answered, not refused
// as malformed: ModeChange decodes it and the QR says unknown_mode.
TEST(ProtocolDocument, ModeNumbersBeyondTheModesAreUnknownModeNotBadValue) {
  std::vector<std::string> lines;
  const auto field = rows_matching(
      std::regex(
          R"(^\| 1 \| u8 \| mode \| 0 safe, .*, (\d) [a-z ]+; any other number \((\d+)\.\.255\) is answered nack `unknown_mode` \|$)"),
      lines);
  ASSERT_EQ(field.size(), 1u) << "the mode_change mode row";
  EXPECT_EQ(std::stoi(field[0][1].str()), wire::kModeCount - 1);
  EXPECT_EQ(std::stoi(field[0][2].str()), wire::kModeCount);
  const wire::ModeChange beyond{1, static_cast<wire::Mode>(wire::kModeCount)};
  EXPECT_TRUE(beyond.valid());
}

// Section 9 points to the generated parameters.md (checked against the table by
// Docs.ParametersMatchTheTable) instead of keeping a second copy of the table.
TEST(ProtocolDocument, ParametersAreListedInParametersMdOnly) {
  const std::vector<std::string> lines = document_lines();
  bool in_section = false, points_there = false;
  for (const std::string& line : lines) {
    if (line.rfind("## ", 0) == 0) in_section = line.rfind("## 9. Parameters", 0) == 0;
    if (!in_section) continue;
    points_there = points_there || line.find("[parameters.md](parameters.md)") != std::string::npos;
    for (const wire::ParameterSpec& spec : wire::kParameterTable) {
      EXPECT_EQ(line.find("| `" + std::string(spec.name) + "` |"), std::string::npos) << "a second table: " << line;
    }
  }
  EXPECT_TRUE(points_there);
}

namespace {

// A number as the document writes it: "11 520" or "7220".
long number_in(const std::string& text) {
  std::string digits;
  for (char c : text) {
    if (c >= '0' && c <= '9') digits += c;
  }
  return std::stol(digits);
}

long frame_bytes(wire::MessageType type) { return wire::frame_length(*wire::message_spec(type)); }

}  // namespace

// Section 7's downlink budget and section 8's download speed, recomputed from the line speed, the
// frame sizes, the top telemetry rate and the log records' part counts.
TEST(ProtocolDocument, LinkBudgetAndDownloadSpeedFollowFromTheFrameSizes) {
  using wire::MessageType;
  const long line_bytes_per_s = 115200 / 10;  // 8N1: ten bits a byte
  const long rate = wire::find_parameter(static_cast<uint8_t>(wire::ParamId::telemetry_rate_hz))->max;
  const long attitude = frame_bytes(MessageType::telemetry_attitude);
  const long rates = frame_bytes(MessageType::telemetry_rates);
  long slow = 0;
  for (MessageType t : {MessageType::telemetry_engines, MessageType::telemetry_setpoints, MessageType::telemetry_system,
                        MessageType::telemetry_link, MessageType::log_status}) {
    slow = std::max(slow, frame_bytes(t));
  }
  const long task = frame_bytes(MessageType::telemetry_task);
  const long free_bytes = line_bytes_per_s - (attitude + rates + slow + task) * rate;
  const long sensor_line = wire::SensorLogRecord::kParts * frame_bytes(MessageType::sensor_log_part);
  const long telemetry_line = wire::TelemetryLogRecord::kParts * frame_bytes(MessageType::telemetry_log_part);

  std::vector<std::string> lines, fast_lines, group_lines, figure_lines;
  const auto budget = rows_matching(
      std::regex(R"(^Budget at the top telemetry rate of (\d+) Hz \(([\d ]+) bytes/s each way\):$)"), lines);
  ASSERT_EQ(budget.size(), 1u);
  EXPECT_EQ(std::stol(budget[0][1].str()), rate);
  EXPECT_EQ(number_in(budget[0][2].str()), line_bytes_per_s);

  const auto fast = rows_matching(
      std::regex(R"(^\| QR→PC \| attitude (\d+) B \+ rates (\d+) B, (\d+) Hz \| (\d+) \| .*$)"), fast_lines);
  ASSERT_EQ(fast.size(), 1u);
  EXPECT_EQ(std::stol(fast[0][1].str()), attitude);
  EXPECT_EQ(std::stol(fast[0][2].str()), rates);
  EXPECT_EQ(std::stol(fast[0][3].str()), rate);
  EXPECT_EQ(std::stol(fast[0][4].str()), (attitude + rates) * rate);
  const auto group = rows_matching(std::regex(R"(^\| QR→PC \| one slow group (\d+) B, (\d+) Hz \| (\d+) \| .*$)"),
                                   group_lines);
  ASSERT_EQ(group.size(), 1u);
  EXPECT_EQ(std::stol(group[0][1].str()), slow);
  EXPECT_EQ(std::stol(group[0][3].str()), slow * rate);
  const auto figure = rows_matching(std::regex(R"(^\| QR→PC \| one task figure (\d+) B, (\d+) Hz \| (\d+) \| .*$)"),
                                    figure_lines);
  ASSERT_EQ(figure.size(), 1u);
  EXPECT_EQ(std::stol(figure[0][1].str()), task);
  EXPECT_EQ(std::stol(figure[0][3].str()), task * rate);

  // The free share is named in both sections, and the lines a second in section 8.
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  const std::regex free_text(R"(([\d ]+) − (\d+) − (\d+) − (\d+) = \*\*(\d+) bytes/s\*\*)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, free_text)) << "section 7: the free bytes/s";
  EXPECT_EQ(number_in(m[1].str()), line_bytes_per_s);
  EXPECT_EQ(std::stol(m[5].str()), free_bytes);
  const std::regex speed(
      R"(a sensor line is (\d+) frames of (\d+) bytes \((\d+) bytes\), a telemetry line (\d+) \((\d+) bytes\);\s+with telemetry still\s+running at (\d+) Hz, (\d+) bytes/s are free \(section 7\), so at most (\d+) sensor\s+lines or (\d+) telemetry lines a second)");
  ASSERT_TRUE(std::regex_search(text, m, speed)) << "section 8: download speed";
  EXPECT_EQ(std::stol(m[1].str()), wire::SensorLogRecord::kParts);
  EXPECT_EQ(std::stol(m[2].str()), frame_bytes(MessageType::sensor_log_part));
  EXPECT_EQ(std::stol(m[3].str()), sensor_line);
  EXPECT_EQ(std::stol(m[4].str()), wire::TelemetryLogRecord::kParts);
  EXPECT_EQ(std::stol(m[5].str()), telemetry_line);
  EXPECT_EQ(std::stol(m[6].str()), rate);
  EXPECT_EQ(std::stol(m[7].str()), free_bytes);
  EXPECT_EQ(std::stol(m[8].str()), free_bytes / sensor_line);
  EXPECT_EQ(std::stol(m[9].str()), free_bytes / telemetry_line);
}
