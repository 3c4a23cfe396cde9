// qrreplay --replay IN.csv --out OUT.csv [--double]: test mode on the host (replay.hpp,
// docs/replay.md). The simulator's `qrsim --replay` does the same through run_replay().
#include <cstring>
#include <iostream>
#include <string>

#include <qr/host/parameter_text.hpp>
#include <qr/host/replay.hpp>

namespace {

constexpr const char* kUsage =
    "usage: qrreplay --replay IN.csv --out OUT.csv [--double] [--param NAME=VALUE]...\n"
    "\n"
    "Runs recorded sensor samples and sticks (IN.csv) through the flight chain tick by tick:\n"
    "the first 512 rows calibrate, the rest fly in full control. Writes every tick's estimates,\n"
    "controller outputs and engine values to OUT.csv. docs/replay.md has both formats.\n"
    "\n"
    "  --double     run the double-precision reference chain instead of the flight build\n"
    "  --param N=V  the chain's parameter N (a name from docs/parameters.md) at V in its unit,\n"
    "               as the flight had it (default: the parameter's default)\n";

}  // namespace

int main(int argc, char** argv) {
  const char* in = nullptr;
  const char* out = nullptr;
  qr::host::ReplayOptions options;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      std::cout << kUsage;
      return 0;
    } else if (std::strcmp(argv[i], "--double") == 0) {
      options.arithmetic = qr::host::ReplayArithmetic::reference_double;
    } else if (std::strcmp(argv[i], "--param") == 0 && i + 1 < argc) {
      const std::string text = argv[++i];
      const size_t eq = text.find('=');
      wire::ParamId id{};
      int32_t raw = 0;
      const std::string problem = eq == std::string::npos
                                      ? "--param needs NAME=VALUE"
                                      : qr::host::parameter_from_text(text.substr(0, eq), text.substr(eq + 1), id, raw);
      if (!problem.empty()) {
        std::cerr << "qrreplay: " << problem << "\n" << kUsage;
        return 2;
      }
      options.parameters.set(static_cast<uint8_t>(id), raw);
    } else if ((std::strcmp(argv[i], "--replay") == 0 || std::strcmp(argv[i], "--out") == 0) && i + 1 < argc) {
      (argv[i][2] == 'r' ? in : out) = argv[i + 1];
      ++i;
    } else {
      std::cerr << "qrreplay: unknown or incomplete argument '" << argv[i] << "'\n" << kUsage;
      return 2;
    }
  }
  if (in == nullptr || out == nullptr) {
    std::cerr << "qrreplay: --replay IN.csv and --out OUT.csv are required\n" << kUsage;
    return 2;
  }
  return qr::host::run_replay(in, out, std::cerr, options);
}
