// qrfilter (qr/tools/filter_tool.hpp): prints the firmware's design, its quantised integers and
// the response; clear errors on bad arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <qr/core/chain/butterworth_table.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/tools/filter_tool.hpp>

namespace qr::tools {
namespace {

struct ToolRun {
  int rc;
  std::string out, err;
};

ToolRun qrfilter(std::vector<const char*> args) {
  args.insert(args.begin(), "qrfilter");
  std::ostringstream out, err;
  const int rc = run_qrfilter(static_cast<int>(args.size()), args.data(), out, err);
  return {rc, out.str(), err.str()};
}

// The value of a JSON key holding a list or number, as text.
std::string field(const std::string& json, const std::string& key) {
  const std::regex re("\"" + key + "\": (\\[[^\\]]*\\]|[-0-9.e+]+|null)");
  std::smatch m;
  return std::regex_search(json, m, re) ? m[1].str() : "";
}

TEST(QrFilter, PrintsTheFlightTableEntry) {
  const ToolRun r = qrfilter({"--order", "2", "--fc", "20", "--fs", "1000"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(r.err.empty());
  const auto& c = chain::ButterworthTable<chain::FixedNumbers::Coefficient, 2, 1000>::for_cutoff(20);
  const std::string expected_b = "[" + std::to_string(c.b0.raw()) + ", " + std::to_string(c.b1.raw()) + ", " +
                                 std::to_string(c.b2().raw()) + "]";
  const std::string expected_a = "[1073741824, " + std::to_string(c.a1.raw()) + ", " + std::to_string(c.a2.raw()) + "]";
  EXPECT_NE(r.out.find("\"quantised\": {\"frac_bits\": 30, \"b\": " + expected_b + ", \"a\": " + expected_a + "}"),
            std::string::npos)
      << r.out;
  // Default response point: the cut-off, -3.0103 dB, -90 deg for order 2.
  EXPECT_EQ(field(r.out, "gain_db"), "-3.010300");
  EXPECT_EQ(field(r.out, "phase_deg"), "-90.000000");
  EXPECT_EQ(field(r.out, "order"), "2");
}

TEST(QrFilter, DoubleCoefficientsRoundTripAndResponsesAtRequestedFrequencies) {
  const ToolRun r = qrfilter({"--order", "1", "--fc", "100", "--fs", "1000", "--frac", "12", "--at", "0,100,500"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const chain::ButterworthDesign d = chain::design_butterworth(1, 100, 1000);
  char b[128];
  std::snprintf(b, sizeof b, "[%.17g, %.17g]", d.b[0], d.b[1]);
  EXPECT_EQ(field(r.out, "b"), b);
  EXPECT_NE(r.out.find("\"frac_bits\": 12"), std::string::npos);
  EXPECT_NE(r.out.find("{\"hz\": 0, \"gain_db\": 0.000000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("{\"hz\": 100, \"gain_db\": -3.010300, \"phase_deg\": -45.000000"), std::string::npos) << r.out;
  // The zero at fs/2: some -300 dB in double rounding (an exact -inf would print as null, which
  // JSON can hold); with 12 bits the DC-gain fix leaves |b0 - b1| = 1 lsb there: -75.8 dB.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m,
                                std::regex("\"hz\": 500, \"gain_db\": ([-0-9.]+|null), .*"
                                           "\"gain_db_quantised\": ([-0-9.]+)")))
      << r.out;
  EXPECT_TRUE(m[1].str() == "null" || std::stod(m[1].str()) < -300) << m[1].str();
  EXPECT_EQ(m[2].str(), "-75.823985");
  EXPECT_EQ(r.out.find("inf"), std::string::npos);
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
  EXPECT_EQ(r.out.find("-0.000000"), std::string::npos);
}

TEST(QrFilter, HelpGoesToStandardOutput) {
  const ToolRun r = qrfilter({"--help"});
  EXPECT_EQ(r.rc, 0);
  EXPECT_EQ(r.out.rfind("usage: qrfilter --order N --fc HZ --fs HZ", 0), 0u);
}

TEST(QrFilter, BadArgumentsAreRefusedClearly) {
  const struct {
    std::vector<const char*> args;
    const char* message;
  } cases[] = {
      {{"--order", "3", "--fc", "10", "--fs", "1000"}, "--order 3 is not supported: 1 or 2"},
      {{"--order", "two", "--fc", "10", "--fs", "1000"}, "--order wants a whole number, got 'two'"},
      {{"--order", "2", "--fc", "500", "--fs", "1000"}, "--fc 500 must be below fs/2 = 500 Hz"},
      {{"--order", "2", "--fc", "-1", "--fs", "1000"}, "--fc must be above 0 Hz, got -1"},
      {{"--order", "2", "--fc", "10x", "--fs", "1000"}, "--fc wants a number in Hz, got '10x'"},
      {{"--order", "2", "--fc", "10", "--fs", "nan"}, "--fs wants a number in Hz, got 'nan'"},
      {{"--order", "2", "--fc", "10", "--fs", "0"}, "--fs must be above 0 Hz, got 0"},
      {{"--order", "2", "--fc", "10"}, "--fs is required"},
      {{"--order", "2", "--fc", "10", "--fs", "1000", "--frac", "31"},
       "--frac wants a whole number of bits from 1 to 30"},
      {{"--order", "2", "--fc", "10", "--fs", "1000", "--at", "10,,20"},
       "--at wants comma-separated numbers in Hz, got ''"},
      {{"--order", "2", "--fc", "10", "--fs", "1000", "--at", "600"}, "--at 600 is outside [0, fs/2 = 500]"},
      {{"--order", "2", "--fc", "10", "--fs", "1000", "--bogus"}, "unknown argument '--bogus'"},
      {{"--order", "2", "--fc"}, "--fc needs a value"},
  };
  for (const auto& c : cases) {
    const ToolRun r = qrfilter(c.args);
    EXPECT_EQ(r.rc, 2) << c.message;
    EXPECT_TRUE(r.out.empty()) << c.message;
    EXPECT_EQ(r.err.rfind(std::string("qrfilter: ") + c.message, 0), 0u) << "got: " << r.err;
  }
}

}  // namespace
}  // namespace qr::tools
