#include <qr/boards/rv32virt/sensor_link_port.hpp>

namespace rv32virt {

bool LinkI2cBus::begin(uint8_t channel, const drivers::I2cTransfer& transfer) {
  if (!queue_.begin(channel, transfer)) return false;
  simlink::I2cBeginFrame f;
  f.channel = channel;
  f.address = transfer.address;
  for (uint8_t i = 0; i < drivers::kI2cMaxWrite; ++i) f.write[i] = transfer.write[i];
  f.write_count = transfer.write_count;
  f.read_count = transfer.read_count;
  port_.send_i2c(f);
  return true;
}

void LinkI2cBus::done(const simlink::I2cDoneFrame& frame) {
  uint8_t channel = 0;
  drivers::I2cTransfer oldest;
  if (!queue_.next(channel, oldest)) return;  // nothing out: a stray end
  drivers::I2cReply reply;
  reply.count = frame.count;
  for (uint8_t i = 0; i < drivers::kI2cMaxRead; ++i) reply.data[i] = frame.data[i];
  // In lock-step over a lossless link the end is always the oldest transfer's; were it not, the
  // oldest is given up as a transfer the bus forgot (its driver counts that), not left out for ever.
  const bool matches = frame.channel == channel;
  queue_.finish(channel, matches ? static_cast<drivers::I2cResult>(frame.result) : drivers::I2cResult::idle,
                matches ? reply : drivers::I2cReply{});
}

void SensorLinkPort::poll() {
  console_.receive([this](uint8_t byte) {
    parser_.push(byte, [this](const simlink::LinkFrame& frame) {
      simlink::I2cDoneFrame done;
      if (frame.decode(pending_)) have_pending_ = true;
      else if (frame.decode(done)) i2c_.done(done);
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

void SensorLinkPort::send_i2c(const simlink::I2cBeginFrame& frame) {
  const simlink::LinkFrameBytes bytes = simlink::encode(frame);
  console_.send(bytes.bytes, bytes.size);
}

}  // namespace rv32virt
