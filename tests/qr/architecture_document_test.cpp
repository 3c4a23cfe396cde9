// docs/architecture.md prints the task table and the mode table: both must be the code's.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <common/parameter_table.hpp>
#include <qr/core/chain/flight_chain.hpp>
#include <qr/core/flight.hpp>

#include "../support/source_text.hpp"

namespace qr {
namespace {

using Firmware = Flight<FixedChain>;

// The lines of one "## " section of the page.
std::vector<std::string> section(const std::string& title) {
  const std::vector<std::string> all = test_support::lines_of(QR_ARCHITECTURE_DOC);
  EXPECT_FALSE(all.empty()) << "cannot read " << QR_ARCHITECTURE_DOC;
  std::vector<std::string> lines;
  bool inside = false;
  for (const std::string& line : all) {
    if (line.rfind("## ", 0) == 0) inside = line == "## " + title;
    else if (inside) lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, by);) {
    const size_t a = part.find_first_not_of(' ');
    const size_t b = part.find_last_not_of(' ');
    parts.push_back(a == std::string::npos ? "" : part.substr(a, b - a + 1));
  }
  return parts;
}

TEST(ArchitectureDocument, TheTaskTableIsTheCodes) {
  const std::regex row(R"(^\| (\d+) \| ([a-z_]+) \| ([a-z_0-9]+) \| (\d+) \| (\d+) \| .+ \|$)");
  size_t rows = 0;
  for (const std::string& line : section("The task table")) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    const size_t i = std::stoul(m[1].str());
    ASSERT_EQ(i, rows) << "rows in task order";
    ASSERT_LT(i, size_t{kFlightTaskCount});
    const Task<Firmware>& task = Firmware::kTasks[i];
    EXPECT_EQ(m[2].str(), task.name);
    const std::string every = m[3].str();
    if (task.divider_from != nullptr) {
      bool named = false;
      for (const wire::ParameterSpec& p : wire::kParameterTable) named = named || every == p.name;
      EXPECT_TRUE(named) << task.name << ": its rate is a parameter; the page names '" << every << "'";
    } else {
      EXPECT_EQ(every, std::to_string(task.divider)) << task.name;
    }
    EXPECT_EQ(std::stoul(m[4].str()), task.phase) << task.name;
    EXPECT_EQ(std::stoul(m[5].str()), task.budget) << task.name;
    ++rows;
  }
  EXPECT_EQ(rows, size_t{kFlightTaskCount}) << "one row per task";
}

// The sources' names as the page writes them (engine_sources.hpp's enumerators).
constexpr const char* kTiltNames[] = {"stick", "angle", "level", "rate"};
constexpr const char* kYawNames[] = {"stick", "rate", "still"};
constexpr const char* kLiftNames[] = {"stick", "hold", "descend"};

TEST(ArchitectureDocument, TheModeTableIsTheCodes) {
  // "{flying}" stands for the set the flying modes share (task_sets::kFlying).
  std::vector<std::string> flying;
  for (const uint8_t id : task_sets::kFlying) flying.push_back(Firmware::kTasks[id].name);
  size_t rows = 0;
  for (const std::string& line : section("The mode table")) {
    if (line.rfind("| ", 0) != 0) continue;
    const std::vector<std::string> cells = split(line.substr(1, line.size() - 2), '|');
    if (cells.size() != 4 || cells[0] == "mode" || cells[0].rfind("---", 0) == 0) continue;
    ASSERT_LT(rows, size_t{kModeCount});
    const Mode mode = static_cast<Mode>(rows);
    EXPECT_EQ(cells[0], wire::mode_name(mode)) << "rows in mode order";
    const FlightMode<Firmware>& code = flight_modes<Firmware>()[rows];
    std::vector<std::string> names;
    for (uint8_t k = 0; k < code.tasks.count; ++k) names.push_back(Firmware::kTasks[code.tasks.ids[k]].name);
    const std::vector<std::string> cell_names = split(cells[1], ',');
    EXPECT_EQ(cell_names.size() == 1 && cell_names[0] == "{flying}" ? flying : cell_names, names) << cells[0];
    const chain::EngineSources& s = code.sources;
    EXPECT_EQ(split(cells[2], ','),
              (std::vector<std::string>{kTiltNames[static_cast<int>(s.tilt)], kYawNames[static_cast<int>(s.yaw)],
                                        kLiftNames[static_cast<int>(s.lift)]}))
        << cells[0] << ": its sources";
    EXPECT_EQ(cells[3].empty(), code.enter == nullptr) << cells[0] << ": an entry action iff the page names one";
    ++rows;
  }
  EXPECT_EQ(rows, size_t{kModeCount}) << "one row per mode";
}

}  // namespace
}  // namespace qr
