// docs/simulator.md prints the built-in scenarios with their bands and every figure a flight
// reports: both must be what the files and the code say.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <qr/boards/sim/scenario.hpp>
#include <qr/boards/sim/scenario_figures.hpp>
#include <qr/boards/sim/sweep.hpp>

#include "../support/source_text.hpp"

namespace {

// The lines of the page from a heading on, up to the next heading of the same or a higher level.
std::vector<std::string> section(const std::string& heading) {
  const std::vector<std::string> all = test_support::lines_of(QR_SIMULATOR_DOC);
  EXPECT_FALSE(all.empty()) << "cannot read " << QR_SIMULATOR_DOC;
  const size_t level = heading.find(' ');
  std::vector<std::string> lines;
  bool inside = false, in_code = false;  // a "# comment" in a code block is no heading
  for (const std::string& line : all) {
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    const size_t hashes = line.find_first_not_of('#');
    const bool is_heading = !in_code && line.rfind("#", 0) == 0 && hashes != std::string::npos && line[hashes] == ' ';
    if (is_heading && hashes <= level) inside = line == heading;
    else if (inside) lines.push_back(line);
  }
  EXPECT_FALSE(lines.empty()) << "no section " << heading;
  return lines;
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::stringstream in(row.substr(1));
  for (std::string cell; std::getline(in, cell, '|');) {
    const size_t a = cell.find_first_not_of(' ');
    const size_t b = cell.find_last_not_of(' ');
    out.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  return out;
}

TEST(ScenarioDocument, TheScenarioTableIsTheFiles) {
  std::map<std::string, std::vector<std::string>> rows;  // name -> cells
  const std::regex row(R"(^\| `([a-z0-9-]+)` \|.*\|$)");
  for (const std::string& line : section("### 6.3 The built-in scenarios")) {
    std::smatch m;
    if (std::regex_match(line, m, row)) rows[m[1].str()] = cells(line);
  }
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(QR_SIM_SCENARIO_DIR)) {
    if (entry.path().extension() != ".txt") continue;
    const std::string name = entry.path().stem().string();
    files.insert(name);
    qrsim::ScenarioScript script;
    std::string error;
    ASSERT_TRUE(qrsim::load_scenario_file(entry.path().string(), script, error)) << error;
    const auto it = rows.find(name);
    if (it == rows.end()) {
      ADD_FAILURE() << name << " has no row in section 6.3";
      continue;
    }
    const std::vector<std::string>& c = it->second;
    ASSERT_EQ(c.size(), 5u) << name;
    std::ostringstream seconds;
    seconds << script.seconds;
    EXPECT_EQ(c[2], seconds.str()) << name << ": seconds";
    std::string bands;
    for (const qrsim::Band& b : script.bands) bands += (bands.empty() ? "`" : ", `") + qrsim::band_text(b) + "`";
    EXPECT_EQ(c[3], bands) << name << ": bands";
    EXPECT_EQ(c[4], script.known_failure.empty() ? "" : "yes") << name << ": known failure";
  }
  for (const auto& [name, c] : rows) EXPECT_TRUE(files.count(name) != 0) << name << " is in the table but has no file";
}

TEST(ScenarioDocument, TheFigureTableIsTheCodes) {
  std::vector<std::string> documented;
  const std::regex row(R"(^\| `([a-z_0-9]+)` \| .+ \|$)");
  for (const std::string& line : section("### 6.5 Figures")) {
    std::smatch m;
    if (std::regex_match(line, m, row)) documented.push_back(m[1].str());
  }
  std::vector<std::string> code;
  for (const qrsim::FigureSpec& f : qrsim::kFigureTable) code.push_back(f.name);
  EXPECT_EQ(documented, code) << "the figures of section 6.5, in print order";
}

// Section 6.4's ranges, row by row in the code's order (mass, inertia, motor lag, vibration, noise).
TEST(ScenarioDocument, TheSweepRangesAreTheCodes) {
  std::vector<std::string> documented;
  const std::regex row(R"(^\| [a-zA-Z].* \| (× [0-9.]+ \.\. [0-9.]+) \|.*\|$)");
  for (const std::string& line : section("### 6.4 Robustness sweep")) {
    std::smatch m;
    if (std::regex_match(line, m, row)) documented.push_back(m[1].str());
  }
  std::vector<std::string> code;
  for (const qrsim::SweepRange& r : qrsim::kSweepRanges) {
    std::ostringstream text;
    text << "× " << r.low << " .. " << r.high;
    code.push_back(text.str());
  }
  EXPECT_EQ(documented, code);
}

// The example of section 6.2, the first code block there, is a file that reads.
TEST(ScenarioDocument, TheExampleReads) {
  std::string text;
  bool inside = false, done = false;
  for (const std::string& line : section("### 6.2 The file format")) {
    if (done) break;
    if (line.rfind("```", 0) == 0) {
      done = inside;
      inside = !inside;
    } else if (inside) {
      text += line + "\n";
    }
  }
  qrsim::ScenarioScript script;
  std::string error;
  ASSERT_TRUE(qrsim::parse_scenario(text, "my-bank", "the example", script, error)) << error << "\n" << text;
  EXPECT_EQ(script.events.size(), 2u);
  EXPECT_EQ(script.bands.size(), 3u);
  EXPECT_FALSE(script.known_failure.empty());
}

// A flight prints exactly the figures of the table (those it measures in every flight, and the
// step, yaw and push figures when the scenario has those events), in the table's order.
TEST(ScenarioDocument, AFlightPrintsTheTablesFiguresInOrder) {
  qrsim::ScenarioScript script;
  std::string error;
  ASSERT_TRUE(
      qrsim::parse_scenario("seconds: 2.5\nat 0 roll 5\nat 0 yaw 0.5\nat 0 torque 0.01 0 0 for 0.01\n"
                            "at 2 roll 0\nband final_mode == full\n",
                            "all-figures", "all-figures", script, error))
      << error;
  const qrsim::ScenarioResult r = qrsim::run_scenario(script, {});
  std::vector<std::string> printed, code;
  for (const qrsim::Figure& f : r.figures) printed.push_back(f.name);
  for (const qrsim::FigureSpec& f : qrsim::kFigureTable) code.push_back(f.name);
  EXPECT_EQ(printed, code);
}

}  // namespace
