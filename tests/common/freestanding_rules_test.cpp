// The freestanding rules for common/ (docs/architecture.md, "Layers"): only <stdint.h>,
// <stddef.h> and project headers; no heap, no exceptions, no RTTI, no virtual dispatch, no floating
// point, no memcpy of structs. The compiler flags catch some of this; this test reads the sources
// for the rest (drivers/ too).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "../support/source_text.hpp"

using test_support::code_of;

TEST(FreestandingRules, CommonUsesOnlyAllowedHeadersAndNoForbiddenFeatures) {
  const std::regex include(R"(#include\s*<([^>]+)>)");
  const std::regex forbidden(
      R"(\b(float|double|new|delete|malloc|free|memcpy|virtual|throw|try|catch|typeid|dynamic_cast|std)\b)");
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(QR_COMMON_DIR)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp") continue;
    ++files;
    const std::string code = code_of(entry.path());
    for (std::sregex_iterator it(code.begin(), code.end(), include), end; it != end; ++it) {
      const std::string header = (*it)[1].str();
      EXPECT_TRUE(header == "stdint.h" || header == "stddef.h" || header.rfind("common/", 0) == 0)
          << entry.path().filename() << " includes <" << header << ">";
    }
    std::smatch m;
    EXPECT_FALSE(std::regex_search(code, m, forbidden)) << entry.path().filename() << " uses '" << m.str() << "'";
  }
  EXPECT_GT(files, 10);
}
