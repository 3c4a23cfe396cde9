// Every file of the project that a source names exists: a file moved or deleted leaves no
// comment, include, CMake line or script behind that still names it, and a page cited (with its
// section) is one of the project's own (docs/, README.md), with that section.
//
// Read: every .hpp .cpp .h .c .S .cmake .in file and CMakeLists.txt under fixedpoint/ common/ qr/
// sim/ tune/ pc/ tests/ cmake/ scripts/, and every script in scripts/. Checked:
//   - a path from a top folder of the tree (those above, or docs/) that ends in a file's extension
//     or in '/' (a folder), or names one of the scripts (scripts/ has no extensions): it exists;
//   - in CMake, ${CMAKE_CURRENT_SOURCE_DIR}/PATH: it exists beside the CMakeLists.txt;
//   - a page named by its file name (safety.md, docs/safety.md): a page of docs/, or a README.md
//     (the root's, or that of the top folder the file is in);
//   - a page's section, as `simulator.md, "Scenarios"` or `simulator.md section 6.2`: a heading of
//     the page (or a paragraph's bold lead) has that title or number.
// A path inside a longer one (build/release/qr/qrsim, ${CMAKE_BINARY_DIR}/qr/...) is build output,
// not the tree's, and is not checked; nor are the CMake-generated sources, which only the build
// folder has (builtin_scenarios.cpp, default_vehicle.cpp: named there without a top folder).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kTopFolders = {"fixedpoint", "common", "qr",    "sim",     "tune",
                                              "pc",         "tests",  "cmake", "scripts", "docs"};
const std::set<std::string> kFileExtensions = {".hpp", ".cpp",   ".h",  ".c",    ".S",  ".md", ".txt",
                                               ".sh",  ".cmake", ".py", ".json", ".ld", ".in", ".csv"};

// Paths that are not meant to exist, each with its reason: made-up paths in a test's own strings.
struct MadeUp {
  const char* file;
  const char* path;
  const char* why;
};
constexpr MadeUp kMadeUp[] = {
    {"tests/layering/layering_test.cpp", "qr/boards/sim/not_code.hpp",
     "a commented-out include the include reader must skip"},
    {"tests/layering/layering_test.cpp", "qr/core/x/local.hpp",
     "a quoted include of a made-up folder, resolved by the include reader"},
    {"tests/layering/layering_test.cpp", "qr/core/flight_new_thing.hpp",
     "a flight header not written yet, which the chain may not include"},
    {"tests/layering/comment_paths_test.cpp", "qr/core/gone.hpp", "the reader's own test lines below"},
    {"tests/layering/comment_paths_test.cpp", "docs/gone.md", "the reader's own test lines below"},
    {"tests/layering/comment_paths_test.cpp", "gone.md", "the reader's own test lines below"},
};

// This file names each of them in the table above.
bool made_up(const std::string& file, const std::string& path) {
  return std::any_of(std::begin(kMadeUp), std::end(kMadeUp), [&](const MadeUp& m) {
    return (file == m.file || file == "tests/layering/comment_paths_test.cpp") && path == m.path;
  });
}

bool path_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
         c == '/' || c == '-' || c == '+';
}

// The project paths a line names: each starts at a top folder (not inside a longer path, unless
// that is ${PROJECT_SOURCE_DIR}/ or ${CMAKE_SOURCE_DIR}/), and is kept when it ends in a file's
// extension or '/', or names a script. Trailing punctuation of the prose is not the path's.
std::vector<std::string> project_paths(const std::string& line) {
  std::vector<std::string> paths;
  for (const std::string& top : kTopFolders) {
    const std::string start = top + "/";
    for (size_t at = line.find(start); at != std::string::npos; at = line.find(start, at + 1)) {
      if (at > 0) {
        const std::string before = line.substr(0, at);
        const bool from_root = before.ends_with("{PROJECT_SOURCE_DIR}/") || before.ends_with("{CMAKE_SOURCE_DIR}/");
        if (path_char(before.back()) && !from_root) continue;
      }
      size_t end = at;
      while (end < line.size() && path_char(line[end])) ++end;
      std::string path = line.substr(at, end - at);
      while (!path.empty() && (path.back() == '.' || path.back() == '-')) path.pop_back();
      const std::string ext = fs::path(path).extension().string();
      const bool script = top == "scripts" && path.find('/', start.size()) == std::string::npos &&
                          path.size() > start.size() && ext.empty();
      if (path.back() == '/' || kFileExtensions.count(ext) != 0 || script) paths.push_back(path);
    }
  }
  return paths;
}

