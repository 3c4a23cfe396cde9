// A radio's channels to the pilot's controls: which channel is which stick or switch (the channel
// map, parameters rc_*_channel), and CRSF's 172..1811 to the wire's stick units (lift 0..1000,
// roll/pitch/yaw -1000..1000 per mille, common/units.hpp).
//
// A stick at rest reads a few units either side of 992 (and a lift stick at its stop a few above
// 172), so a deadband of kRcDeadband CRSF units reads as exactly neutral: leaving safe needs the
// sticks at 0 (docs/safety.md). Outside it the scale continues from 0, so there is no step.
#pragma once

#include <stdint.h>

#include <common/drivers/crsf.hpp>
#include <common/units.hpp>

namespace drivers {

inline constexpr uint16_t kRcDeadband = 10;
// Switch positions: below the midpoint of low and centre is low, above that of centre and high
// is high (a 2-position switch sends 172 or 1811, a 3-position one 992 between).
inline constexpr uint16_t kRcSwitchLowBelow = (kCrsfChannelMin + kCrsfChannelMid) / 2;  // 582
inline constexpr uint16_t kRcSwitchHighFrom = (kCrsfChannelMid + kCrsfChannelMax) / 2;  // 1401

// Channel numbers, 0-based (the parameters count from 1, as radios do).
struct RcChannelMap {
  uint8_t roll = 0, pitch = 1, lift = 2, yaw = 3, arm = 4, mode = 5;
};

struct RcSticks {
  uint16_t lift = 0;
  int16_t roll = 0, pitch = 0, yaw = 0;
  bool arm = false;           // the arm switch high
  uint8_t mode_position = 0;  // the mode switch: 0 low, 1 centre, 2 high
};

constexpr int16_t rc_stick(uint16_t v) {
  const int32_t d = static_cast<int32_t>(v) - kCrsfChannelMid;
  if (d >= -kRcDeadband && d <= kRcDeadband) return 0;
  constexpr int32_t kSpan = kCrsfChannelMax - kCrsfChannelMid - kRcDeadband;  // 809
  const int32_t s = (d > 0 ? d - kRcDeadband : d + kRcDeadband) * wire::kStickMax / kSpan;
  return static_cast<int16_t>(s > wire::kStickMax ? wire::kStickMax : s < -wire::kStickMax ? -wire::kStickMax : s);
}

constexpr uint16_t rc_lift(uint16_t v) {
  if (v <= kCrsfChannelMin + kRcDeadband) return 0;
  constexpr uint32_t kSpan = kCrsfChannelMax - kCrsfChannelMin - kRcDeadband;  // 1629
  const uint32_t l = (v - kCrsfChannelMin - kRcDeadband) * uint32_t{wire::kLiftMax} / kSpan;
  return static_cast<uint16_t>(l > wire::kLiftMax ? wire::kLiftMax : l);
}

constexpr uint8_t rc_switch_position(uint16_t v) { return v < kRcSwitchLowBelow ? 0 : v < kRcSwitchHighFrom ? 1 : 2; }

constexpr RcSticks rc_sticks(const CrsfChannels& c, const RcChannelMap& map) {
  RcSticks s;
  s.lift = rc_lift(c.value[map.lift & 15u]);
  s.roll = rc_stick(c.value[map.roll & 15u]);
  s.pitch = rc_stick(c.value[map.pitch & 15u]);
  s.yaw = rc_stick(c.value[map.yaw & 15u]);
  s.arm = rc_switch_position(c.value[map.arm & 15u]) == 2;
  s.mode_position = rc_switch_position(c.value[map.mode & 15u]);
  return s;
}

// The same from an RC channels frame, reading only the six channels the map names (what the
// flight does per frame); false when the frame is no RC channels frame.
constexpr bool rc_sticks(const CrsfFrame& frame, const RcChannelMap& map, RcSticks& out) {
  if (!is_rc_channels(frame)) return false;
  const uint8_t* p = frame.payload;
  out.lift = rc_lift(crsf_channel(p, map.lift));
  out.roll = rc_stick(crsf_channel(p, map.roll));
  out.pitch = rc_stick(crsf_channel(p, map.pitch));
  out.yaw = rc_stick(crsf_channel(p, map.yaw));
  out.arm = rc_switch_position(crsf_channel(p, map.arm)) == 2;
  out.mode_position = rc_switch_position(crsf_channel(p, map.mode));
  return true;
}

// The inverse, for the simulator's radio: a stick value to a CRSF channel value that reads as it
// (within one unit) and a lift to one that reads exactly as it.
constexpr uint16_t rc_channel_of_stick(int16_t stick) {
  if (stick == 0) return kCrsfChannelMid;
  constexpr int32_t kSpan = kCrsfChannelMax - kCrsfChannelMid - kRcDeadband;
  const int32_t s = stick > wire::kStickMax ? wire::kStickMax : stick < -wire::kStickMax ? -wire::kStickMax : stick;
  // The nearest channel value: it reads back within one unit (809 CRSF steps for 1000 stick units).
  const int32_t mag = ((s > 0 ? s : -s) * kSpan + wire::kStickMax - 1) / wire::kStickMax + kRcDeadband;
  return static_cast<uint16_t>(s > 0 ? kCrsfChannelMid + mag : kCrsfChannelMid - mag);
}

constexpr uint16_t rc_channel_of_lift(uint16_t lift) {
  if (lift == 0) return kCrsfChannelMin;
  constexpr uint32_t kSpan = kCrsfChannelMax - kCrsfChannelMin - kRcDeadband;
  const uint32_t l = lift > wire::kLiftMax ? wire::kLiftMax : lift;
  return static_cast<uint16_t>(kCrsfChannelMin + kRcDeadband + (l * kSpan + wire::kLiftMax - 1) / wire::kLiftMax);
}

}  // namespace drivers
