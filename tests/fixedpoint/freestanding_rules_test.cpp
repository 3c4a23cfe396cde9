// The freestanding rules for fixedpoint/ (docs/architecture.md, "Layers"), as tests/common and
// tests/chain check them for their folders: only <stdint.h>, <stddef.h> and the library's own
// headers; no heap, exceptions, RTTI, virtual dispatch or standard library; header-only. Floating
// point is not banned here: constants are made from double literals at compile time, the float
// overloads serve the float number policy, and the misuse tests (compile_fail/) keep doubles out of
// run time.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "../support/source_text.hpp"

namespace {

using test_support::code_of;

TEST(FixedpointFreestandingRules, LibraryUsesOnlyAllowedHeadersAndNoForbiddenFeatures) {
  const std::regex include(R"(#include\s*<([^>]+)>)");
  const std::regex forbidden(R"(\b(new|delete|malloc|free|memcpy|virtual|throw|try|catch|typeid|dynamic_cast|std)\b)");
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(QR_FIXEDPOINT_DIR)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    const std::string name = entry.path().lexically_relative(QR_FIXEDPOINT_DIR).generic_string();
    EXPECT_NE(ext, ".cpp") << name << ": the library is header-only";
    if (ext != ".hpp" && ext != ".cpp") continue;
    ++files;
    const std::string code = code_of(entry.path());
    for (std::sregex_iterator it(code.begin(), code.end(), include), end; it != end; ++it) {
      const std::string header = (*it)[1].str();
      EXPECT_TRUE(header == "stdint.h" || header == "stddef.h" || header.rfind("fixedpoint/", 0) == 0)
          << name << " includes <" << header << ">";
    }
    EXPECT_EQ(code.find("#include \""), std::string::npos) << name << " includes by a relative path";
    std::smatch m;
    EXPECT_FALSE(std::regex_search(code, m, forbidden)) << name << " uses '" << m.str() << "'";
  }
  EXPECT_GE(files, 12);
}

}  // namespace
