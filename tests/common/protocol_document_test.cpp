// docs/protocol.md is the contract for other clients: its message table, nack reasons and
// parameter table must say what the code does. (Golden frames: golden_frames_test.)
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include <common/message_table.hpp>
#include <common/nack_reason.hpp>
#include <common/parameter_table.hpp>

namespace {

std::vector<std::smatch> rows_matching(const std::regex& row, std::vector<std::string>& storage) {
  std::ifstream doc(QR_PROTOCOL_DOC);
  EXPECT_TRUE(doc.good()) << "cannot read " << QR_PROTOCOL_DOC;
  std::string line;
  while (std::getline(doc, line)) storage.push_back(line);
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
      std::regex(R"(^\| (0x[0-9A-F]{2}) \| (\w+) \| (PC→QR|QR→PC) \| (\d+) \| (yes|no) \| (\d+) \|$)"), lines);
  ASSERT_EQ(rows.size(), wire::kMessageCount);
  for (size_t i = 0; i < rows.size(); ++i) {
    const wire::MessageSpec& spec = wire::kMessageTable[i];
    const std::smatch& r = rows[i];
    EXPECT_EQ(r[1].str(), hex_byte(wire::type_byte(spec.type)));
    EXPECT_EQ(r[2].str(), spec.name);
    EXPECT_EQ(r[3].str(), spec.direction == wire::Direction::pc_to_qr ? "PC→QR" : "QR→PC") << spec.name;
    EXPECT_EQ(std::stoi(r[4].str()), spec.payload_length) << spec.name;
    EXPECT_EQ(r[5].str(), spec.acked ? "yes" : "no") << spec.name;
    EXPECT_EQ(std::stoi(r[6].str()), spec.payload_length + 3) << spec.name;
  }
}

TEST(ProtocolDocument, NackReasonsMatchTheCode) {
  std::vector<std::string> lines;
  const auto rows = rows_matching(std::regex(R"(^\| (\d+) \| ([a-z_]+) \| [^|]+ \|$)"), lines);
  ASSERT_EQ(rows.size(), std::size(wire::kNackReasons));
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(std::stoi(rows[i][1].str()), static_cast<int>(wire::kNackReasons[i].reason));
    EXPECT_EQ(rows[i][2].str(), wire::kNackReasons[i].name);
  }
}

TEST(ProtocolDocument, ParameterTableMatchesTheCode) {
  std::vector<std::string> lines;
  const auto rows = rows_matching(
      std::regex(R"(^\| (\d+) \| `(\w+)` \| (\d+) \| (-?\d+) \| (-?\d+) \| (-?\d+) \| ([^|]+) \| [^|]+ \|$)"), lines);
  ASSERT_EQ(rows.size(), wire::kParameterCount);
  for (size_t i = 0; i < rows.size(); ++i) {
    const wire::ParameterSpec& spec = wire::kParameterTable[i];
    const std::smatch& r = rows[i];
    EXPECT_EQ(std::stoi(r[1].str()), static_cast<int>(spec.id)) << spec.name;
    EXPECT_EQ(r[2].str(), spec.name);
    EXPECT_EQ(std::stoi(r[3].str()), spec.frac_bits) << spec.name;
    EXPECT_EQ(std::stol(r[4].str()), spec.min) << spec.name;
    EXPECT_EQ(std::stol(r[5].str()), spec.max) << spec.name;
    EXPECT_EQ(std::stol(r[6].str()), spec.default_value) << spec.name;
    EXPECT_EQ(r[7].str(), spec.unit) << spec.name;
  }
}
