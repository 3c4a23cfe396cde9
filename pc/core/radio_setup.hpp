// The radio screen's state, without a terminal (docs/console.md, "The radio screen"): the sixteen
// channels of the QR's radio receiver as its streams bring them (observables rc_ch1..rc_ch16,
// docs/protocol.md section 13.5), the lowest and highest value of each since the screen opened,
// and what the firmware makes of them: which channel the parameters rc_*_channel give each
// control, the arm and mode switch positions, and whether each stick reaches its ends. The
// readings are the firmware's own functions (common/drivers/rc_sticks.hpp), so the screen says
// what the QR will read, not what the console thinks of the values.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <optional>
#include <string>

#include <common/drivers/crsf.hpp>
#include <common/mode.hpp>
#include <common/parameter_table.hpp>

namespace qrterm {

inline constexpr uint8_t kRadioChannels = drivers::kCrsfChannelCount;
// The streams' rate: above the screen's 10 redraws a second, 1200 B/s of the line for all 16.
inline constexpr uint16_t kRadioStreamHz = 25;
// A stick reaches an end when the firmware reads at least this share of full deflection there
// (per mille): a transmitter whose travel stops short gives the pilot less than the parameters'
// full tilt, rate or lift. The lift's low end must read 0 exactly: leaving safe needs it.
inline constexpr int kStickEndPermille = 950;

// The controls a channel can be, one row each: the parameter that names its channel.
enum class RcRole : uint8_t { roll, pitch, lift, yaw, arm, mode };
struct RcRoleSpec {
  RcRole role;
  const char* name;
  wire::ParamId channel;  // rc_*_channel: 1..16, as radios count
  bool stick;             // a stick: its ends are checked
};
inline constexpr RcRoleSpec kRcRoles[] = {
    {RcRole::roll, "roll", wire::ParamId::rc_roll_channel, true},
    {RcRole::pitch, "pitch", wire::ParamId::rc_pitch_channel, true},
    {RcRole::lift, "lift", wire::ParamId::rc_lift_channel, true},
    {RcRole::yaw, "yaw", wire::ParamId::rc_yaw_channel, true},
    {RcRole::arm, "arm", wire::ParamId::rc_arm_channel, false},
    {RcRole::mode, "mode", wire::ParamId::rc_mode_channel, false},
};

// The channel (0..15) the parameters give a control.
uint8_t role_channel(RcRole role, const wire::ParameterValues& params);
// The controls on channel `ch`, "roll" or "lift+arm" (a map that puts two on one channel); empty
// for a channel the QR does not read.
std::string channel_roles(uint8_t ch, const wire::ParameterValues& params);

// A CRSF value in microseconds, as receivers convert it (172 is 988 us, 992 1500, 1811 2012).
int crsf_us(uint16_t crsf);

// A switch as the firmware reads its channel: position 0 low, 1 centre, 2 high.
struct SwitchReading {
  uint8_t position;
  const char* position_name;  // "low", "centre", "high"
};
SwitchReading read_switch(uint16_t crsf);
// The arm switch: on only high (drivers::rc_sticks). "ON (high)", "off (centre)".
std::string arm_switch_text(uint16_t crsf);
// The mode switch: its position and the mode the arm switch arms there. "low: manual".
std::string mode_switch_text(uint16_t crsf);

// A stick's ends as the firmware reads them, in per mille of full deflection (the lift 0..1000,
// the others -1000..1000), and whether each reaches its end.
struct StickEnds {
  int low_permille;
  int high_permille;
  bool low_reached;
  bool high_reached;
};
StickEnds stick_ends(RcRole role, uint16_t lowest_crsf, uint16_t highest_crsf);
// "both ends", "no low end", "no high end", "no end yet".
const char* stick_ends_text(const StickEnds& ends);

class RadioSetup {
 public:
  // The screen opened: nothing known yet, the ends counted from now.
  void start();
  // The ends counted again from the values now (the screen's space key).
  void restart_ends();
  // Channel `ch` (0..15) as a sample brought it. 0 is the QR's "no RC frame yet", not a value.
  void on_channel(uint8_t ch, uint16_t crsf);

  bool heard() const { return heard_; }
  std::optional<uint16_t> value(uint8_t ch) const;
  // The lowest and highest value seen since start(); empty before the first.
  std::optional<uint16_t> lowest(uint8_t ch) const;
  std::optional<uint16_t> highest(uint8_t ch) const;

 private:
  std::array<uint16_t, kRadioChannels> value_{};  // 0: not seen
  std::array<uint16_t, kRadioChannels> lowest_{};
  std::array<uint16_t, kRadioChannels> highest_{};
  bool heard_ = false;
};

}  // namespace qrterm
