#include <qr/boards/sim/sim_i2c_bus.hpp>

#include <algorithm>

namespace qrsim {
namespace {

constexpr uint64_t kBitNs = 1000000000u / SimI2cBus::kClockHz;  // 2500 ns at 400 kHz
constexpr uint32_t kByteBits = 9;                               // 8 data bits and the acknowledge

drivers::I2cResult result_of(sim::I2cAck ack) {
  switch (ack) {
    case sim::I2cAck::ack: return drivers::I2cResult::ok;
    case sim::I2cAck::address_nack: return drivers::I2cResult::address_nack;
    case sim::I2cAck::data_nack: return drivers::I2cResult::data_nack;
  }
  return drivers::I2cResult::bus_stuck;
}

}  // namespace

bool SimI2cBus::begin(uint8_t channel, const drivers::I2cTransfer& transfer) {
  if (!queue_.begin(channel, transfer)) return false;
  // The wire takes what is queued, back to back from now or from the end of the last transfer.
  uint8_t on_wire = 0;
  drivers::I2cTransfer t;
  while (queue_.next(on_wire, t)) {
    const uint64_t start = std::max(now_ns(), wire_free_at_ns_);
    drivers::I2cReply reply;
    const drivers::I2cResult result = run(t, start, reply);
    const uint64_t duration = drivers::transfer_time_ns(t, kClockHz);
    wire_free_at_ns_ = start + duration;
    ready_at_ns_[on_wire] = wire_free_at_ns_;
    busy_ns_ += duration;
    ++transfers_;
    queue_.finish(on_wire, result, reply);
  }
  return true;
}

drivers::I2cResult SimI2cBus::poll(uint8_t channel, drivers::I2cReply& reply) {
  if (channel < kChannels && now_ns() < ready_at_ns_[channel]) {
    return drivers::I2cResult::pending;  // still on the wire
  }
  return queue_.poll(channel, reply);
}

sim::I2cDevice* SimI2cBus::chip(uint8_t address) const {
  for (sim::I2cDevice* c : chips_) {
    if (c->address() == address) return c;
  }
  return nullptr;
}

const SimI2cBus::WireWindow* SimI2cBus::fault_at(uint8_t address, uint64_t start_ns) const {
  for (const WireWindow& w : faults_) {
    if (start_ns < w.from_ns || start_ns >= w.until_ns) continue;
    if (w.kind == WireFault::stuck || w.address == address) return &w;
  }
  return nullptr;
}

drivers::I2cResult SimI2cBus::run(const drivers::I2cTransfer& t, uint64_t start_ns, drivers::I2cReply& reply) {
  reply = drivers::I2cReply{};
  // A wire fault answers before any chip: the chip never sees the transfer.
  if (const WireWindow* fault = fault_at(t.address, start_ns)) {
    ++fault_answers_;
    if (fault->kind == WireFault::stuck) return drivers::I2cResult::bus_stuck;
    ++address_nacks_;
    std::fill(reply.data, reply.data + drivers::kI2cMaxRead, static_cast<uint8_t>(0xFF));
    return drivers::I2cResult::address_nack;
  }
  sim::I2cDevice* device = chip(t.address);
  if (device == nullptr) {
    ++address_nacks_;
    return drivers::I2cResult::address_nack;
  }
  // START, the address with the write bit, the bytes written: each acknowledged at its ninth bit.
  uint64_t bits = 0;
  if (t.write_count > 0 || t.read_count == 0) {
    bits = 1 + kByteBits + kByteBits * t.write_count;
    const sim::I2cAck ack = device->write(t.write, t.write_count, static_cast<double>(start_ns + bits * kBitNs) * 1e-9);
    if (ack != sim::I2cAck::ack) {
      if (ack == sim::I2cAck::address_nack) ++address_nacks_;
      return result_of(ack);
    }
  }
  if (t.read_count == 0) return drivers::I2cResult::ok;
  // The (repeated) START and the address with the read bit, acknowledged; then the bytes clocked out.
  bits += 1 + kByteBits;
  const uint8_t n = std::min(t.read_count, drivers::kI2cMaxRead);
  const sim::I2cAck ack = device->read(reply.data, n, static_cast<double>(start_ns + bits * kBitNs) * 1e-9);
  if (ack != sim::I2cAck::ack) {
    if (ack == sim::I2cAck::address_nack) ++address_nacks_;
    reply = drivers::I2cReply{};
    return result_of(ack);
  }
  reply.count = n;
  return drivers::I2cResult::ok;
}

}  // namespace qrsim
