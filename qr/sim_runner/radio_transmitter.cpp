#include <qr/sim_runner/radio_transmitter.hpp>

#include <common/drivers/rc_sticks.hpp>

namespace qrsim {
namespace {

constexpr uint64_t kRcPeriodNs = 1000000000ull / 150;
constexpr uint32_t kStatsEvery = 15;

// A link as a receiver a few metres from its transmitter reports it.
drivers::CrsfLinkStatistics nearby_link() {
  drivers::CrsfLinkStatistics stats;
  stats.uplink_rssi_ant1 = 45;
  stats.uplink_rssi_ant2 = 47;
  stats.uplink_link_quality = 100;
  stats.uplink_snr = 10;
  stats.rf_mode = 4;
  stats.uplink_tx_power = 3;
  stats.downlink_rssi = 50;
  stats.downlink_link_quality = 100;
  stats.downlink_snr = 8;
  return stats;
}

}  // namespace

drivers::CrsfChannels transmitter_channels(const wire::Control& sticks, bool arm_switch_on,
                                           wire::ModeSwitch mode_switch) {
  drivers::CrsfChannels c;
  for (uint16_t& v : c.value) v = drivers::kCrsfChannelMid;
  c.value[0] = drivers::rc_channel_of_stick(sticks.roll);
  c.value[1] = drivers::rc_channel_of_stick(sticks.pitch);
  c.value[2] = drivers::rc_channel_of_lift(sticks.lift);
  c.value[3] = drivers::rc_channel_of_stick(sticks.yaw);
  c.value[4] = arm_switch_on ? drivers::kCrsfChannelMax : drivers::kCrsfChannelMin;
  c.value[5] = mode_switch == wire::ModeSwitch::low      ? drivers::kCrsfChannelMin
               : mode_switch == wire::ModeSwitch::centre ? drivers::kCrsfChannelMid
                                                         : drivers::kCrsfChannelMax;
  return c;
}

bool RadioTransmitter::arm(wire::Mode mode, uint64_t now_us) {
  if (!wire::armed_by_the_radio(mode)) return false;
  arming_ = true;
  mode_ = mode;
  arm_at_us_ = now_us + kArmSwitchOffUs;
  return true;
}

void RadioTransmitter::step(uint64_t now_us, bool silent, SimBoard& board) {
  if (now_us * 1000 < next_rc_ns_) return;
  next_rc_ns_ += kRcPeriodNs;
  if (next_rc_ns_ < now_us * 1000) next_rc_ns_ = now_us * 1000 + kRcPeriodNs;
  if (silent) return;
  const drivers::CrsfFrameBytes f = drivers::encode_rc_channels(
      transmitter_channels(sticks_, arm_switch_on(now_us), wire::mode_spec(mode_).armed_at));
  board.radio_send(f.bytes, f.size);
  if (++rc_frames_ % kStatsEvery == 0) {
    const drivers::CrsfFrameBytes s = drivers::encode_link_statistics(nearby_link());
    board.radio_send(s.bytes, s.size);
  }
}

}  // namespace qrsim
