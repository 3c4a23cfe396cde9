// CRSF frames from flight firmwares' own test suites, taken as facts:
//   Betaflight's receiver unit test, src/test/unit/rx_crsf_unittest.cc (github.com/betaflight/
//   betaflight, read at commit 03318652113900d77a952a8f24a42ecf95431a53);
//   ESP-FC's CRSF input test, test/test_input_crsf/test_input_crsf.cpp (github.com/rtlopez/esp-fc,
//   read at commit 120a1a6edee4d197c7aaca386cef4ee2190be1b3).
// The bytes and the values those tests assert are quoted as data; the code here is ours. Our parser,
// decoders and encoder must read and write them as those firmwares do.
#include <gtest/gtest.h>

#include <common/crc8.hpp>
#include <common/drivers/crsf.hpp>
#include <common/drivers/crsf_parser.hpp>

#include <vector>

namespace {

using Bytes = std::vector<uint8_t>;

struct Parsed {
  std::vector<uint8_t> types;
  std::vector<uint8_t> sizes;
  std::vector<drivers::CrsfChannels> channels;
};

Parsed parse(const Bytes& bytes) {
  drivers::CrsfParser parser;
  Parsed p;
  parser.push(bytes.data(), bytes.size(), [&](const drivers::CrsfFrame& f) {
    p.types.push_back(f.type);
    p.sizes.push_back(f.size);
    drivers::CrsfChannels c;
    if (drivers::decode_rc_channels(f, c)) p.channels.push_back(c);
  });
  return p;
}

// "capturedData", two RC channels frames captured from a receiver; Betaflight's
// TestCapturedData asserts their check bytes (0x6C, 0x94) and channels 0..3: 189, 993, 978, 983
// and 189, 993, 978, 981. They start with address 0x00 (broadcast); fed byte by byte, Betaflight's
// receiver completes no frame from them (TestCrsfDataReceive), and ours, which syncs on 0xC8 only,
// none either.
const Bytes kCaptured1{0x00, 0x18, 0x16, 0xBD, 0x08, 0x9F, 0xF4, 0xAE, 0xF7, 0xBD, 0xEF, 0x7D, 0xEF,
                       0xFB, 0xAD, 0xFD, 0x45, 0x2B, 0x5A, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x6C};
const Bytes kCaptured2{0x00, 0x18, 0x16, 0xBD, 0x08, 0x9F, 0xF4, 0xAA, 0xF7, 0xBD, 0xEF, 0x7D, 0xEF,
                       0xFB, 0xAD, 0xFD, 0x45, 0x2B, 0x5A, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x94};

Bytes addressed_to_the_flight_computer(Bytes frame) {
  frame[0] = drivers::kCrsfSync;  // the check leaves the address out
  return frame;
}

TEST(CrsfFirmwareVectors, BetaflightsCapturedFramesDecodeToItsChannels) {
  EXPECT_TRUE(parse(kCaptured1).types.empty()) << "address 0x00 is no frame for the flight computer";
  const struct {
    const Bytes& frame;
    uint16_t want[4];
  } cases[] = {{kCaptured1, {189, 993, 978, 983}}, {kCaptured2, {189, 993, 978, 981}}};
  for (const auto& c : cases) {
    const Parsed p = parse(addressed_to_the_flight_computer(c.frame));
    ASSERT_EQ(p.channels.size(), 1u);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(p.channels[0].value[i], c.want[i]) << "channel " << i;
    EXPECT_EQ(wire::crc8(c.frame.data() + 2, 23), c.frame[25]) << "the check over type and payload";
  }
}

// TestCrsfFrameStatusUnpacking: a payload whose channels are 0x7FF, 0x1F, 0, 172, 0, 992, 0, 1811
// and then 0 (Betaflight computes the frame's check in the test; so do we).
TEST(CrsfFirmwareVectors, BetaflightsUnpackingPayloadGivesItsChannels) {
  Bytes frame{drivers::kCrsfSync, 0x18, 0x16, 0xFF, 0xFF, 0x00, 0x00, 0x58, 0x01, 0x00, 0xF0, 0x01, 0x60, 0xE2};
  frame.resize(3 + drivers::kCrsfChannelsPayload, 0);
  frame.push_back(wire::crc8(frame.data() + 2, 1 + drivers::kCrsfChannelsPayload));
  const Parsed p = parse(frame);
  ASSERT_EQ(p.channels.size(), 1u);
  const uint16_t want[16] = {0x7FF, 0x1F, 0, 172, 0, 992, 0, 1811, 0, 0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 16; ++i) EXPECT_EQ(p.channels[0].value[i], want[i]) << "channel " << i;
}

// "buadrateNegotiationFrame" (a command frame, type 0x32, whose last byte is the frame's check and
// the one before the command's own) and "capturedSubsetData" (a subset RC frame, type 0x17):
// Betaflight asserts both frame checks (0x72, 0xD1). Our parser takes both as frames of their
// type; neither is RC channels to our decoder (the QR reads only full RC frames: a receiver sends
// those to a flight computer that has not asked for subsets).
TEST(CrsfFirmwareVectors, BetaflightsCommandAndSubsetFramesAreFramesButNotChannels) {
  const Bytes command{0xC8, 0x0C, 0x32, 0xC8, 0xEC, 0x0A, 0x70, 0x01, 0x00, 0x1E, 0x84, 0x80, 0x22, 0x72};
  const Bytes subset{0xC8, 0x09, 0x17, 0x24, 0x00, 0xA0, 0xD9, 0xE9, 0xFF, 0x0F, 0xD1};
  const Parsed p = parse(command);
  ASSERT_EQ(p.types.size(), 1u);
  EXPECT_EQ(p.types[0], 0x32);
  EXPECT_EQ(p.sizes[0], 10u);
  EXPECT_TRUE(p.channels.empty());
  const Parsed s = parse(subset);
  ASSERT_EQ(s.types.size(), 1u);
  EXPECT_EQ(s.types[0], 0x17);
  EXPECT_EQ(s.sizes[0], 7u);
  EXPECT_TRUE(s.channels.empty());
}

// TestOversizedFrameLengthIsRejected: the flight computer's address, a length of 64 (the whole
// frame's maximum, so past the length byte's 62) and an RC type, then zeros: no frame.
TEST(CrsfFirmwareVectors, BetaflightsOversizedLengthIsNoFrame) {
  Bytes frame{0xC8, 64, 0x16};
  frame.resize(64, 0);
  EXPECT_TRUE(parse(frame).types.empty());
}

// ESP-FC's test_input_crsf_rc_valid and _rc_prefix: an RC frame (check 0x23), also found after four
// bytes of garbage, whose first six channels ESP-FC reads as 1500, 1500, 1425, 1500, 1000, 1000 us.
// CRSF's 172..1811 stands for 988..2012 us (docs/drivers.md): our channels, so converted and
// rounded, are ESP-FC's.
TEST(CrsfFirmwareVectors, EspFcsFrameDecodesToItsMicroseconds) {
  const Bytes frame{0xC8, 0x18, 0x16, 0xE0, 0x03, 0xDF, 0xD9, 0xC0, 0xF7, 0x8B, 0x5F, 0x94, 0xAF,
                    0x7C, 0xE5, 0x2B, 0x5F, 0xF9, 0xCA, 0x07, 0x00, 0x00, 0x4C, 0x7C, 0xE2, 0x23};
  const Bytes garbage{0xA1, 0x04, 0xC5, 0x09};
  Bytes prefixed = garbage;
  prefixed.insert(prefixed.end(), frame.begin(), frame.end());
  const uint16_t want_us[6] = {1500, 1500, 1425, 1500, 1000, 1000};
  for (const Bytes& bytes : {frame, prefixed}) {
    const Parsed p = parse(bytes);
    ASSERT_EQ(p.channels.size(), 1u);
    for (int i = 0; i < 6; ++i) {
      const uint32_t v = p.channels[0].value[i];
      const uint32_t us = 988 + ((v - 172) * 1024 * 2 + 1639) / (2 * 1639);
      EXPECT_EQ(us, want_us[i]) << "channel " << i << " = " << v;
    }
  }
}

// ESP-FC's test_crsf_encode_rc: every channel at 992 but channel 2 (the lift) at 172 encodes to
// these 26 bytes, check 0xDB. Our encoder (the simulator's radio) makes the same bytes.
TEST(CrsfFirmwareVectors, OurEncoderMakesEspFcsBytes) {
  drivers::CrsfChannels channels;
  for (uint16_t& v : channels.value) v = 992;
  channels.value[2] = 172;
  const drivers::CrsfFrameBytes f = drivers::encode_rc_channels(channels);
  const Bytes want{0xC8, 0x18, 0x16, 0xE0, 0x03, 0x1F, 0x2B, 0xC0, 0x07, 0x3E, 0xF0, 0x81, 0x0F,
                   0x7C, 0xE0, 0x03, 0x1F, 0xF8, 0xC0, 0x07, 0x3E, 0xF0, 0x81, 0x0F, 0x7C, 0xDB};
  EXPECT_EQ(Bytes(f.bytes, f.bytes + f.size), want);
}

}  // namespace
