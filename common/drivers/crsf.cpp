#include <common/crc8.hpp>
#include <common/drivers/crsf.hpp>

namespace drivers {
namespace {

CrsfFrameBytes frame_of(CrsfType type, const uint8_t* payload, uint8_t size) {
  CrsfFrameBytes f;
  f.bytes[0] = kCrsfSync;
  f.bytes[1] = static_cast<uint8_t>(size + 2);
  f.bytes[2] = static_cast<uint8_t>(type);
  for (uint8_t i = 0; i < size; ++i) f.bytes[3 + i] = payload[i];
  f.bytes[3 + size] = wire::crc8(&f.bytes[2], size + 1u);
  f.size = static_cast<uint8_t>(size + 4);
  return f;
}

}  // namespace

bool decode_rc_channels(const CrsfFrame& frame, CrsfChannels& out) {
  if (!is_rc_channels(frame)) return false;
  for (uint8_t ch = 0; ch < kCrsfChannelCount; ++ch) out.value[ch] = crsf_channel(frame.payload, ch);
  return true;
}

bool decode_link_statistics(const CrsfFrame& frame, CrsfLinkStatistics& out) {
  if (frame.type != static_cast<uint8_t>(CrsfType::link_statistics) || frame.size != kCrsfLinkStatsPayload)
    return false;
  const uint8_t* p = frame.payload;
  out.uplink_rssi_ant1 = p[0];
  out.uplink_rssi_ant2 = p[1];
  out.uplink_link_quality = p[2];
  out.uplink_snr = static_cast<int8_t>(p[3]);
  out.active_antenna = p[4];
  out.rf_mode = p[5];
  out.uplink_tx_power = p[6];
  out.downlink_rssi = p[7];
  out.downlink_link_quality = p[8];
  out.downlink_snr = static_cast<int8_t>(p[9]);
  return true;
}

CrsfFrameBytes encode_rc_channels(const CrsfChannels& channels) {
  uint8_t payload[kCrsfChannelsPayload] = {};
  uint32_t acc = 0;
  uint8_t bits = 0, at = 0;
  for (uint16_t v : channels.value) {
    acc |= uint32_t{v & 0x7FFu} << bits;
    bits = static_cast<uint8_t>(bits + 11);
    while (bits >= 8) {
      payload[at++] = static_cast<uint8_t>(acc);
      acc >>= 8;
      bits = static_cast<uint8_t>(bits - 8);
    }
  }
  return frame_of(CrsfType::rc_channels, payload, kCrsfChannelsPayload);
}

CrsfFrameBytes encode_link_statistics(const CrsfLinkStatistics& s) {
  const uint8_t payload[kCrsfLinkStatsPayload] = {s.uplink_rssi_ant1,      s.uplink_rssi_ant2,
                                                  s.uplink_link_quality,   static_cast<uint8_t>(s.uplink_snr),
                                                  s.active_antenna,        s.rf_mode,
                                                  s.uplink_tx_power,       s.downlink_rssi,
                                                  s.downlink_link_quality, static_cast<uint8_t>(s.downlink_snr)};
  return frame_of(CrsfType::link_statistics, payload, kCrsfLinkStatsPayload);
}

}  // namespace drivers
