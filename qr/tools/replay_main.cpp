// qrreplay --replay IN.csv --out OUT.csv [--double]: test mode on the host (replay.hpp,
// docs/replay.md). The simulator's `qrsim --replay` does the same through run_replay().
#include <cstring>
#include <iostream>

#include <qr/host/replay.hpp>

namespace {

constexpr const char* kUsage =
    "usage: qrreplay --replay IN.csv --out OUT.csv [--double]\n"
    "\n"
    "Runs recorded sensor samples and sticks (IN.csv) through the flight chain tick by tick:\n"
    "the first 512 rows calibrate, the rest fly in full control. Writes every tick's estimates,\n"
    "controller outputs and engine values to OUT.csv. docs/replay.md has both formats.\n"
    "\n"
    "  --double   run the double-precision reference chain instead of the flight build\n";

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
