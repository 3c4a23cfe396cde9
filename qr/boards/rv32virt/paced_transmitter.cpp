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

}  // namespace rv32virt
