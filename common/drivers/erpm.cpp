#include <common/drivers/erpm.hpp>

namespace drivers {
namespace {

// 5-bit group -> nibble, 0xFF for the 16 groups no nibble makes: one lookup per group.
struct GcrDecodeTable {
  uint8_t nibble[32];
};

constexpr GcrDecodeTable make_decode_table() {
  GcrDecodeTable t{};
  for (uint8_t& n : t.nibble) n = 0xFF;
  for (uint8_t v = 0; v < 16; ++v) t.nibble[kGcrOfNibble[v]] = v;
  return t;
}

constexpr GcrDecodeTable kGcrDecode = make_decode_table();

constexpr uint16_t answer_check(uint16_t code) {
  return static_cast<uint16_t>(~(code ^ (code >> 4) ^ (code >> 8)) & 0xFu);
}

}  // namespace

ErpmReading decode_erpm_answer(uint32_t raw) {
  const uint32_t gcr = (raw ^ (raw >> 1)) & 0xFFFFFu;
  uint32_t value = 0;
  for (int group = 3; group >= 0; --group) {
    const uint8_t nibble = kGcrDecode.nibble[(gcr >> (5 * group)) & 0x1Fu];
    if (nibble == 0xFF) return {};
    value = (value << 4) | nibble;
  }
  const uint16_t code = static_cast<uint16_t>(value >> 4);
  if ((value & 0xFu) != answer_check(code)) return {};
  if (code == kErpmStopped) return {true, 0};
  return {true, static_cast<uint32_t>(code & 0x1FFu) << (code >> 9)};
}

uint32_t encode_erpm_answer(uint16_t period_code, bool start_high) {
  const uint16_t code = static_cast<uint16_t>(period_code & 0xFFFu);
  const uint32_t value = (uint32_t{code} << 4) | answer_check(code);
  uint32_t gcr = 0;
  for (int nibble = 3; nibble >= 0; --nibble) gcr = (gcr << 5) | kGcrOfNibble[(value >> (4 * nibble)) & 0xFu];
  // A 1 is a change of level: each bit is the one before it XOR the GCR bit.
  uint32_t level = start_high ? 1u : 0u;
  uint32_t raw = level;
  for (int bit = 19; bit >= 0; --bit) {
    level ^= (gcr >> bit) & 1u;
    raw = (raw << 1) | level;
  }
  return raw;
}

}  // namespace drivers
