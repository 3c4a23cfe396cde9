// The radio receiver's side of the flight: CRSF bytes in (crsf_parser.hpp), the pilot's sticks and
// switches out through the channel map (rc_sticks.hpp), the link statistics kept for telemetry.
// Only a valid RC channels frame is life of the radio link: link statistics say how the link is,
// not that the pilot is there. The last RC frame's payload is kept as it came (22 bytes, not 16
// decoded channels: a copy per frame, a channel unpacked only when the stream samples it), so the
// console's radio screen sees all 16 channels (observables rc_ch1..rc_ch16). The mode the arm switch arms at each position of the mode switch
// is a column of the mode table (wire::mode_at_switch, common/mode.hpp).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/drivers/crsf.hpp>
#include <common/drivers/crsf_parser.hpp>
#include <common/drivers/rc_sticks.hpp>
#include <common/parameter_table.hpp>
#include <qr/core/flight_types.hpp>

namespace qr {

class RadioReceiver {
 public:
  // The channel map from the parameters (channels counted from 1, as radios do).
  void set_map(const wire::ParameterValues& p) {
    using wire::ParamId;
    const auto channel = [&p](ParamId id) { return static_cast<uint8_t>(p.get(id) - 1); };
    map_.roll = channel(ParamId::rc_roll_channel);
    map_.pitch = channel(ParamId::rc_pitch_channel);
    map_.lift = channel(ParamId::rc_lift_channel);
    map_.yaw = channel(ParamId::rc_yaw_channel);
    map_.arm = channel(ParamId::rc_arm_channel);
    map_.mode = channel(ParamId::rc_mode_channel);
  }

  // Received bytes; calls on_rc(const drivers::RcSticks&) for each valid RC frame they complete.
  template <class OnRc>
  void push(const uint8_t* bytes, size_t size, uint32_t now_us, OnRc&& on_rc) {
    parser_.push(bytes, size, [&](const drivers::CrsfFrame& frame) {
      drivers::RcSticks sticks;
      if (drivers::rc_sticks(frame, map_, sticks)) {
        for (uint8_t i = 0; i < drivers::kCrsfChannelsPayload; ++i) channels_[i] = frame.payload[i];
        heard_ = true;
        last_rc_us_ = now_us;
        on_rc(sticks);
      } else if (drivers::decode_link_statistics(frame, stats_)) {
        heard_ = true;
      }
    });
  }

  bool heard() const { return heard_; }
  uint32_t last_rc_us() const { return last_rc_us_; }
  const drivers::CrsfLinkStatistics& stats() const { return stats_; }
  // Channel `ch` (0..15) of the last RC frame in CRSF units (172..1811), as the transmitter sent
  // it, before the channel map; 0 before the first RC frame.
  uint16_t channel(uint8_t ch) const { return drivers::crsf_channel(channels_, ch); }
  const drivers::CrsfCounters& counters() const { return parser_.counters(); }

 private:
  drivers::CrsfParser parser_;
  drivers::RcChannelMap map_;
  drivers::CrsfLinkStatistics stats_;
  uint8_t channels_[drivers::kCrsfChannelsPayload] = {};
  uint32_t last_rc_us_ = 0;
  bool heard_ = false;
};

}  // namespace qr
