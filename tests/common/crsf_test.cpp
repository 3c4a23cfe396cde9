// The CRSF receiver parser and payloads (common/drivers/crsf*.hpp) against published frames.
//
// The frames: the all-centre RC frame (16 x 992) and the all-low one (16 x 172) are the frames
// that circulate in public CRSF test suites and receiver code (e.g. Crossfire/ELRS "idle" frames;
// their check bytes 0xAD and 0x5B); the example frame of the CRSFv2-elrs README
// (github.com/kielerrr/CRSFv2-elrs, sent to the TX module with address 0xEE) and its check 0x36;
// a link statistics frame C8 0C 14 11 00 64 0B 00 09 07 00 00 00 F8 from public receiver code
// (uplink RSSI -17 dBm, LQ 100 %, SNR 11 dB, RF mode 9, power index 7). docs/drivers.md lists them.
#include <gtest/gtest.h>

#include <common/crc8.hpp>
#include <common/drivers/crsf.hpp>
#include <common/drivers/crsf_parser.hpp>
#include <common/drivers/rc_sticks.hpp>

#include <vector>

namespace {

using Bytes = std::vector<uint8_t>;

const Bytes kAllCentre{0xC8, 0x18, 0x16, 0xE0, 0x03, 0x1F, 0xF8, 0xC0, 0x07, 0x3E, 0xF0, 0x81, 0x0F,
                       0x7C, 0xE0, 0x03, 0x1F, 0xF8, 0xC0, 0x07, 0x3E, 0xF0, 0x81, 0x0F, 0x7C, 0xAD};
const Bytes kAllLow{0xC8, 0x18, 0x16, 0xAC, 0x60, 0x05, 0x2B, 0x58, 0xC1, 0x0A, 0x56, 0xB0, 0x82,
                    0x15, 0xAC, 0x60, 0x05, 0x2B, 0x58, 0xC1, 0x0A, 0x56, 0xB0, 0x82, 0x15, 0x5B};
// The README's frame with the flight computer's address in place of 0xEE (the check leaves the
// address out).
const Bytes kReadmeExample{0xC8, 0x18, 0x16, 0xE1, 0xE3, 0xDE, 0x09, 0xC7, 0xD7, 0x8A, 0x56, 0x80, 0x0F,
                           0x7C, 0xE0, 0x03, 0x1F, 0xF8, 0xC0, 0x07, 0x3E, 0xF0, 0x81, 0x0F, 0x7C, 0x36};
const Bytes kLinkStats{0xC8, 0x0C, 0x14, 0x11, 0x00, 0x64, 0x0B, 0x00, 0x09, 0x07, 0x00, 0x00, 0x00, 0xF8};

struct Received {
  std::vector<drivers::CrsfChannels> channels;
  std::vector<drivers::CrsfLinkStatistics> stats;
  int frames = 0;
};

Received parse(drivers::CrsfParser& parser, const Bytes& bytes) {
  Received r;
  for (uint8_t b : bytes) {
    parser.push(b, [&](const drivers::CrsfFrame& f) {
      ++r.frames;
      drivers::CrsfChannels c;
      drivers::CrsfLinkStatistics s;
      if (drivers::decode_rc_channels(f, c)) r.channels.push_back(c);
      if (drivers::decode_link_statistics(f, s)) r.stats.push_back(s);
    });
  }
  return r;
}

Received parse(const Bytes& bytes) {
  drivers::CrsfParser parser;
  return parse(parser, bytes);
}

Bytes operator+(Bytes a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The catalogue check value of CRC-8/DVB-S2 over "123456789" is 0xBC (the same CRC the wire uses).
TEST(Crsf, TheCheckIsCrc8DvbS2) {
  const uint8_t digits[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(wire::crc8(digits, sizeof digits), 0xBCu);
}

TEST(Crsf, PublishedRcFramesDecode) {
  const Received centre = parse(kAllCentre);
  ASSERT_EQ(centre.channels.size(), 1u);
  for (uint16_t v : centre.channels[0].value) EXPECT_EQ(v, 992u);
  const Received low = parse(kAllLow);
  ASSERT_EQ(low.channels.size(), 1u);
  for (uint16_t v : low.channels[0].value) EXPECT_EQ(v, 172u);
  const Received example = parse(kReadmeExample);
  ASSERT_EQ(example.channels.size(), 1u);
  const uint16_t want[16] = {993, 988, 1063, 995, 173, 173, 992, 992, 992, 992, 992, 992, 992, 992, 992, 992};
  for (int i = 0; i < 16; ++i) EXPECT_EQ(example.channels[0].value[i], want[i]) << i;
}

TEST(Crsf, LinkStatisticsDecode) {
  const Received r = parse(kLinkStats);
  ASSERT_EQ(r.stats.size(), 1u);
  const drivers::CrsfLinkStatistics& s = r.stats[0];
  EXPECT_EQ(s.uplink_rssi_ant1, 0x11u);  // -17 dBm
  EXPECT_EQ(s.uplink_rssi_ant2, 0u);
  EXPECT_EQ(s.uplink_link_quality, 100u);
  EXPECT_EQ(s.uplink_snr, 11);
  EXPECT_EQ(s.active_antenna, 0u);
  EXPECT_EQ(s.rf_mode, 9u);
  EXPECT_EQ(s.uplink_tx_power, 7u);
  EXPECT_EQ(s.downlink_rssi, 0u);
  EXPECT_EQ(s.downlink_link_quality, 0u);
  EXPECT_EQ(s.downlink_snr, 0);
}

TEST(Crsf, EncodersMakeThePublishedBytes) {
  drivers::CrsfChannels centre;
  for (uint16_t& v : centre.value) v = 992;
  const drivers::CrsfFrameBytes f = drivers::encode_rc_channels(centre);
  EXPECT_EQ(Bytes(f.bytes, f.bytes + f.size), kAllCentre);
  const Received r = parse(kLinkStats);
  const drivers::CrsfFrameBytes s = drivers::encode_link_statistics(r.stats[0]);
  EXPECT_EQ(Bytes(s.bytes, s.bytes + s.size), kLinkStats);
}

TEST(Crsf, ChannelsRoundTripEveryValueInEverySlot) {
  for (int slot = 0; slot < 16; ++slot) {
    for (uint16_t v = 0; v < 2048; v = static_cast<uint16_t>(v + 7)) {
      drivers::CrsfChannels c;
      for (int i = 0; i < 16; ++i) c.value[i] = static_cast<uint16_t>((i * 131 + 5) & 0x7FF);
      c.value[slot] = v;
      const drivers::CrsfFrameBytes f = drivers::encode_rc_channels(c);
      const Received r = parse(Bytes(f.bytes, f.bytes + f.size));
      ASSERT_EQ(r.channels.size(), 1u);
      for (int i = 0; i < 16; ++i) ASSERT_EQ(r.channels[0].value[i], c.value[i]);
    }
  }
}

TEST(Crsf, EveryBitFlipIsRejected) {
  for (size_t byte = 1; byte < kAllCentre.size(); ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      Bytes damaged = kAllCentre;
      damaged[byte] = static_cast<uint8_t>(damaged[byte] ^ (1u << bit));
      EXPECT_TRUE(parse(damaged).channels.empty()) << byte << ":" << bit;
    }
  }
}

TEST(Crsf, FindsFramesAfterGarbageAndInsideADamagedOne) {
  // Garbage with sync bytes and a length (48) that claims the good frames after it: once its 50
  // bytes are in and its check fails, every whole frame among them is found, in order.
  const Bytes garbage{0x00, 0xC8, 0xFF, 0xC8, 0x30, 0x16, 0x01, 0x02, 0xC8};
  Received r = parse(garbage + kAllCentre + kLinkStats + kAllLow);
  ASSERT_EQ(r.channels.size(), 2u);
  EXPECT_EQ(r.channels[0].value[0], 992u);
  EXPECT_EQ(r.channels[1].value[0], 172u);
  EXPECT_EQ(r.stats.size(), 1u);
  // A frame cut short (its sender restarted) and then a whole one: the whole one is found inside
  // the bytes the cut one was thought to own.
  const Bytes cut(kAllLow.begin(), kAllLow.begin() + 10);
  drivers::CrsfParser parser;
  r = parse(parser, cut + kAllCentre);
  ASSERT_EQ(r.channels.size(), 1u);
  EXPECT_EQ(r.channels[0].value[0], 992u);
  EXPECT_GE(parser.counters().check_failures, 1u);
  EXPECT_EQ(parser.counters().frames, 1u);
}

TEST(Crsf, LengthsOutsideTheFormatAreNoFrames) {
  for (int length : {0, 1, 63, 64, 255}) {
    drivers::CrsfParser parser;
    const Received r = parse(parser, Bytes{0xC8, static_cast<uint8_t>(length), 0x16} + kAllCentre);
    EXPECT_EQ(r.channels.size(), 1u) << length;
    EXPECT_GE(parser.counters().bad_lengths, 1u);
  }
}

TEST(Crsf, OtherTypesAndSizesAreFramesButNoPayload) {
  // A frame of another type (a device ping, 0x28, extended: destination, origin) passes the parser;
  // the decoders take only their own type with its own size.
  Bytes ping{0xC8, 0x04, 0x28, 0x00, 0xEA};
  ping.push_back(wire::crc8(&ping[2], 3));
  const Received r = parse(ping);
  EXPECT_EQ(r.frames, 1);
  EXPECT_TRUE(r.channels.empty());
  EXPECT_TRUE(r.stats.empty());
}

TEST(RcSticks, TheRangeMapsToTheWiresUnits) {
  EXPECT_EQ(drivers::rc_stick(992), 0);
  EXPECT_EQ(drivers::rc_stick(1002), 0);  // the deadband
  EXPECT_EQ(drivers::rc_stick(982), 0);
  EXPECT_EQ(drivers::rc_stick(1811), 1000);
  EXPECT_EQ(drivers::rc_stick(172), -1000);
  EXPECT_EQ(drivers::rc_stick(0), -1000);  // beyond the range: the end, never more
  EXPECT_EQ(drivers::rc_stick(2047), 1000);
  EXPECT_EQ(drivers::rc_lift(172), 0u);
  EXPECT_EQ(drivers::rc_lift(182), 0u);
  EXPECT_EQ(drivers::rc_lift(1811), 1000u);
  EXPECT_EQ(drivers::rc_lift(2047), 1000u);
  EXPECT_EQ(drivers::rc_lift(0), 0u);
  for (uint16_t v = 172; v < 1811; ++v) {  // monotonic: no step at the deadband's edges
    ASSERT_LE(drivers::rc_stick(v), drivers::rc_stick(static_cast<uint16_t>(v + 1)));
    ASSERT_LE(drivers::rc_stick(static_cast<uint16_t>(v + 1)) - drivers::rc_stick(v), 2);
    ASSERT_LE(drivers::rc_lift(v), drivers::rc_lift(static_cast<uint16_t>(v + 1)));
  }
}

TEST(RcSticks, TheSimulatorsRadioReadsBack) {
  for (int s = -1000; s <= 1000; ++s) {
    const int16_t read = drivers::rc_stick(drivers::rc_channel_of_stick(static_cast<int16_t>(s)));
    ASSERT_LE(read - s, 1);
    ASSERT_GE(read - s, -1);
    ASSERT_EQ(read == 0, s == 0);
  }
  for (uint16_t l = 0; l <= 1000; ++l) ASSERT_EQ(drivers::rc_lift(drivers::rc_channel_of_lift(l)), l);
}

TEST(RcSticks, TheMapPicksTheChannelsAndSwitchPositions) {
  drivers::CrsfChannels c;
  for (uint16_t& v : c.value) v = 992;
  drivers::RcChannelMap map;  // AETR: roll 1, pitch 2, lift 3, yaw 4, arm 5, mode 6
  c.value[2] = 1811;
  c.value[4] = 1811;
  c.value[5] = 172;
  drivers::RcSticks s = drivers::rc_sticks(c, map);
  EXPECT_EQ(s.lift, 1000u);
  EXPECT_TRUE(s.arm);
  EXPECT_EQ(s.mode_position, 0u);
  map.lift = 0;  // TAER
  map.roll = 2;
  s = drivers::rc_sticks(c, map);
  EXPECT_EQ(s.lift, 497u);
  EXPECT_EQ(s.roll, 1000);
  EXPECT_EQ(drivers::rc_switch_position(992), 1u);
  EXPECT_EQ(drivers::rc_switch_position(1400), 1u);
  EXPECT_EQ(drivers::rc_switch_position(1401), 2u);
  EXPECT_EQ(drivers::rc_switch_position(581), 0u);
}

}  // namespace
