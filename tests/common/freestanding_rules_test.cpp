// The freestanding rules for common/ (DESIGN.md): only <stdint.h>, <stddef.h> and project
// headers; no heap, no exceptions, no RTTI, no virtual dispatch, no floating point, no memcpy of
// structs. The compiler flags catch some of this; this test reads the sources for the rest.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

// The source without comments and string literals, so prose may mention what code may not use.
std::string code_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  std::string code;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
      code += '\n';
    } else if (text[i] == '"') {
      code += "\"\"";
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\') ++i;
      }
    } else {
      code += text[i];
    }
  }
  return code;
}

}  // namespace

TEST(FreestandingRules, CommonUsesOnlyAllowedHeadersAndNoForbiddenFeatures) {
  const std::regex include(R"(#include\s*<([^>]+)>)");
  const std::regex forbidden(R"(\b(float|double|new|delete|malloc|free|memcpy|virtual|throw|try|catch|typeid|dynamic_cast|std)\b)");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(QR_COMMON_DIR)) {
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
