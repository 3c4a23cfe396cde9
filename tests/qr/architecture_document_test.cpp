// docs/architecture.md prints the task table and the mode table: both must be the code's. What
// else the page says of the code is held to it where a test can read both: the tick's exchanges
// with the board and their bounds, the task numbers it gives, what the chain knows, the jobs
// table's files, and the one place the mode changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <common/parameter_table.hpp>
#include <qr/core/chain/flight_chain.hpp>
#include <qr/core/flight.hpp>

#include "../support/source_text.hpp"

namespace qr {
namespace {

namespace fs = std::filesystem;
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

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// The number `pattern`'s group captures in `text` ("at most (\\d+) received bytes").
int number_in(const std::string& text, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(pattern))) {
    ADD_FAILURE() << "the page no longer says /" << pattern << "/";
    return -1;
  }
  return std::stoi(m[1].str());
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

// The receive, radio and send bounds of "One tick" (at 1 kHz) are the scheduler's.
TEST(ArchitectureDocument, TheTickBoundsAreTheSchedulers) {
  if (kControlHz != 1000) GTEST_SKIP() << "the page's figures are at 1 kHz";
  const std::string tick = joined(section("One tick"));
  const SchedulerLimits limits;
  EXPECT_EQ(number_in(tick, R"(at most (\d+) received bytes)"), limits.rx_bytes_per_tick);
  EXPECT_EQ(number_in(tick, R"(at most (\d+) radio bytes)"), limits.radio_bytes_per_tick);
  EXPECT_EQ(number_in(tick, R"(at most (\d+) bytes go out)"), limits.tx_bytes_per_tick);
  EXPECT_EQ(number_in(tick, R"(the (\d+) bytes the line carries in a period)"), kLineBytesPerTick);
}

// "One tick" names every call the scheduler makes on the board (`board.x`), and those of a tick's
// run in the order it makes them: an exchange added to the tick is missing from the page until
// it says where it happens.
TEST(ArchitectureDocument, TheTickNamesEveryBoardExchangeInOrder) {
  const std::string code = test_support::code_of(fs::path(QR_SOURCE_DIR) / "qr/core/scheduler.hpp");
  const size_t run = code.find("void run(uint32_t now_us)");
  const size_t finish = code.find("void finish(");
  ASSERT_NE(run, std::string::npos);
  ASSERT_NE(finish, std::string::npos);
  const std::string tick = joined(section("One tick"));
  const std::regex call(R"(board_\.([a-z_]+)\()");
  std::vector<std::string> in_run;
  size_t named = 0;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), call); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1].str();
    const size_t at = static_cast<size_t>(it->position());
    if (at > run && at < finish && std::find(in_run.begin(), in_run.end(), name) == in_run.end()) {
      in_run.push_back(name);
    }
    EXPECT_NE(tick.find("`board." + name + "`"), std::string::npos) << "the scheduler calls board." << name;
    ++named;
  }
  EXPECT_GE(named, 10u) << "the scheduler's calls were read";
  ASSERT_GE(in_run.size(), 8u);
  for (size_t i = 1; i < in_run.size(); ++i) {
    EXPECT_LT(tick.find("`board." + in_run[i - 1] + "`"), tick.find("`board." + in_run[i] + "`"))
        << "the tick calls board." << in_run[i - 1] << " before board." << in_run[i];
  }
}

// The task table's rows go by number, not by the order they run in: the page names each task whose
// number is out of its place in a mode's run ("the vertical task (13)"), with its number.
TEST(ArchitectureDocument, TheTasksNumberedOutOfTheirRunAreNamed) {
  std::set<std::string> out_of_place;
  for (uint8_t set = 0; set < Firmware::kSetCount; ++set) {
    const TaskSet tasks = Firmware::task_set(set);
    for (uint8_t i = 0; i < tasks.count; ++i) {
      for (uint8_t j = static_cast<uint8_t>(i + 1); j < tasks.count; ++j) {
        if (tasks.ids[j] < tasks.ids[i]) out_of_place.insert(wire::kTaskNames[tasks.ids[i]]);
      }
    }
  }
  const std::string text = joined(section("The task table"));
  const std::regex claim(R"(the ([a-z_]+) task \((\d+)\))");
  std::set<std::string> named;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), claim); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1].str();
    const size_t number = std::stoul((*it)[2].str());
    ASSERT_LT(number, size_t{wire::kTaskCount}) << name;
    EXPECT_EQ(name, wire::kTaskNames[number]) << "the page numbers the " << name << " task " << number;
    named.insert(name);
  }
  EXPECT_FALSE(out_of_place.empty()) << "the sets were read";
  EXPECT_EQ(named, out_of_place) << "the tasks that run before a task of a smaller number";
}

