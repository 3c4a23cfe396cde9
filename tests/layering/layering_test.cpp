// Arrows only point down (docs/architecture.md, "Layers"). This test reads the source tree: every
// project include and every CMake file, and fails when a layer reaches up or sideways.
//
//   pc            -> tune, common, fixedpoint
//   qr/sim_runner -> qr/boards/sim, qr/host, sim, tune, qr/core (and below)
//   qr/boards/*   -> qr/core (and below); the sim board also -> sim
//   qr/tools      -> qr/host, qr/core (and below)
//   qr/host       -> qr/core (and below)
//   qr/core       -> common, fixedpoint
//   common        -> fixedpoint
//   fixedpoint    -> nothing
//   sim           -> nothing (host physics; it knows no QR)
//   tune          -> common, fixedpoint (autotune's fit and design: host, knows no QR, sim or console)
//   tests         -> anything
//
// qr/host holds what the host programs share (the floating-point number policies of the chain,
// replay), so that neither the simulator's runner nor the tools needs the other. The sim board is
// a board like the others: what flies it (scenarios, scoring, serve mode, qrsim) is the runner's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Layer {
  const char* dir;                   // relative to the source root, without a trailing slash
  std::vector<const char*> may_use;  // besides itself
};

// Who may include whom, and link whom. "cmake" is the build helpers (flags, the RV32 link
// function): they are checked where they are called, and every layer may call them.
const std::vector<Layer> kLayers = {
    {"fixedpoint", {}},
    {"common", {"fixedpoint"}},
    {"qr/core", {"common", "fixedpoint"}},
    {"qr/host", {"qr/core", "common", "fixedpoint"}},
    {"qr/boards/rv32virt", {"qr/core", "common", "fixedpoint"}},
    {"qr/boards/fake", {"qr/core", "common", "fixedpoint"}},
    {"qr/boards/sim", {"sim", "qr/core", "common", "fixedpoint"}},
    {"qr/sim_runner", {"qr/boards/sim", "sim", "qr/host", "tune", "qr/core", "common", "fixedpoint"}},
    {"qr/tools", {"qr/host", "qr/core", "common", "fixedpoint"}},
    {"qr", {}},  // the umbrella CMakeLists.txt only
    {"sim", {}},
    {"tune", {"common", "fixedpoint"}},
    {"pc", {"tune", "common", "fixedpoint"}},
    {"tests",
     {"fixedpoint", "common", "qr/core", "qr/host", "qr/boards/rv32virt", "qr/boards/fake", "qr/boards/sim",
      "qr/sim_runner", "qr/tools", "qr", "sim", "tune", "pc"}},
    {"cmake", {}},
};

// The first path component of every project header and of every folder this test reads.
const std::set<std::string> kRoots = {"fixedpoint", "common", "qr", "sim", "tune", "pc", "tests", "cmake"};

// The layer a path (relative to the source root) belongs to: the longest layer folder holding
// it, or "" when none does (the root's own files, scripts/, docs/).
std::string layer_of(const std::string& path) {
  std::string best;
  for (const Layer& layer : kLayers) {
    const std::string dir = layer.dir;
    if ((path == dir || path.rfind(dir + "/", 0) == 0) && dir.size() > best.size()) best = dir;
  }
  return best;
}

bool may_use(const std::string& from, const std::string& to) {
  if (from == to || to == "cmake") return true;
  for (const Layer& layer : kLayers) {
    if (from != layer.dir) continue;
    return std::any_of(layer.may_use.begin(), layer.may_use.end(), [&](const char* d) { return to == d; });
  }
  return false;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream all;
  all << in.rdbuf();
  return all.str();
}

