// Fuzz target: arbitrary text as a simulator vehicle file (sim/vehicle.cpp, docs/simulator.md
// section 3). Beyond what ASan and UBSan catch: a refused file says why; an accepted one has only
// finite, positive masses and inertias.
#include <stddef.h>
#include <stdint.h>

#include <cmath>
#include <string>

#include <sim/vehicle.hpp>

#include "fuzz_checks.hpp"

using fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sim::VehicleParams vehicle;
  std::string error;
  if (!sim::parse_vehicle(text, vehicle, error)) {
    require(!error.empty());
    return 0;
  }
  require(std::isfinite(vehicle.mass_kg) && vehicle.mass_kg > 0);
  require(std::isfinite(vehicle.inertia_kgm2.x) && vehicle.inertia_kgm2.x > 0);
  require(std::isfinite(vehicle.inertia_kgm2.y) && vehicle.inertia_kgm2.y > 0);
  require(std::isfinite(vehicle.inertia_kgm2.z) && vehicle.inertia_kgm2.z > 0);
  return 0;
}
