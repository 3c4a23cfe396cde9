// No function in pc/ or qr/ is longer than 80 lines (issue 31): a function that long is doing more
// than one thing. The longest of each are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "function_spans.hpp"

namespace {

namespace fs = std::filesystem;
using qrterm_test::function_spans;
using qrterm_test::FunctionSpan;

constexpr size_t kMaxFunctionLines = 80;

struct Measured {
  std::string file;  // relative to the source root
  FunctionSpan span;
};

// Every function of the C++ files under `folder` (relative to the source root), longest first.
std::vector<Measured> measure(const std::string& folder) {
  std::vector<Measured> all;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(QR_SOURCE_DIR) / folder)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string file = fs::relative(entry.path(), QR_SOURCE_DIR).string();
    for (const FunctionSpan& span : function_spans(text.str())) all.push_back({file, span});
  }
  std::sort(all.begin(), all.end(), [](const Measured& a, const Measured& b) {
    return a.span.lines() != b.span.lines() ? a.span.lines() > b.span.lines() : a.file < b.file;
  });
  return all;
}

std::string describe(const Measured& m) {
  return std::to_string(m.span.lines()) + " lines  " + m.file + ":" + std::to_string(m.span.first_line) + "  " +
         m.span.name;
}

void print_longest(const char* folder, const std::vector<Measured>& all, size_t count) {
  std::cout << "longest functions in " << folder << "/:\n";
  for (size_t i = 0; i < std::min(count, all.size()); ++i) std::cout << "  " << describe(all[i]) << "\n";
}

size_t lines_of(const std::string& source, const std::string& name) {
  for (const FunctionSpan& span : function_spans(source)) {
    if (span.name == name) return span.lines();
  }
  return 0;
}

TEST(Layering, NoFunctionOver80Lines) {
  for (const char* folder : {"pc", "qr"}) {
    const std::vector<Measured> all = measure(folder);
    ASSERT_GT(all.size(), 100u) << "the reader found too few functions in " << folder << "/ to be reading it";
    print_longest(folder, all, 8);
    for (const Measured& m : all) EXPECT_LE(m.span.lines(), kMaxFunctionLines) << describe(m);
  }
}

TEST(FunctionLengths, CountsFromTheDeclarationToTheClosingBrace) {
  const std::string source =
      "namespace a {\n"
      "template <class T>\n"
      "int f(T t) {\n"
      "  return t;\n"
      "}\n"
      "}  // namespace a\n";
  const std::vector<FunctionSpan> spans = function_spans(source);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].name, "f");
  EXPECT_EQ(spans[0].first_line, 2u);
  EXPECT_EQ(spans[0].last_line, 5u);
}

TEST(FunctionLengths, BracesInCommentsStringsAndDirectivesDoNotCount) {
  const std::string source =
      "#define OPEN {\n"
      "void f() {  // }\n"
      "  const char* s = \"}\";\n"
      "  char c = '}';\n"
      "  /* } */ int n = 1'000;\n"
      "  const char* r = R\"x(})x\";\n"
      "}\n"
      "void g() {}\n";
  EXPECT_EQ(lines_of(source, "f"), 6u);
  EXPECT_EQ(lines_of(source, "g"), 1u);
}

TEST(FunctionLengths, AConstructorsBracedInitialisersAreNotItsBody) {
  const std::string source =
      "Console::Console(int a)\n"
      "    : a_{a}, hooks_(Hooks{[this](int x) { use(x); }}),\n"
      "      b_(1) {\n"
      "  start();\n"
      "}\n";
  const std::vector<FunctionSpan> spans = function_spans(source);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].name, "Console::Console");
  EXPECT_EQ(spans[0].lines(), 5u);
}

TEST(FunctionLengths, MembersOfClassesAreFunctionsTablesAndInitialisersAreNot) {
  const std::string source =
      "struct Receiver {\n"
      " public:\n"
      "  void operator()(const Ack& ack) { answer(ack); }\n"
      "  bool ok() const {\n"
      "    return true;\n"
      "  }\n"
      "  int table_[2] = {1, 2};\n"
      "  LineReader out_{-1};\n"
      "  std::function<void()> hook{[] { a(); }};\n"
      "  enum class E { a, b };\n"
      "};\n"
      "constexpr Row kRows[] = {{1, \"a\"}, {2, \"b\"}};\n"
      "const auto f = [](int x) { return x; };\n";
  const std::vector<FunctionSpan> spans = function_spans(source);
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0].name, "operator()");
  EXPECT_EQ(spans[0].lines(), 1u);
  EXPECT_EQ(spans[1].name, "ok");
  EXPECT_EQ(spans[1].lines(), 3u);
}

TEST(FunctionLengths, LambdasAndBlocksInsideAFunctionAreItsLines) {
  const std::string source =
      "void Console::tick(uint32_t now_ms) {\n"
      "  const auto f = [&](int x) {\n"
      "    if (x) { return 1; }\n"
      "    return 0;\n"
      "  };\n"
      "  struct Local { int g() { return 2; } };\n"
      "}\n";
  const std::vector<FunctionSpan> spans = function_spans(source);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].name, "Console::tick");
  EXPECT_EQ(spans[0].lines(), 7u);
}

}  // namespace