// The project headers a source includes, as paths relative to the root. `<X>` is ours when X
// starts with one of our folders; `"X"` is taken relative to the including file's folder (`dir`,
// relative to the root), and is ours when it lands inside the tree.
std::vector<std::string> project_includes(const std::string& text, const std::string& dir) {
  static const std::regex include(R"(^[ \t]*#[ \t]*include[ \t]*([<"])([^>"]+)[>"])");
  std::vector<std::string> found;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, include)) continue;
    const std::string name = m[2].str();
    if (m[1].str() == "<") {
      const std::string first = name.substr(0, name.find('/'));
      if (name.find('/') != std::string::npos && kRoots.count(first) != 0) found.push_back(name);
    } else {
      const std::string resolved = (fs::path(dir) / name).lexically_normal().generic_string();
      if (resolved.rfind("../", 0) != 0) found.push_back(resolved);
    }
  }
  return found;
}

bool is_source(const fs::path& p) {
  const std::string name = p.filename().string();
  for (const char* ext : {".hpp", ".cpp", ".h", ".c", ".S", ".hpp.in", ".cpp.in"}) {
    const std::string e = ext;
    if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0) return true;
  }
  return false;
}

bool is_cmake(const fs::path& p) { return p.filename() == "CMakeLists.txt" || p.extension() == ".cmake"; }

