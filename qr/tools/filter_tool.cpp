// qrfilter: prints a Butterworth low-pass design as JSON, from the very code the firmware's
// design table is built with, so what the console or a person reads is what flies.
#include "filter_tool.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <qr/core/chain/butterworth_design.hpp>
#include <qr/tools/filter_response.hpp>

namespace qr::tools {
namespace {

constexpr const char* kUsage =
    "usage: qrfilter --order N --fc HZ --fs HZ [--frac BITS] [--at HZ,HZ,...]\n"
    "\n"
    "Designs a Butterworth low-pass (bilinear transform, cut-off pre-warped) with the firmware's\n"
    "design code and prints JSON: the coefficients in double (b = [b0, b1(, b2)], a = [1, a1(, a2)],\n"
    "y = b.x - a1 y1 - a2 y2), the same quantised to integers of Q<BITS> as the firmware stores\n"
    "them (DC gain exactly 1), and gain (dB) and phase (deg) at the requested frequencies, for the\n"
    "design, the quantised coefficients and the analytic Butterworth magnitude.\n"
    "\n"
    "  --order N     1 or 2\n"
    "  --fc HZ       cut-off frequency, 0 < fc < fs/2\n"
    "  --fs HZ       sample rate, > 0 (the firmware runs at 1000 or 500)\n"
    "  --frac BITS   fractional bits of the quantised coefficients, 1..30 (default 30, as in flight)\n"
    "  --at LIST     comma-separated frequencies in [0, fs/2] (default: fc)\n"
    "  --help        this text\n";

bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

bool parse_integer(const std::string& text, long& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtol(text.c_str(), &end, 10);
  return errno == 0 && end == text.c_str() + text.size();
}

// JSON has no infinities: a gain of -inf dB (a zero at fs/2) prints as null.
std::string number(double v, const char* format) {
  if (!std::isfinite(v)) return "null";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

struct Arguments {
  long order = 0;
  double fc = 0, fs = 0;
  long frac = 30;
  std::vector<double> at;
  bool have_order = false, have_fc = false, have_fs = false, help = false;
};

// Fills `a` or returns an error message.
std::string parse(int argc, const char* const* argv, Arguments& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h") {
      a.help = true;
      return {};
    }
    if (option != "--order" && option != "--fc" && option != "--fs" && option != "--frac" && option != "--at") {
      return "unknown argument '" + option + "'";
    }
    if (i + 1 >= argc) return option + " needs a value";
    const std::string value = argv[++i];
    if (option == "--order") {
      if (!parse_integer(value, a.order)) return "--order wants a whole number, got '" + value + "'";
      if (a.order != 1 && a.order != 2) return "--order " + value + " is not supported: 1 or 2";
      a.have_order = true;
    } else if (option == "--fc") {
      if (!parse_number(value, a.fc)) return "--fc wants a number in Hz, got '" + value + "'";
      a.have_fc = true;
    } else if (option == "--fs") {
      if (!parse_number(value, a.fs)) return "--fs wants a number in Hz, got '" + value + "'";
      a.have_fs = true;
    } else if (option == "--frac") {
      if (!parse_integer(value, a.frac) || a.frac < 1 || a.frac > 30) {
        return "--frac wants a whole number of bits from 1 to 30, got '" + value + "'";
      }
    } else {  // --at
      a.at.clear();
      size_t start = 0;
      while (true) {
        const size_t comma = value.find(',', start);
        const std::string item = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        double f = 0;
        if (!parse_number(item, f)) return "--at wants comma-separated numbers in Hz, got '" + item + "'";
        a.at.push_back(f);
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
    }
  }
  if (!a.have_order) return "--order is required";
  if (!a.have_fc) return "--fc is required";
  if (!a.have_fs) return "--fs is required";
  if (!(a.fs > 0)) return "--fs must be above 0 Hz, got " + number(a.fs, "%g");
  if (!(a.fc > 0)) return "--fc must be above 0 Hz, got " + number(a.fc, "%g");
  if (!(a.fc < a.fs / 2)) {
    return "--fc " + number(a.fc, "%g") + " must be below fs/2 = " + number(a.fs / 2, "%g") + " Hz";
  }
  for (const double f : a.at) {
    if (f < 0 || f > a.fs / 2)
      return "--at " + number(f, "%g") + " is outside [0, fs/2 = " + number(a.fs / 2, "%g") + "]";
  }
  if (a.at.empty()) a.at.push_back(a.fc);
  return {};
}

// Six decimals, with -0.000000 printed as 0.000000.
std::string decimals6(double v) { return number(std::fabs(v) < 5e-7 ? 0.0 : v, "%.6f"); }

template <class T>
std::string json_list(const T* values, int count, const char* format) {
  std::string s = "[";
  for (int i = 0; i < count; ++i) {
    if (i) s += ", ";
    s += number(static_cast<double>(values[i]), format);
  }
  return s + "]";
}

std::string json_int_list(const int64_t* values, int count) {
  std::string s = "[";
  for (int i = 0; i < count; ++i) {
    if (i) s += ", ";
    s += std::to_string(values[i]);
  }
  return s + "]";
}

}  // namespace

int run_qrfilter(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  Arguments a;
  if (const std::string error = parse(argc, argv, a); !error.empty()) {
    err << "qrfilter: " << error << "\n" << kUsage;
    return 2;
  }
  if (a.help) {
    out << kUsage;
    return 0;
  }
  const int order = static_cast<int>(a.order);
  const chain::ButterworthDesign d = chain::design_butterworth(order, a.fc, a.fs);
  const chain::QuantisedDesign q = chain::quantise(d, static_cast<int>(a.frac));
  if (!d.valid() || !q.fits_int32()) {
    err << "qrfilter: this design's coefficients do not fit 32-bit Q<" << a.frac << ">\n";
    return 2;
  }
  const int taps = order + 1;
  out << "{\n";
  out << "  \"order\": " << order << ",\n";
  out << "  \"fc_hz\": " << number(a.fc, "%.17g") << ",\n";
  out << "  \"fs_hz\": " << number(a.fs, "%.17g") << ",\n";
  out << "  \"b\": " << json_list(d.b, taps, "%.17g") << ",\n";
  out << "  \"a\": " << json_list(d.a, taps, "%.17g") << ",\n";
  out << "  \"quantised\": {\"frac_bits\": " << q.frac_bits << ", \"b\": " << json_int_list(q.b, taps)
      << ", \"a\": " << json_int_list(q.a, taps) << "},\n";
  out << "  \"response\": [";
  for (size_t i = 0; i < a.at.size(); ++i) {
    const double f = a.at[i];
    const chain::Response designed = chain::response_of(d, f, a.fs);
    const chain::Response quantised = chain::response_of(q, f, a.fs);
    out << (i ? ",\n    " : "\n    ");
    out << "{\"hz\": " << number(f, "%.17g") << ", \"gain_db\": " << decimals6(designed.gain_db)
        << ", \"phase_deg\": " << decimals6(designed.phase_deg)
        << ", \"gain_db_quantised\": " << decimals6(quantised.gain_db)
        << ", \"phase_deg_quantised\": " << decimals6(quantised.phase_deg)
        << ", \"gain_db_analytic\": " << decimals6(chain::analytic_butterworth_gain_db(order, a.fc, a.fs, f)) << "}";
  }
  out << "\n  ]\n}\n";
  return 0;
}

}  // namespace qr::tools
