// Fuzz target: arbitrary text as the console's parameter file (pc/core/param_file.cpp). Beyond
// what ASan and UBSan catch: every error names a line of the text; a file read without errors
// holds only values inside their ranges, and written out and read again gives the same values.
#include <stddef.h>
#include <stdint.h>

#include <string>

#include <pc/core/param_file.hpp>

#include "fuzz_checks.hpp"

using fuzz::require;
using fuzz::line_count;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const qrterm::ParamFileContents read = qrterm::parse_param_file(text);
  for (const qrterm::LineError& e : read.errors)
    require(e.line >= 1 && e.line <= line_count(text) && !e.message.empty());
  if (!read.errors.empty()) return 0;
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    const int32_t v = read.values.get(spec.id);
    require(v >= spec.min && v <= spec.max);
  }
  const qrterm::ParamFileContents again = qrterm::parse_param_file(qrterm::format_param_file(read.values));
  require(again.errors.empty());
  for (const wire::ParameterSpec& spec : wire::kParameterTable)
    require(again.values.get(spec.id) == read.values.get(spec.id));
  return 0;
}
