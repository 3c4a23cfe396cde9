// The commanding requests' guard: CRC-24/OPENPGP as RFC 4880 (section 6.1) and the CRC catalogue
// define it.
#include <gtest/gtest.h>

#include <common/crc24.hpp>

TEST(Crc24, CatalogueCheckValue) {
  static constexpr uint8_t text[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(wire::crc24(text, sizeof text), 0x21CF02u);
  EXPECT_EQ(wire::crc24(text, 0), wire::kCrc24Init) << "nothing covered: the initial value";
}

TEST(Crc24, EverySingleBitFlipOfAGuardedBodyChangesIt) {
  const uint8_t body[] = {0x14, 0x03, 0x0A, 0x04, 0x29, 0x00, 0x00};  // param_set's type and payload (G3)
  const uint32_t good = wire::crc24(body, sizeof body);
  for (size_t bit = 0; bit < 8 * sizeof body; ++bit) {
    uint8_t flipped[sizeof body];
    for (size_t i = 0; i < sizeof body; ++i) flipped[i] = body[i];
    flipped[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
    EXPECT_NE(wire::crc24(flipped, sizeof flipped), good) << "bit " << bit;
  }
}
