#include <pc/core/radio_setup.hpp>

#include <cmath>

#include <common/drivers/rc_sticks.hpp>

namespace qrterm {

uint8_t role_channel(RcRole role, const wire::ParameterValues& params) {
  return static_cast<uint8_t>(params.get(kRcRoles[static_cast<size_t>(role)].channel) - 1);
}

std::string channel_roles(uint8_t ch, const wire::ParameterValues& params) {
  std::string roles;
  for (const RcRoleSpec& spec : kRcRoles) {
    if (role_channel(spec.role, params) == ch) roles += (roles.empty() ? "" : "+") + std::string(spec.name);
  }
  return roles;
}

// 172..1811 is 988..2012 us (common/drivers/crsf.hpp): 1024 us over 1639 steps, 992 at 1500 us.
int crsf_us(uint16_t crsf) {
  constexpr double kUsPerStep = 1024.0 / (drivers::kCrsfChannelMax - drivers::kCrsfChannelMin);
  return 988 + static_cast<int>(std::lround((crsf - drivers::kCrsfChannelMin) * kUsPerStep));
}

SwitchReading read_switch(uint16_t crsf) {
  constexpr const char* kPositions[] = {"low", "centre", "high"};
  const uint8_t position = drivers::rc_switch_position(crsf);
  return {position, kPositions[position]};
}

std::string arm_switch_text(uint16_t crsf) {
  const SwitchReading r = read_switch(crsf);
  return std::string(r.position == 2 ? "ON (" : "off (") + r.position_name + ")";
}

std::string mode_switch_text(uint16_t crsf) {
  const SwitchReading r = read_switch(crsf);
  return std::string(r.position_name) + ": " + wire::mode_name(wire::mode_at_switch(r.position));
}

StickEnds stick_ends(RcRole role, uint16_t lowest_crsf, uint16_t highest_crsf) {
  StickEnds e{};
  if (role == RcRole::lift) {
    e.low_permille = drivers::rc_lift(lowest_crsf);
    e.high_permille = drivers::rc_lift(highest_crsf);
    e.low_reached = e.low_permille == 0;
  } else {
    e.low_permille = drivers::rc_stick(lowest_crsf);
    e.high_permille = drivers::rc_stick(highest_crsf);
    e.low_reached = e.low_permille <= -kStickEndPermille;
  }
  e.high_reached = e.high_permille >= kStickEndPermille;
  return e;
}

const char* stick_ends_text(const StickEnds& ends) {
  if (ends.low_reached && ends.high_reached) return "both ends";
  if (ends.low_reached) return "no high end";
  if (ends.high_reached) return "no low end";
  return "no end yet";
}

void RadioSetup::start() { *this = RadioSetup{}; }

void RadioSetup::restart_ends() {
  lowest_ = value_;
  highest_ = value_;
}

void RadioSetup::on_channel(uint8_t ch, uint16_t crsf) {
  if (ch >= kRadioChannels || crsf == 0) return;
  heard_ = true;
  value_[ch] = crsf;
  if (lowest_[ch] == 0 || crsf < lowest_[ch]) lowest_[ch] = crsf;
  if (crsf > highest_[ch]) highest_[ch] = crsf;
}

namespace {
std::optional<uint16_t> known(uint16_t v) { return v == 0 ? std::nullopt : std::optional<uint16_t>(v); }
}  // namespace

std::optional<uint16_t> RadioSetup::value(uint8_t ch) const { return known(value_[ch]); }
std::optional<uint16_t> RadioSetup::lowest(uint8_t ch) const { return known(lowest_[ch]); }
std::optional<uint16_t> RadioSetup::highest(uint8_t ch) const { return known(highest_[ch]); }

}  // namespace qrterm
