// The four pilot inputs in the wire's scale: lift 0..1000, roll/pitch/yaw -1000..1000 (per mille of
// full deflection), signs as in docs/conventions.md. Wider than the wire's types so sums of
// joystick and trim can be formed before they are clamped.
#pragma once

#include <stdint.h>

namespace qrterm {

struct Sticks {
  int32_t lift = 0;
  int32_t roll = 0;
  int32_t pitch = 0;
  int32_t yaw = 0;

  constexpr bool operator==(const Sticks&) const = default;
};

}  // namespace qrterm
