#include <pc/core/telemetry_model.hpp>

namespace qrterm {

void TelemetryModel::on(const wire::TelemetryAttitude& message) {
  // The tick counts attitude frames sent; a gap is frames lost on the way. A jump of more than
  // half the counter is more likely a QR restart than 128 lost frames.
  if (attitude) {
    const uint8_t gap = static_cast<uint8_t>(message.tick - attitude->tick - 1);
    if (gap < 128) attitude_lost += gap;
  }
  attitude = message;
  ++attitude_frames;
}

}  // namespace qrterm
