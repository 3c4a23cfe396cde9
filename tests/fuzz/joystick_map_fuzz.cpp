// Fuzz target: arbitrary text as the console's joystick map (pc/core/joystick_map.cpp). Beyond
// what ASan and UBSan catch: every error names a line of the text; a map read without errors,
// written out and read again, is the same map; its sticks stay in the wire's ranges for every
// axis value.
#include <stddef.h>
#include <stdint.h>

#include <string>

#include <pc/core/joystick_map.hpp>

#include "fuzz_checks.hpp"

using fuzz::require;
using fuzz::line_count;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const qrterm::JoystickMapFile read = qrterm::parse_joystick_map(text);
  for (const qrterm::LineError& e : read.errors)
    require(e.line >= 1 && e.line <= line_count(text) && !e.message.empty());
  if (!read.errors.empty()) return 0;
  const std::string written = qrterm::format_joystick_map(read.map);
  const qrterm::JoystickMapFile again = qrterm::parse_joystick_map(written);
  require(again.errors.empty() && qrterm::format_joystick_map(again.map) == written);
  for (const int32_t raw : {-32768, -32767, -1000, 0, 1000, 32767}) {
    const int32_t s = read.map.stick(read.map.roll, raw);
    require(s >= -1000 && s <= 1000);
    const int32_t lift = read.map.lift_of(raw);
    require(lift >= 0 && lift <= 1000);
  }
  return 0;
}
