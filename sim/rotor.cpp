#include <sim/rotor.hpp>

namespace sim {

std::array<RotorGeometry, kRotorCount> rotor_geometry(const VehicleParams& v) {
  const double l = v.arm_m;
  const double up = -v.hub_height_m;  // body z points down
  std::array<RotorGeometry, kRotorCount> rotors = {{
      {{l, 0, up}, +1},   // 0 front, clockwise
      {{0, l, up}, -1},   // 1 right, counter-clockwise
      {{-l, 0, up}, +1},  // 2 back, clockwise
      {{0, -l, up}, -1},  // 3 left, counter-clockwise
  }};
  for (size_t i = 0; i < kRotorCount; ++i) {
    if (v.wiring.reversed[i] != 0) rotors[i] = turned_the_other_way(rotors[i]);
  }
  return rotors;
}

}  // namespace sim
