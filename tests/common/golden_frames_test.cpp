// Golden frames: the bytes in docs/protocol.md are the bytes the code makes and reads, and every
// 1- and 2-bit corruption of them is refused.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>

#include "golden_frames.hpp"
#include "wire_test_support.hpp"

using wire_test::bytes_of;
using wire_test::from_hex;
using wire_test::golden_frames;
using wire_test::GoldenFrame;
using wire_test::parse_all;
using wire_test::to_hex;

namespace {

// Rows of the golden table in docs/protocol.md: "| G<n> | ... | `<hex>` |".
std::map<std::string, std::string> golden_rows_of_the_document() {
  std::ifstream doc(QR_PROTOCOL_DOC);
  EXPECT_TRUE(doc.good()) << "cannot read " << QR_PROTOCOL_DOC;
  std::map<std::string, std::string> rows;
  const std::regex row(R"(^\|\s*(G[0-9]+)\s*\|.*`([0-9A-Fa-f ]+)`\s*\|\s*$)");
  std::string line;
  while (std::getline(doc, line)) {
    std::smatch m;
    if (std::regex_match(line, m, row)) {
      EXPECT_TRUE(rows.emplace(m[1].str(), m[2].str()).second) << "listed twice: " << m[1].str();
    }
  }
  return rows;
}

std::vector<uint8_t> flipped(std::vector<uint8_t> bytes, std::initializer_list<size_t> bits) {
  for (size_t bit : bits) bytes[bit / 8] = static_cast<uint8_t>(bytes[bit / 8] ^ (0x80u >> (bit % 8)));
  return bytes;
}

}  // namespace

TEST(GoldenFrames, TheEncoderMakesExactlyTheGoldenBytes) {
  for (const GoldenFrame& g : golden_frames()) {
    bool ok = false;
    const std::vector<uint8_t> expected = from_hex(g.hex, &ok);
    ASSERT_TRUE(ok) << g.id;
    EXPECT_EQ(to_hex(bytes_of(g.encoded)), to_hex(expected)) << g.id;
  }
}

TEST(GoldenFrames, TheParserAndDecoderGiveBackTheMessage) {
  for (const GoldenFrame& g : golden_frames()) {
    const std::vector<wire::Frame> frames = parse_all(from_hex(g.hex));
    ASSERT_EQ(frames.size(), 1u) << g.id;
    EXPECT_EQ(frames[0].type, g.type) << g.id;
    EXPECT_TRUE(g.decodes_to_message(frames[0])) << g.id;
  }
}

TEST(GoldenFrames, EveryMessageTypeHasOne) {
  std::set<wire::MessageType> covered;
  for (const GoldenFrame& g : golden_frames()) covered.insert(g.type);
  for (const wire::MessageSpec& spec : wire::kMessageTable) EXPECT_EQ(covered.count(spec.type), 1u) << spec.name;
}

TEST(GoldenFrames, TheProtocolDocumentListsExactlyTheseFrames) {
  const std::map<std::string, std::string> documented = golden_rows_of_the_document();
  std::map<std::string, std::string> tested;
  for (const GoldenFrame& g : golden_frames()) tested[g.id] = to_hex(from_hex(g.hex));
  std::map<std::string, std::string> documented_normalised;
  for (const auto& [id, hex] : documented) documented_normalised[id] = to_hex(from_hex(hex));
  EXPECT_EQ(documented_normalised, tested);
}

TEST(GoldenFrames, EverySingleBitFlipIsRejectedAndTheNextFrameStillArrives) {
  for (const GoldenFrame& g : golden_frames()) {
    const std::vector<uint8_t> good = from_hex(g.hex);
    for (size_t bit = 0; bit < good.size() * 8; ++bit) {
      std::vector<uint8_t> stream = flipped(good, {bit});
      EXPECT_TRUE(parse_all(stream).empty()) << g.id << " bit " << bit;
      stream.insert(stream.end(), good.begin(), good.end());
      const std::vector<wire::Frame> frames = parse_all(stream);
      ASSERT_EQ(frames.size(), 1u) << g.id << " bit " << bit;
      EXPECT_TRUE(g.decodes_to_message(frames[0])) << g.id << " bit " << bit;
    }
  }
}

TEST(GoldenFrames, EveryTwoBitFlipIsRejected) {
  for (const GoldenFrame& g : golden_frames()) {
    const std::vector<uint8_t> good = from_hex(g.hex);
    const size_t bits = good.size() * 8;
    for (size_t a = 0; a < bits; ++a) {
      for (size_t b = a + 1; b < bits; ++b) {
        EXPECT_TRUE(parse_all(flipped(good, {a, b})).empty()) << g.id << " bits " << a << "," << b;
      }
    }
  }
}
