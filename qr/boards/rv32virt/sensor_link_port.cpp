#include <qr/boards/rv32virt/sensor_link_port.hpp>


namespace rv32virt {

void SensorLinkPort::poll() {
  console_.receive([this](uint8_t byte) {
    parser_.push(byte, [this](const simlink::LinkFrame& frame) {
      if (frame.decode(pending_)) have_pending_ = true;
    });
  });
}

const simlink::SensorFrame* SensorLinkPort::take_kick(uint32_t ground_received) {
  if (!have_pending_ || static_cast<int32_t>(ground_received - pending_.ground_bytes) < 0) return nullptr;
  have_pending_ = false;
  return &pending_;
}

void SensorLinkPort::send_engines(const simlink::EngineFrame& frame) {
  const simlink::LinkFrameBytes bytes = simlink::encode(frame);
  console_.send(bytes.bytes, bytes.size);
}

}  // namespace rv32virt
