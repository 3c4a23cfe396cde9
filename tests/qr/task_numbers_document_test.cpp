// docs/protocol.md numbers the telemetry_task message's tasks 0..N-1 by the rows of the firmware's
// task table and lists their names: the list must be the table, whatever its length.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <qr/core/flight.hpp>

#include "../support/source_text.hpp"

#include "scripted_chain.hpp"

namespace qr {
namespace {

using Firmware = Flight<test::ScriptedChain>;

std::vector<std::string> document_lines() {
  const std::vector<std::string> lines = test_support::lines_of(QR_PROTOCOL_DOC);
  EXPECT_FALSE(lines.empty()) << "cannot read " << QR_PROTOCOL_DOC;
  return lines;
}

TEST(TaskNumbersDocument, TheTaskTableIsTheFirmwaresTaskTable) {
  std::vector<int> numbers;
  std::vector<std::string> names;
  std::string count_text;
  const std::regex row(R"(^\| (\d+) \| `([a-z_ ]+)` \|$)");
  const std::regex count(R"(today N = (\d+)\.)");
  for (const std::string& line : document_lines()) {
    std::smatch m;
    if (std::regex_match(line, m, row)) {
      numbers.push_back(std::stoi(m[1].str()));
      names.push_back(m[2].str());
    }
    if (std::regex_search(line, m, count)) count_text = m[1].str();
  }
  ASSERT_EQ(names.size(), size_t{kFlightTaskCount}) << "one row per task of qr/core/flight_tasks.hpp";
  static_assert(Firmware::kTaskCount == kFlightTaskCount);
  for (size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(numbers[i], static_cast<int>(i));
    EXPECT_EQ(names[i], Firmware::kTasks[i].name) << "task " << i;
  }
  ASSERT_FALSE(count_text.empty()) << "the page says how many tasks there are today";
  EXPECT_EQ(std::stoi(count_text), kFlightTaskCount);
}

}  // namespace
}  // namespace qr
