// The check byte: the catalogue check value, and the error-detection claims of docs/protocol.md
// proven exhaustively for every frame length the message table uses.
#include <gtest/gtest.h>

#include <initializer_list>
#include <set>
#include <vector>

#include <common/crc8.hpp>
#include <common/frame.hpp>
#include <common/message_table.hpp>

namespace {

// Bit-at-a-time reference from the polynomial's definition, independent of the table in crc8.cpp.
uint8_t crc8_by_definition(const std::vector<uint8_t>& data) {
  unsigned crc = 0;
  for (uint8_t byte : data) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc & 0x80u) != 0 ? ((crc << 1) ^ 0xD5u) & 0xFFu : (crc << 1) & 0xFFu;
  }
  return static_cast<uint8_t>(crc);
}

// A codeword as the receiver checks it: type + payload followed by the check byte.
std::vector<uint8_t> codeword(size_t payload_length, uint32_t seed) {
  std::vector<uint8_t> word(1 + payload_length);
  for (size_t i = 0; i < word.size(); ++i) {
    seed = seed * 1103515245u + 12345u;
    word[i] = static_cast<uint8_t>(seed >> 16);
  }
  word.push_back(wire::crc8(word.data(), word.size()));
  return word;
}

bool passes_check(const std::vector<uint8_t>& word) { return wire::crc8(word.data(), word.size() - 1) == word.back(); }

void flip(std::vector<uint8_t>& word, size_t bit) {
  word[bit / 8] = static_cast<uint8_t>(word[bit / 8] ^ (0x80u >> (bit % 8)));
}

std::set<size_t> payload_lengths_in_use() {
  std::set<size_t> lengths;
  for (const wire::MessageSpec& spec : wire::kMessageTable) lengths.insert(spec.payload_length);
  return lengths;
}

// Counts the error patterns of `weight` flipped bits (1..3) that the check does not notice.
size_t undetected_of_weight(size_t payload_length, int weight) {
  const std::vector<uint8_t> good = codeword(payload_length, static_cast<uint32_t>(payload_length));
  const size_t bits = good.size() * 8;
  size_t undetected = 0;
  auto count_if_passes = [&](std::initializer_list<size_t> positions) {
    std::vector<uint8_t> word = good;
    for (size_t bit : positions) flip(word, bit);
    if (passes_check(word)) ++undetected;
  };
  for (size_t a = 0; a < bits; ++a) {
    if (weight == 1) count_if_passes({a});
    for (size_t b = a + 1; weight >= 2 && b < bits; ++b) {
      if (weight == 2) count_if_passes({a, b});
      for (size_t c = b + 1; weight == 3 && c < bits; ++c) count_if_passes({a, b, c});
    }
  }
  return undetected;
}

}  // namespace

TEST(Crc8, CatalogueCheckValueOf123456789Is0xBC) {
  const char* text = "123456789";
  EXPECT_EQ(wire::crc8(reinterpret_cast<const uint8_t*>(text), 9), 0xBC);
}

TEST(Crc8, TableMatchesThePolynomialForEveryByteAndPrefix) {
  for (unsigned first = 0; first < 256; ++first) {
    for (unsigned second = 0; second < 256; second += 17) {
      const std::vector<uint8_t> data = {static_cast<uint8_t>(first), static_cast<uint8_t>(second), 0x4D};
      ASSERT_EQ(wire::crc8(data.data(), data.size()), crc8_by_definition(data)) << first << "," << second;
    }
  }
}

TEST(Crc8, EveryFrameLengthInUseFitsTheTwoBitGuarantee) {
  // 93 bits is the period of the polynomial's non-(x+1) factor; the codeword must stay below it.
  for (size_t length : payload_lengths_in_use()) {
    EXPECT_LE(length, wire::kMaxPayloadBytes);
    EXPECT_LE((length + 2) * 8, 93u) << "payload " << length;
  }
}

TEST(Crc8, DetectsEverySingleBitErrorInEveryFrameLengthInUse) {
  for (size_t length : payload_lengths_in_use()) EXPECT_EQ(undetected_of_weight(length, 1), 0u) << "payload " << length;
}

TEST(Crc8, DetectsEveryTwoBitErrorInEveryFrameLengthInUse) {
  for (size_t length : payload_lengths_in_use()) EXPECT_EQ(undetected_of_weight(length, 2), 0u) << "payload " << length;
}

TEST(Crc8, DetectsEveryThreeBitErrorInEveryFrameLengthInUse) {
  for (size_t length : payload_lengths_in_use()) EXPECT_EQ(undetected_of_weight(length, 3), 0u) << "payload " << length;
}

TEST(Crc8, DetectsEveryBurstOfUpToEightBitsInEveryFrameLengthInUse) {
  for (size_t length : payload_lengths_in_use()) {
    const std::vector<uint8_t> good = codeword(length, 99u + static_cast<uint32_t>(length));
    const size_t bits = good.size() * 8;
    size_t undetected = 0, bursts = 0;
    // A burst starts at `start` (that bit flips) and spans at most 8 bits: the other 7 bits of the
    // span take every pattern; patterns running past the end are cut off there.
    for (size_t start = 0; start < bits; ++start) {
      for (unsigned rest = 0; rest < 128; ++rest) {
        std::vector<uint8_t> word = good;
        flip(word, start);
        bool inside = true;
        for (size_t k = 0; k < 7 && inside; ++k) {
          if (((rest >> k) & 1u) == 0) continue;
          inside = start + 1 + k < bits;
          if (inside) flip(word, start + 1 + k);
        }
        if (!inside) continue;
        ++bursts;
        if (passes_check(word)) ++undetected;
      }
    }
    EXPECT_EQ(undetected, 0u) << "payload " << length;
    EXPECT_GT(bursts, bits);
  }
}

// Why no payload is longer than 9 bytes: one byte more and some 2-bit errors (93 bits apart) pass.
TEST(Crc8, ATenBytePayloadWouldLetTwoBitErrors93BitsApartThrough) {
  EXPECT_GT(undetected_of_weight(10, 2), 0u);
  std::vector<uint8_t> word = codeword(10, 5);
  flip(word, 0);
  flip(word, 93);
  EXPECT_TRUE(passes_check(word));
}