// Every file under the layer folders (build trees and hidden folders are not under them).
std::vector<std::string> tree_files(bool (*wanted)(const fs::path&)) {
  std::vector<std::string> files;
  const fs::path root = QR_SOURCE_DIR;
  if (wanted(root / "CMakeLists.txt")) files.push_back("CMakeLists.txt");
  for (const std::string& top : kRoots) {
    if (!fs::is_directory(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (entry.is_regular_file() && wanted(entry.path())) {
        files.push_back(entry.path().lexically_relative(root).generic_string());
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// ---- CMake, read as commands ----

struct Command {
  std::string name;
  std::vector<std::string> args;
};

// The commands of a CMake file with comments dropped and quotes removed from arguments. Enough
// CMake for our own files: `name(args)` with quoted strings and nested parentheses.
std::vector<Command> cmake_commands(const std::string& text) {
  std::vector<Command> commands;
  size_t i = 0;
  const size_t n = text.size();
  auto skip_comment = [&] {
    while (i < n && text[i] != '\n') ++i;
  };
  while (i < n) {
    const char c = text[i];
    if (c == '#') {
      skip_comment();
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      size_t j = i;
      while (j < n && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
      std::string name = text.substr(i, j - i);
      size_t k = j;
      while (k < n && (text[k] == ' ' || text[k] == '\t')) ++k;
      if (k >= n || text[k] != '(') {
        i = j;
        continue;
      }
      Command cmd{name, {}};
      std::string arg;
      int depth = 1;
      bool in_arg = false;
      for (i = k + 1; i < n && depth > 0; ++i) {
        const char d = text[i];
        if (d == '"') {
          in_arg = true;
          for (++i; i < n && text[i] != '"'; ++i) {
            if (text[i] == '\\' && i + 1 < n) ++i;
            arg += text[i];
          }
        } else if (d == '#') {
          skip_comment();
        } else if (d == '(' || d == ')') {
          depth += d == '(' ? 1 : -1;
          if (depth > 0) {
            arg += d;
            in_arg = true;
          }
        } else if (std::isspace(static_cast<unsigned char>(d))) {
          if (in_arg && depth == 1) {
            cmd.args.push_back(arg);
            arg.clear();
            in_arg = false;
          } else if (in_arg) {
            arg += d;
          }
          continue;
        } else {
          arg += d;
          in_arg = true;
        }
        if (depth == 0 && in_arg) cmd.args.push_back(arg);
      }
      std::transform(cmd.name.begin(), cmd.name.end(), cmd.name.begin(), ::tolower);
      commands.push_back(cmd);
    } else {
      ++i;
    }
  }
  return commands;
}

// The text of a CMake file without its comments (quoted strings kept).
std::string cmake_without_comments(const std::string& text) {
  std::string out;
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"' && (i == 0 || text[i - 1] != '\\')) quoted = !quoted;
    if (c == '#' && !quoted) {
      while (i < text.size() && text[i] != '\n') ++i;
      out += '\n';
      continue;
    }
    out += c;
  }
  return out;
}

struct CMakeFile {
  std::string path;
  std::string layer;
  std::vector<Command> commands;
};

std::vector<CMakeFile> all_cmake_files() {
  std::vector<CMakeFile> files;
  for (const std::string& path : tree_files(is_cmake)) {
    files.push_back({path, layer_of(path), cmake_commands(read_text(fs::path(QR_SOURCE_DIR) / path))});
  }
  return files;
}

// A function of ours that makes a target from its first argument, and what it links it to.
struct TargetFunction {
  std::vector<std::string> links;
};

struct Model {
  std::map<std::string, std::string> target_layer;  // every library and program of ours
  std::map<std::string, TargetFunction> functions;  // functions that make targets
};

bool is_link_keyword(const std::string& a) {
  return a == "PUBLIC" || a == "PRIVATE" || a == "INTERFACE" || a == "LINK_PUBLIC" || a == "LINK_PRIVATE";
}

Model build_model(const std::vector<CMakeFile>& files) {
  Model model;
  for (const CMakeFile& file : files) {
    for (size_t i = 0; i < file.commands.size(); ++i) {
      const Command& c = file.commands[i];
      if (c.name != "function" || c.args.size() < 2) continue;
      const std::string param = "${" + c.args[1] + "}";
      bool makes_target = false;
      TargetFunction fn;
      for (size_t j = i + 1; j < file.commands.size() && file.commands[j].name != "endfunction"; ++j) {
        const Command& body = file.commands[j];
        if ((body.name == "add_library" || body.name == "add_executable") && !body.args.empty() &&
            body.args[0] == param) {
          makes_target = true;
        }
        if (body.name == "target_link_libraries" && !body.args.empty() && body.args[0] == param) {
          for (size_t k = 1; k < body.args.size(); ++k) fn.links.push_back(body.args[k]);
        }
      }
      if (makes_target) model.functions[c.args[0]] = fn;
    }
  }
  for (const CMakeFile& file : files) {
    for (const Command& c : file.commands) {
      if (c.args.empty() || c.args[0].find("${") != std::string::npos) continue;
      if (c.name == "add_library" || c.name == "add_executable" || model.functions.count(c.name) != 0) {
        model.target_layer[c.args[0]] = file.layer;
      }
    }
  }
  return model;
}

// What a CMake file of a layer links: every target_link_libraries item, and what the helper
// functions it calls link for it (qr_rv32_executable links the devboard runtime).
std::vector<std::string> links_of(const CMakeFile& file, const Model& model) {
  std::vector<std::string> links;
  for (const Command& c : file.commands) {
    if (c.name == "target_link_libraries") {
      for (size_t k = 1; k < c.args.size(); ++k) links.push_back(c.args[k]);
    }
    const auto fn = model.functions.find(c.name);
    if (fn != model.functions.end()) links.insert(links.end(), fn->second.links.begin(), fn->second.links.end());
  }
  return links;
}

bool is_production(const std::string& path) { return path.rfind("tests/", 0) != 0; }

// ---- the checker itself, on made-up input, so that a green tree means something ----

TEST(Layering, TableSaysWhoMayUseWhom) {
  EXPECT_EQ(layer_of("qr/core/chain/flight_chain.hpp"), "qr/core");
  EXPECT_EQ(layer_of("qr/boards/sim/sim_board.hpp"), "qr/boards/sim");
  EXPECT_EQ(layer_of("sim/world.hpp"), "sim");
  EXPECT_EQ(layer_of("fixedpoint/detail/raw.hpp"), "fixedpoint");
  EXPECT_EQ(layer_of("scripts/devboard"), "");
  EXPECT_TRUE(may_use("qr/core", "common"));
  EXPECT_TRUE(may_use("qr/core", "qr/core"));
  EXPECT_TRUE(may_use("qr/boards/sim", "sim"));
  EXPECT_TRUE(may_use("pc", "fixedpoint"));
  EXPECT_FALSE(may_use("fixedpoint", "common"));
  EXPECT_FALSE(may_use("fixedpoint", "qr/boards/rv32virt"));
  EXPECT_FALSE(may_use("common", "qr/core"));
  EXPECT_FALSE(may_use("qr/core", "qr/boards/rv32virt"));
  EXPECT_FALSE(may_use("qr/boards/sim", "qr/tools"));
  EXPECT_FALSE(may_use("qr/boards/sim", "qr/sim_runner"));
  EXPECT_FALSE(may_use("qr/boards/sim", "qr/host"));
  EXPECT_TRUE(may_use("qr/sim_runner", "qr/boards/sim"));
  EXPECT_EQ(layer_of("qr/sim_runner/scenario.hpp"), "qr/sim_runner");
  EXPECT_FALSE(may_use("qr/boards/rv32virt", "sim"));
  EXPECT_FALSE(may_use("sim", "qr/core"));
  EXPECT_FALSE(may_use("pc", "qr/core"));
  EXPECT_FALSE(may_use("pc", "sim"));
  EXPECT_TRUE(may_use("tune", "common"));
  EXPECT_TRUE(may_use("qr/sim_runner", "tune"));
  EXPECT_FALSE(may_use("tune", "qr/core"));
  EXPECT_FALSE(may_use("tune", "sim"));
  EXPECT_FALSE(may_use("tune", "pc"));
  EXPECT_FALSE(may_use("common", "tune"));
  EXPECT_FALSE(may_use("qr/core", "tune"));
  EXPECT_FALSE(may_use("qr/host", "qr/tools"));
}

TEST(Layering, IncludeReaderFindsOurHeadersInBothSpellings) {
  const std::string text =
      "#include <stdint.h>\n"
      "#include <fixedpoint/q.hpp>\n"
      "  #  include <common/messages.hpp>\n"
      "#include <gtest/gtest.h>\n"
      "#include \"../chain/flight_chain.hpp\"\n"
      "#include \"local.hpp\"\n"
      "// #include <qr/boards/sim/not_code.hpp> is prose\n";
  const std::vector<std::string> expected = {"fixedpoint/q.hpp", "common/messages.hpp",
                                             "qr/core/chain/flight_chain.hpp", "qr/core/x/local.hpp"};
  EXPECT_EQ(project_includes(text, "qr/core/x"), expected);
}

TEST(Layering, CMakeReaderSeesCommandsNotComments) {
  const std::string text =
      "# target_link_libraries(a PRIVATE commented_out)\n"
      "target_link_libraries(qr_sim_board PUBLIC qr_sim  # why\n"
      "  qr_chain \"$<TARGET_FILE:x>\")\n"
      "add_test(NAME T COMMAND sh -c \"echo (a) b\")\n";
  const std::vector<Command> commands = cmake_commands(text);
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].name, "target_link_libraries");
  const std::vector<std::string> args = {"qr_sim_board", "PUBLIC", "qr_sim", "qr_chain", "$<TARGET_FILE:x>"};
  EXPECT_EQ(commands[0].args, args);
  EXPECT_EQ(commands[1].args.back(), "echo (a) b");
  EXPECT_EQ(cmake_without_comments("x(tests/a) # tests/b\n"), "x(tests/a) \n");
}

// ---- the tree ----

TEST(Layering, EveryIncludePointsDown) {
  int checked = 0;
  std::set<std::string> layers_seen;
  for (const std::string& file : tree_files(is_source)) {
    const std::string from = layer_of(file);
    ASSERT_FALSE(from.empty()) << file << " is in no layer";
    const std::string dir = fs::path(file).parent_path().generic_string();
    for (const std::string& header : project_includes(read_text(fs::path(QR_SOURCE_DIR) / file), dir)) {
      const std::string to = layer_of(header);
      EXPECT_TRUE(may_use(from, to)) << file << " (" << from << ") includes " << header << " ("
                                     << (to.empty() ? "no layer" : to) << ")";
      if (from != "tests") {
        ++checked;
        layers_seen.insert(from);
      }
    }
  }
  // The walk really read the tree: hundreds of includes, from every production layer.
  EXPECT_GT(checked, 300);
  for (const char* layer : {"fixedpoint", "common", "qr/core", "qr/host", "qr/boards/rv32virt", "qr/boards/sim",
                            "qr/sim_runner", "qr/tools", "sim", "tune", "pc"}) {
    EXPECT_EQ(layers_seen.count(layer), 1u) << "no include read in " << layer;
  }
}

// The signal chain is an algorithm library: of the core around it, it knows the board's
// interface, the rate, the flight's shared types (flight_types.hpp) and the sensor scales, never
// the flight, its tables, the safety machine or the scheduler. Forbidden by name, so that a new
// header of the flight (flight_*.hpp, safety*.hpp, scheduler*.hpp, replay_tick.hpp) is forbidden
// the day it is written.
bool chain_may_not_include(const std::string& header) {
  static const std::regex upward(R"(qr/core/(flight[a-z_]*|safety[a-z_]*|scheduler[a-z_]*|replay_tick|task)\.hpp)");
  return header != "qr/core/flight_types.hpp" && std::regex_match(header, upward);
}

TEST(Layering, TheChainsUpwardIncludesAreForbiddenByName) {
  for (const char* header : {"qr/core/flight.hpp", "qr/core/flight_impl.hpp", "qr/core/flight_tasks.hpp",
                             "qr/core/flight_requests.hpp", "qr/core/flight_new_thing.hpp", "qr/core/safety.hpp",
                             "qr/core/scheduler.hpp", "qr/core/replay_tick.hpp", "qr/core/task.hpp"}) {
    EXPECT_TRUE(chain_may_not_include(header)) << header;
  }
  for (const char* header : {"qr/core/flight_types.hpp", "qr/core/board.hpp", "qr/core/control_rate.hpp",
                             "qr/core/sensor_scale.hpp", "qr/core/chain/flight_chain.hpp", "common/mode.hpp"}) {
    EXPECT_FALSE(chain_may_not_include(header)) << header;
  }
}

TEST(Layering, TheSignalChainKnowsNothingOfTheFlightAroundIt) {
  int checked = 0;
  for (const std::string& file : tree_files(is_source)) {
    if (file.rfind("qr/core/chain/", 0) != 0) continue;
    const std::string dir = fs::path(file).parent_path().generic_string();
    for (const std::string& header : project_includes(read_text(fs::path(QR_SOURCE_DIR) / file), dir)) {
      ++checked;
      EXPECT_FALSE(chain_may_not_include(header)) << file << " includes " << header;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(Layering, ProductionCMakeNamesNoPathUnderTests) {
  const std::regex tests_path(R"((^|[^A-Za-z0-9_.-])tests/)");
  int checked = 0;
  for (const std::string& path : tree_files(is_cmake)) {
    if (!is_production(path)) continue;
    ++checked;
    const std::string code = cmake_without_comments(read_text(fs::path(QR_SOURCE_DIR) / path));
    std::smatch m;
    EXPECT_FALSE(std::regex_search(code, m, tests_path)) << path << " names a path under tests/";
  }
  EXPECT_GE(checked, 10);
}

// Paths into the source tree that a layer's CMake names (${PROJECT_SOURCE_DIR}/X) are its own or
// those of a layer it may use: a build does not reach into another layer's files either.
TEST(Layering, ProductionCMakeNamesOnlyFilesOfLayersBelow) {
  const std::regex source_path(R"(\$\{(?:PROJECT_SOURCE_DIR|CMAKE_SOURCE_DIR)\}/([A-Za-z0-9_./-]+))");
  for (const std::string& path : tree_files(is_cmake)) {
    const std::string from = layer_of(path);
    if (!is_production(path) || from.empty() || from == "cmake") continue;
    const std::string code = cmake_without_comments(read_text(fs::path(QR_SOURCE_DIR) / path));
    for (std::sregex_iterator it(code.begin(), code.end(), source_path), end; it != end; ++it) {
      const std::string named = (*it)[1].str();
      const std::string to = layer_of(named);
      EXPECT_TRUE(!to.empty() && may_use(from, to)) << path << " (" << from << ") names " << named;
    }
  }
}

TEST(Layering, ProductionTargetsLinkOnlyLayersBelow) {
  const std::vector<CMakeFile> files = all_cmake_files();
  const Model model = build_model(files);
  // The model knows our targets, where they are made, and that the RV32 helper links the board.
  for (const auto& [target, layer] : std::map<std::string, std::string>{{"qr_fixedpoint", "fixedpoint"},
                                                                        {"qr_common", "common"},
                                                                        {"qr_core", "qr/core"},
                                                                        {"qr_chain", "qr/core"},
                                                                        {"qr_replay", "qr/host"},
                                                                        {"qr_sim_board", "qr/boards/sim"},
                                                                        {"qr_sim_runner", "qr/sim_runner"},
                                                                        {"qr_filter_tool", "qr/tools"},
                                                                        {"qr_sim", "sim"},
                                                                        {"tune", "tune"}}) {
    ASSERT_EQ(model.target_layer.count(target), 1u) << target;
    EXPECT_EQ(model.target_layer.at(target), layer) << target;
  }
  ASSERT_EQ(model.functions.count("qr_rv32_executable"), 1u);
  const auto& rv32_links = model.functions.at("qr_rv32_executable").links;
  EXPECT_NE(std::find(rv32_links.begin(), rv32_links.end(), "rv32virt_runtime"), rv32_links.end());

  int checked = 0;
  for (const CMakeFile& file : files) {
    if (!is_production(file.path) || file.layer.empty() || file.layer == "cmake") continue;
    for (const std::string& link : links_of(file, model)) {
      if (is_link_keyword(link)) continue;
      const auto target = model.target_layer.find(link);
      if (target == model.target_layer.end()) continue;  // not ours: GTest, ncurses, libgcc
      ++checked;
      EXPECT_TRUE(may_use(file.layer, target->second))
          << file.path << " (" << file.layer << ") links " << link << " (" << target->second << ")";
    }
  }
  EXPECT_GT(checked, 20);
}

// The two arrows issue 13 was about, named: the library at the bottom links and builds nothing of
// ours, and the sim board does not reach sideways into the tools.
TEST(Layering, FixedpointIsAHeaderOnlyLibraryAlone) {
  const std::vector<CMakeFile> files = all_cmake_files();
  const Model model = build_model(files);
  for (const CMakeFile& file : files) {
    if (file.layer != "fixedpoint") continue;
    for (const Command& c : file.commands) {
      EXPECT_NE(c.name, "target_link_libraries") << file.path;
      EXPECT_NE(c.name, "add_executable") << file.path;
      EXPECT_EQ(model.functions.count(c.name), 0u) << file.path << " calls " << c.name;
      EXPECT_NE(c.name, "add_test") << file.path;
    }
  }
  for (const std::string& file : tree_files(is_source)) {
    if (layer_of(file) != "fixedpoint") continue;
    EXPECT_EQ(fs::path(file).extension(), ".hpp") << file << ": fixedpoint/ is header-only";
  }
}

TEST(Layering, SimBoardDoesNotLinkTheTools) {
  const std::vector<CMakeFile> files = all_cmake_files();
  const Model model = build_model(files);
  int sim_board_links = 0;
  for (const CMakeFile& file : files) {
    for (const Command& c : file.commands) {
      if (c.name != "target_link_libraries" || c.args.empty() || c.args[0] != "qr_sim_board") continue;
      for (size_t k = 1; k < c.args.size(); ++k) {
        const auto target = model.target_layer.find(c.args[k]);
        if (target == model.target_layer.end()) continue;
        ++sim_board_links;
        EXPECT_NE(target->second, "qr/tools") << "qr_sim_board links " << c.args[k];
      }
    }
  }
  EXPECT_GE(sim_board_links, 3);
}

}  // namespace
