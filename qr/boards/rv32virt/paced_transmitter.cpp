#include <qr/boards/rv32virt/paced_transmitter.hpp>

#include <common/link_timing.hpp>

namespace rv32virt {

bool PacedTransmitter::accept(uint64_t now_ns) {
  // ceil((line_free - now) / byte time) bytes are in flight: full at kCapacity of them.
  if (line_free_ns_ > now_ns && line_free_ns_ - now_ns > (kCapacity - 1) * uint64_t{wire::kLineByteTimeNs})
    return false;
  line_free_ns_ = (line_free_ns_ > now_ns ? line_free_ns_ : now_ns) + wire::kLineByteTimeNs;
  return true;
}

bool PacedReceiver::take(uint64_t now_ns, bool behind) {
  if (now_ns < next_ns_) return false;
  // When this byte came: straight after the one before, or, if the board has not looked for
  // longer than its FIFO holds, no earlier than the FIFO's depth ago (older bytes a real 16550
  // would have lost; QEMU's kept them for us, and they count as having come late).
  constexpr uint64_t kFifoNs = uint64_t{kFifoBytes} * wire::kLineByteTimeNs;
  const uint64_t came = now_ns - next_ns_ > kFifoNs ? now_ns - kFifoNs : next_ns_;
  next_ns_ = came + (behind ? wire::kLineByteTimeNs / 2 : wire::kLineByteTimeNs);
  return true;
}

}  // namespace rv32virt