// The pages a line names by their file name (safety.md, docs/safety.md), and the sections it cites
// of them: {page, "Title"} or {page, "6.2"}.
struct PageCitation {
  std::string page;
  std::string section;  // empty: the page alone
};
std::vector<PageCitation> page_citations(const std::string& line) {
  static const std::regex page(
      R"((^|[^A-Za-z0-9_./-])(docs/)?([A-Za-z0-9_-]+\.md)\b(\)|`)?(,? \"([^\"]+)\"|,? sections? (\d+(\.\d+)*))?)");
  std::vector<PageCitation> out;
  for (auto it = std::sregex_iterator(line.begin(), line.end(), page); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out.push_back({m[3].str(), m[6].matched ? m[6].str() : m[7].str()});
  }
  return out;
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The sources the test reads, relative to the root.
std::vector<std::string> sources() {
  const fs::path root = QR_SOURCE_DIR;
  static const std::set<std::string> kSourceExtensions = {".hpp", ".cpp", ".h", ".c", ".S", ".cmake", ".in"};
  std::vector<std::string> out;
  for (const std::string& top : kTopFolders) {
    if (top == "docs") continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (!entry.is_regular_file()) continue;
      const fs::path& p = entry.path();
      const bool script = top == "scripts" && p.parent_path() == root / "scripts";
      if (kSourceExtensions.count(p.extension().string()) != 0 || p.filename() == "CMakeLists.txt" || script) {
        out.push_back(fs::relative(p, root).generic_string());
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(CommentPaths, TheReaderFindsThePathsOfALine) {
  EXPECT_EQ(project_paths("// moved to qr/core/replay_tick.hpp, see docs/architecture.md."),
            (std::vector<std::string>{"qr/core/replay_tick.hpp", "docs/architecture.md"}));
  EXPECT_EQ(project_paths("(qr/boards/sim/), scripts/devboard --bench, qr/core/flight*.hpp, sim/world"),
            (std::vector<std::string>{"qr/boards/sim/", "scripts/devboard"}));
  EXPECT_TRUE(
      project_paths("build/release/qr/qrsim.cpp ${CMAKE_BINARY_DIR}/qr/x.cpp tests/qr/safety-rule-tests").empty());
  EXPECT_EQ(project_paths("  ${PROJECT_SOURCE_DIR}/docs/gone.md"), (std::vector<std::string>{"docs/gone.md"}));
  EXPECT_EQ(project_paths("#include <qr/core/gone.hpp>"), (std::vector<std::string>{"qr/core/gone.hpp"}));
  const std::vector<PageCitation> cited = page_citations(
      "(gone.md, \"Layers\"), [safety.md](safety.md) rule 3, docs/simulator.md section 6.2, build/x.md");
  ASSERT_EQ(cited.size(), 4u);
  EXPECT_EQ(cited[0].page, "gone.md");
  EXPECT_EQ(cited[0].section, "Layers");
  EXPECT_EQ(cited[1].page, "safety.md");
  EXPECT_EQ(cited[2].section, "");
  EXPECT_EQ(cited[3].page, "simulator.md");
  EXPECT_EQ(cited[3].section, "6.2");
}

TEST(CommentPaths, EveryProjectPathNamedExists) {
  const fs::path root = QR_SOURCE_DIR;
  size_t checked = 0;
  for (const std::string& file : sources()) {
    const std::vector<std::string> lines = lines_of(read(root / file));
    const bool cmake = fs::path(file).filename() == "CMakeLists.txt" || fs::path(file).extension() == ".cmake";
    static const std::regex current(R"(\$\{CMAKE_CURRENT_SOURCE_DIR\}/([A-Za-z0-9_./+-]+))");
    for (size_t i = 0; i < lines.size(); ++i) {
      for (const std::string& path : project_paths(lines[i])) {
        ++checked;
        if (made_up(file, path)) continue;
        EXPECT_TRUE(fs::exists(root / path)) << file << ":" << i + 1 << ": " << path << " is not in the tree";
      }
      if (!cmake) continue;
      for (auto it = std::sregex_iterator(lines[i].begin(), lines[i].end(), current); it != std::sregex_iterator();
           ++it) {
        ++checked;
        const fs::path beside = (root / file).parent_path() / (*it)[1].str();
        EXPECT_TRUE(fs::exists(beside)) << file << ":" << i + 1 << ": " << (*it)[1].str() << " is not beside it";
      }
    }
  }
  EXPECT_GT(checked, 1000u) << "the sources were read";
}

// The project's files speak of the project: a page they cite is one of its own.
TEST(CommentPaths, EveryPageCitedIsTheProjectsWithItsSection) {
  const fs::path root = QR_SOURCE_DIR;
  size_t checked = 0;
  for (const std::string& file : sources()) {
    const std::vector<std::string> lines = lines_of(read(root / file));
    for (size_t i = 0; i < lines.size(); ++i) {
      for (const PageCitation& cited : page_citations(lines[i])) {
        if (made_up(file, cited.page)) continue;
        fs::path page = root / "docs" / cited.page;
        if (cited.page == "README.md") {
          const fs::path own = root / fs::path(file).begin()->string() / "README.md";
          page = fs::exists(own) ? own : root / "README.md";
        }
        ++checked;
        if (!fs::exists(page)) {
          ADD_FAILURE() << file << ":" << i + 1 << ": " << cited.page << " is not a page of the project";
          continue;
        }
        if (cited.section.empty()) continue;
        bool found = false;
        for (const std::string& heading : lines_of(read(page))) {
          if (heading.rfind("#", 0) != 0 && heading.rfind("**", 0) != 0) continue;
          const size_t text = heading.find_first_not_of("#* ");
          if (text == std::string::npos) continue;
          const std::string title = heading.substr(text);
          const bool numbered = title.rfind(cited.section, 0) == 0 && title.size() > cited.section.size() &&
                                (title[cited.section.size()] == ' ' || title[cited.section.size()] == '.');
          found = found || numbered || title.find(cited.section) != std::string::npos;
        }
        EXPECT_TRUE(found) << file << ":" << i + 1 << ": " << cited.page << " has no section \"" << cited.section
                           << "\"";
      }
    }
  }
  EXPECT_GT(checked, 100u) << "the sources were read";
}

}  // namespace
