#include <pc/core/hex_log.hpp>

#include <pc/core/console_log.hpp>

namespace qrterm {

std::string hex_line(uint32_t time_ms, const uint8_t* bytes, size_t count) {
  constexpr char kDigits[] = "0123456789ABCDEF";
  std::string line = format_seconds(time_ms) + " ";
  line.reserve(line.size() + 3 * count + 1);
  for (size_t i = 0; i < count; ++i) {
    line += ' ';
    line += kDigits[bytes[i] >> 4];
    line += kDigits[bytes[i] & 0x0F];
  }
  return line + "\n";
}

}  // namespace qrterm
