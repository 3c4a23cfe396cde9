// Which joystick axis is which pilot input, which way round, how big a deadband, and which button
// aborts. Joysticks differ (a throttle lever may be axis 2 or 3, pushed forward may read negative),
// so this lives in a small file (`--joystick-map`) rather than in the code.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include <pc/core/settings_text.hpp>
#include <pc/core/sticks.hpp>

namespace qrterm {

struct AxisBinding {
  uint8_t axis = 0;
  bool invert = false;
};

// Defaults fit the common flight stick layout (Logitech Extreme 3D and alike): x roll, y pitch,
// twist yaw, a throttle lever that reads -32767 when pushed fully forward. The Linux driver reads
// a stick pushed forward (or left) as negative; pulled back is nose up, which is positive pitch
// (docs/conventions.md), so pitch needs no inversion.
struct JoystickMap {
  AxisBinding lift{3, true};
  AxisBinding roll{0, false};
  AxisBinding pitch{1, false};
  AxisBinding yaw{2, false};
  uint8_t abort_button = 0;        // the trigger ("fire")
  int32_t deadband_permille = 50;  // of full deflection; around the centre, and at the throttle's low end

  // Axis values (-32767..32767 as the driver reports them) -> pilot inputs in the wire's scale.
  int32_t stick(const AxisBinding& binding, int32_t raw) const;
  int32_t lift_of(int32_t raw) const;
};

struct JoystickMapFile {
  JoystickMap map;
  std::vector<LineError> errors;
};

JoystickMapFile parse_joystick_map(const std::string& text);
std::string format_joystick_map(const JoystickMap& map);

}  // namespace qrterm
