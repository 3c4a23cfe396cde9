// CRSF, the serial protocol of Crossfire and ExpressLRS receivers (420 000 baud, 8N1): the frames a
// receiver sends the flight computer and their payloads. A frame is
//
//   0xC8 (the flight computer's address, also the sync byte), length (type + payload + check,
//   2..62), type, payload, check (CRC-8/DVB-S2, poly 0xD5, over type and payload)
//
// RC channels (type 0x16): 22 bytes, 16 channels of 11 bits packed little-endian (channel 0 in the
// low bits of byte 0), 172..1811 with 992 the centre (ExpressLRS and Crossfire send 172 for
// 988 us and 1811 for 2012 us). Link statistics (type 0x14): 10 one-byte fields, below.
// Sources (facts): the TBS CRSF specification and the ExpressLRS documentation; the example frames
// in the tests are published ones (docs/drivers.md).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace drivers {

inline constexpr uint8_t kCrsfSync = 0xC8;     // address of the flight computer
inline constexpr uint8_t kCrsfMinLength = 2;   // type + check
inline constexpr uint8_t kCrsfMaxLength = 62;  // a frame is at most 64 bytes
inline constexpr uint8_t kCrsfMaxFrameBytes = 64;
inline constexpr uint8_t kCrsfMaxPayload = kCrsfMaxLength - 2;

enum class CrsfType : uint8_t { link_statistics = 0x14, rc_channels = 0x16 };

inline constexpr uint8_t kCrsfChannelCount = 16;
inline constexpr uint8_t kCrsfChannelsPayload = 22;  // 16 x 11 bits
inline constexpr uint8_t kCrsfLinkStatsPayload = 10;
inline constexpr uint16_t kCrsfChannelMin = 172;
inline constexpr uint16_t kCrsfChannelMid = 992;
inline constexpr uint16_t kCrsfChannelMax = 1811;

// A complete frame with a good check, as the parser hands it out.
struct CrsfFrame {
  uint8_t type = 0;
  uint8_t size = 0;  // payload bytes
  const uint8_t* payload = nullptr;
};

struct CrsfChannels {
  uint16_t value[kCrsfChannelCount] = {};
};

// Link statistics as the receiver reports them. RSSI in -dBm (a byte of 60 is -60 dBm), link
// quality in %, SNR in dB (signed).
struct CrsfLinkStatistics {
  uint8_t uplink_rssi_ant1 = 0;
  uint8_t uplink_rssi_ant2 = 0;
  uint8_t uplink_link_quality = 0;
  int8_t uplink_snr = 0;
  uint8_t active_antenna = 0;
  uint8_t rf_mode = 0;
  uint8_t uplink_tx_power = 0;  // an index: 0 0 mW, 1 10, 2 25, 3 100, 4 500, 5 1000, 6 2000, 7 250, 8 50
  uint8_t downlink_rssi = 0;
  uint8_t downlink_link_quality = 0;
  int8_t downlink_snr = 0;
};

// Channel `ch` (0..15) of an RC channels payload: it starts at bit 11 ch, and the three bytes from
// there hold all its 11 bits (two for the last channel).
constexpr uint16_t crsf_channel(const uint8_t* payload, uint8_t ch) {
  const uint32_t bit = 11u * (ch & 15u);
  const uint32_t at = bit >> 3;
  uint32_t word = payload[at] | (uint32_t{payload[at + 1]} << 8);
  if (at + 2 < kCrsfChannelsPayload) word |= uint32_t{payload[at + 2]} << 16;
  return static_cast<uint16_t>((word >> (bit & 7u)) & 0x7FFu);
}

constexpr bool is_rc_channels(const CrsfFrame& frame) {
  return frame.type == static_cast<uint8_t>(CrsfType::rc_channels) && frame.size == kCrsfChannelsPayload;
}

// Payload decoders: false (and `out` untouched) when the frame is not of that type and size.
bool decode_rc_channels(const CrsfFrame& frame, CrsfChannels& out);
bool decode_link_statistics(const CrsfFrame& frame, CrsfLinkStatistics& out);

// The other end (the simulator's receiver, tests): whole frames, sync to check.
struct CrsfFrameBytes {
  uint8_t bytes[kCrsfMaxFrameBytes] = {};
  uint8_t size = 0;
};
CrsfFrameBytes encode_rc_channels(const CrsfChannels& channels);
CrsfFrameBytes encode_link_statistics(const CrsfLinkStatistics& stats);

}  // namespace drivers
