// The radio screen: the sixteen channels of the QR's radio receiver as bars with their value in
// microseconds, the control the parameters give each, each stick's lowest and highest value since
// the screen opened (and whether the firmware reads its ends), and the arm and mode switches as
// the firmware reads them.
#include <algorithm>

#include <pc/core/radio_pilot.hpp>
#include <pc/core/radio_setup.hpp>
#include <pc/ui/screen_draw.hpp>
#include <pc/ui/screens.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {
namespace {

constexpr int kBarColumn = 21;
constexpr int kEndsColumns = 25;  // "1500..2012 no high end", "centre: yaw control"

// The first stick or switch the parameters put on channel `ch`, if any.
const RcRoleSpec* role_on(uint8_t ch, const wire::ParameterValues& params) {
  for (const RcRoleSpec& spec : kRcRoles) {
    if (role_channel(spec.role, params) == ch) return &spec;
  }
  return nullptr;
}

// What the firmware makes of the channel: a stick's ends, a switch's position.
void draw_reading(const RadioSetup& radio, uint8_t ch, const RcRoleSpec& role, int row, int column) {
  const std::optional<uint16_t> value = radio.value(ch);
  if (!value) return;
  if (role.role == RcRole::arm) {
    const bool on = read_switch(*value).position == 2;
    put(row, column, arm_switch_text(*value), on ? kWarning : kInfo, on ? A_BOLD | A_REVERSE : A_NORMAL);
  } else if (role.role == RcRole::mode) {
    put(row, column, mode_switch_text(*value), kInfo);
  } else {
    const StickEnds ends = stick_ends(role.role, *radio.lowest(ch), *radio.highest(ch));
    const bool both = ends.low_reached && ends.high_reached;
    put(row, column,
        text("%4d..%-4d %s", crsf_us(*radio.lowest(ch)), crsf_us(*radio.highest(ch)), stick_ends_text(ends)),
        both ? kInfo : kWarning, both ? A_NORMAL : A_BOLD);
  }
}

void draw_channel(const Console& console, uint8_t ch, int row, int bar) {
  const RadioSetup& radio = console.streams().radio();
  const wire::ParameterValues& params = console.params();
  const RcRoleSpec* role = role_on(ch, params);
  put(row, 0, text("%2d", ch + 1), role != nullptr ? 0 : kDim, role != nullptr ? A_BOLD : A_NORMAL);
  put(row, 3, channel_roles(ch, params), 0, A_BOLD);
  const std::optional<uint16_t> value = radio.value(ch);
  if (!value) {
    put(row, 13, "  -- us", kDim);
    put(row, kBarColumn, std::string(static_cast<size_t>(bar), '.'), kDim);
    return;
  }
  put(row, 13, text("%4d us", crsf_us(*value)), role != nullptr ? 0 : kDim);
  const int span = drivers::kCrsfChannelMax - drivers::kCrsfChannelMin;
  const int filled = std::clamp((*value - drivers::kCrsfChannelMin) * bar / span, 0, bar);
  put(row, kBarColumn, std::string(static_cast<size_t>(filled), '#'), role != nullptr ? kBar : kDim, A_BOLD);
  put(row, kBarColumn + filled, std::string(static_cast<size_t>(bar - filled), '.'), kDim);
  if (role != nullptr) draw_reading(radio, ch, *role, row, kBarColumn + bar + 1);
}

}  // namespace

void draw_radio_screen(const Console& console, int top, int rows, int width) {
  const StreamSession& streams = console.streams();
  const RadioSetup& radio = streams.radio();
  const wire::ParameterValues& params = console.params();
  put(top, 0, "RADIO", 0, A_BOLD);
  // Streaming zeros: the QR's receiver has had no RC frame.
  const bool silent = streams.radio_streaming() && !radio.heard();
  put(top, 6, streams.radio_state() + (silent ? ": no RC frame yet (receiver bound?)" : ""),
      radio.heard() ? kDim : kWarning);
  const int bar = std::max(16, width - kBarColumn - 1 - kEndsColumns);
  if (radio.heard()) put(top, kBarColumn + bar + 1, "since opened, us", kDim);
  for (uint8_t ch = 0; ch < kRadioChannels; ++ch) draw_channel(console, ch, top + 1 + ch, bar);

  // The switches as the firmware reads them, and who flies.
  const int row = top + 1 + kRadioChannels;
  const uint8_t arm = role_channel(RcRole::arm, params);
  const uint8_t mode = role_channel(RcRole::mode, params);
  const std::optional<uint16_t> arm_value = radio.value(arm);
  const std::optional<uint16_t> mode_value = radio.value(mode);
  put(row, 0,
      text("arm ch %d: %s   mode ch %d: %s", arm + 1, arm_value ? arm_switch_text(*arm_value).c_str() : "--", mode + 1,
           mode_value ? mode_switch_text(*mode_value).c_str() : "--"));
  const bool flies = radio_flies(console.telemetry());
  put(row, width - 12, flies ? "RADIO FLIES" : "PC flies", flies ? kWarning : kDim, flies ? A_BOLD : A_NORMAL);
  put(top + rows - 2, 0, "space: count the ends again   Tab: cockpit   the cockpit's keys still act", kDim);
  draw_prompt_or_log(console, top + rows - 1, width);
}

}  // namespace qrterm
