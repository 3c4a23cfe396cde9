#include <pc/core/radio_pilot.hpp>

namespace qrterm {

RadioArming radio_arming(wire::Mode mode, bool in_safe, bool simulator, const TelemetryModel& telemetry) {
  if (!simulator || !wire::armed_by_the_radio(mode) || !radio_flies(telemetry)) return RadioArming::console;
  return in_safe ? RadioArming::arm : RadioArming::refused;
}

}  // namespace qrterm
