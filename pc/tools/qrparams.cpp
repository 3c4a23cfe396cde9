// qrparams: the shared parameter table as a document. --markdown writes docs/parameters.md;
// --check FILE says whether FILE is what the table makes now (a CTest runs it on the docs).
#include <cstdio>
#include <cstring>
#include <string>

#include <pc/core/parameter_doc.hpp>
#include <pc/core/settings_text.hpp>

namespace {

constexpr const char* kUsage =
    "usage: qrparams --markdown          the parameter table as markdown (docs/parameters.md)\n"
    "       qrparams --check FILE        exit 0 if FILE is exactly that, 1 (naming the first\n"
    "                                    differing line) if not\n"
    "       qrparams --help              this text\n"
    "Regenerate the document: build/host/pc/qrparams --markdown > docs/parameters.md\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (argc == 2 && std::strcmp(argv[1], "--markdown") == 0) {
    std::fputs(qrterm::parameters_markdown().c_str(), stdout);
    return 0;
  }
  if (argc == 3 && std::strcmp(argv[1], "--check") == 0) {
    std::string text;
    if (!qrterm::read_file(argv[2], text)) {
      std::fprintf(stderr, "qrparams: cannot read %s\n", argv[2]);
      return 1;
    }
    const std::string difference = qrterm::first_difference(qrterm::parameters_markdown(), text);
    if (difference.empty()) return 0;
    std::fprintf(stderr,
                 "qrparams: %s differs from common/parameter_table.hpp at %s\n"
                 "qrparams: regenerate it: build/host/pc/qrparams --markdown > docs/parameters.md\n",
                 argv[2], difference.c_str());
    return 1;
  }
  std::fputs(kUsage, stderr);
  return 2;
}
