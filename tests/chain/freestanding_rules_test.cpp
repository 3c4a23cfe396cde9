// The freestanding rules for qr/core/chain (docs/architecture.md, "Layers"): only <stdint.h>,
// <stddef.h> and project headers; no heap, exceptions, RTTI, virtual dispatch or standard library.
// Floating point is allowed only where it becomes constants at compile time, which the compiler
// cannot tell from here: the rv32 ELF check (ChainDevboard.FlightChainHasNoSoftFloat) proves none
// reaches run time, so this test only keeps `float` out and `double` to the design and constant
// files.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "../support/source_text.hpp"

namespace {

using test_support::code_of;

TEST(ChainFreestandingRules, ChainUsesOnlyAllowedHeadersAndNoForbiddenFeatures) {
  const std::regex include(R"(#include\s*<([^>]+)>)");
  const std::regex forbidden(
      R"(\b(float|new|delete|malloc|free|memcpy|virtual|throw|try|catch|typeid|dynamic_cast|std)\b)");
  const std::regex double_word(R"(\bdouble\b)");
  // Where double may appear: the compile-time design, and the constexpr constants of the blocks
  // (Q(0.35) style constants take a double literal).
  const std::set<std::string> design_files = {"design_math.hpp",         "butterworth_design.hpp",
                                              "butterworth_lowpass.hpp", "butterworth_table.hpp",
                                              "pilot_setpoints.hpp",     "isa_table.hpp"};
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(QR_CHAIN_DIR)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp") continue;
    ++files;
    const std::string name = entry.path().filename().string();
    const std::string code = code_of(entry.path());
    for (std::sregex_iterator it(code.begin(), code.end(), include), end; it != end; ++it) {
      const std::string header = (*it)[1].str();
      EXPECT_TRUE(header == "stdint.h" || header == "stddef.h" || header.rfind("qr/core/", 0) == 0 ||
                  header.rfind("common/", 0) == 0 || header.rfind("fixedpoint/", 0) == 0)
          << name << " includes <" << header << ">";
    }
    std::smatch m;
    EXPECT_FALSE(std::regex_search(code, m, forbidden)) << name << " uses '" << m.str() << "'";
    if (design_files.count(name) == 0) {
      EXPECT_FALSE(std::regex_search(code, m, double_word)) << name << " names double outside the design files";
    }
  }
  EXPECT_GE(files, 15);
}

}  // namespace