// What the chain knows of the core around it: every core header a chain file includes is named in
// "Layers" ("knows the board's interface (`qr/core/board.hpp`), ...").
TEST(ArchitectureDocument, TheChainKnowsWhatThePageSays) {
  const std::string layers = joined(section("Layers"));
  const std::regex include(R"(#include <qr/core/([a-z_]+\.hpp)>)");
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(QR_SOURCE_DIR) / "qr/core/chain")) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp") continue;
    ++files;
    const std::string text = joined(test_support::lines_of(entry.path()));
    for (auto it = std::sregex_iterator(text.begin(), text.end(), include); it != std::sregex_iterator(); ++it) {
      const std::string header = (*it)[1].str();
      const bool named = layers.find("`" + header + "`") != std::string::npos ||
                         layers.find("`qr/core/" + header + "`") != std::string::npos;
      EXPECT_TRUE(named) << entry.path().filename().string() << " includes qr/core/" << header;
    }
  }
  EXPECT_GT(files, 10u) << "the chain's files were read";
}

// "Where the flight's jobs live" gives every file of qr/core/ (the chain's folder apart) a row.
TEST(ArchitectureDocument, TheJobsTableNamesEveryFileOfTheCore) {
  const std::string jobs = joined(section("Where the flight's jobs live"));
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(QR_SOURCE_DIR) / "qr/core")) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".hpp" && ext != ".cpp")) continue;
    ++files;
    const std::string name = entry.path().filename().string();
    const bool named = jobs.find("`" + name + "`") != std::string::npos ||
                       jobs.find("`qr/core/" + name + "`") != std::string::npos;
    EXPECT_TRUE(named) << "qr/core/" << name << " has no row";
  }
  EXPECT_GT(files, 20u) << "the core's files were read";
}

// "One door": the safety machine changes its mode in one place (enter(), which records it), and the
// flight asks what was entered in one place (Flight::change_modes, the door).
TEST(ArchitectureDocument, TheModeChangesAtOneDoor) {
  const fs::path core = fs::path(QR_SOURCE_DIR) / "qr/core";
  const std::string safety = test_support::code_of(core / "safety.hpp") + test_support::code_of(core / "safety.cpp");
  const std::regex assignment(R"((^|[;{})])\s*mode_\s*=[^=])");
  const auto assignments = std::distance(std::sregex_iterator(safety.begin(), safety.end(), assignment),
                                         std::sregex_iterator());
  EXPECT_EQ(assignments, 1) << "the mode is set in enter() alone";
  const size_t enter = safety.find("void enter(Mode to) {");
  ASSERT_NE(enter, std::string::npos);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(safety, m, assignment));
  EXPECT_LT(static_cast<size_t>(m.position()) - enter, 40u) << "the assignment is enter()'s";

  std::vector<std::string> askers;
  for (const auto& entry : fs::directory_iterator(core)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("flight", 0) != 0) continue;
    const std::string code = test_support::code_of(entry.path());
    for (size_t at = code.find("take_entered()"); at != std::string::npos; at = code.find("take_entered()", at + 1)) {
      // The function the call is in: the last definition before it.
      const size_t door = code.rfind("void change_modes()", at);
      const size_t other = code.rfind("void ", at);
      askers.push_back(door != std::string::npos && door == other ? "change_modes" : name);
    }
  }
  EXPECT_EQ(askers, std::vector<std::string>{"change_modes"})
      << "the flight asks the safety machine what it entered in change_modes() alone";
}

}  // namespace
}  // namespace qr
