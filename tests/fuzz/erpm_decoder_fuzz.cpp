// Fuzz target: arbitrary words into the bidirectional DShot answer decoder (common/drivers/erpm.hpp)
// and the ESC's frame decoder (common/drivers/dshot.hpp), four bytes at a time. Checks, beyond what
// ASan and UBSan catch: an answer read as valid has a period an ESC's answer gives back, reads the
// same with the line inverted and whatever lies above its 21 bits, and a bounded period and
// RPM; a DShot frame read as valid is the frame of its value.
#include <stddef.h>
#include <stdint.h>

#include <common/drivers/dshot.hpp>
#include <common/drivers/erpm.hpp>

#include "fuzz_checks.hpp"

namespace {

using fuzz::require;

void check_answer(uint32_t raw) {
  const drivers::ErpmReading r = drivers::decode_erpm_answer(raw);
  if (!r.valid) return;
  const uint16_t code = r.period_us == 0 ? drivers::kErpmStopped : drivers::erpm_period_code(r.period_us);
  const drivers::ErpmReading again = drivers::decode_erpm_answer(drivers::encode_erpm_answer(code));
  require(again.valid && again.period_us == r.period_us);
  // Only the level changes carry information: the line inverted reads the same, and the bits
  // above the answer's 21 are not read at all.
  const drivers::ErpmReading flipped = drivers::decode_erpm_answer(raw ^ 0x1FFFFFu);
  require(flipped.valid && flipped.period_us == r.period_us);
  const drivers::ErpmReading trimmed = drivers::decode_erpm_answer(raw & 0x1FFFFFu);
  require(trimmed.valid && trimmed.period_us == r.period_us);
  require(r.period_us <= (0x1FFu << 7));
  require(drivers::rpm_of_period(r.period_us, 1) <= drivers::kMicrosPerMinute);
}

void check_frame(uint16_t frame) {
  for (drivers::DshotLine line : {drivers::DshotLine::unidirectional, drivers::DshotLine::bidirectional}) {
    const drivers::DshotDecoded d = drivers::dshot_decode(frame, line);
    if (!d.valid) continue;
    require(d.value <= drivers::kDshotValueMax);
    require(drivers::dshot_frame(d.value, d.telemetry_request, line) == frame);
    require(drivers::dshot_engine(d.value) <= drivers::kDshotEngineMax);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (size_t i = 0; i + 4 <= size; i += 4) {
    const uint32_t word = data[i] | (uint32_t{data[i + 1]} << 8) | (uint32_t{data[i + 2]} << 16) |
                          (uint32_t{data[i + 3]} << 24);
    check_answer(word);
    check_frame(static_cast<uint16_t>(word));
    check_frame(static_cast<uint16_t>(word >> 16));
  }
  return 0;
}
