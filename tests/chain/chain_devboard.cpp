// The flight chain on the RV32 devboard: the synthetic flight through FixedChain, its checksum
// against the host's (chain_checksum.hpp), and instructions retired per task call (average and
// worst over the run, from minstret; exact under QEMU -icount). Exits 0 only on a match.
#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/core/chain/flight_chain.hpp>

#include "chain_checksum.hpp"

namespace {

using qr::chain::checksum::kChainTaskCount;

struct InstructionTimer {
  uint32_t start = 0;
  uint32_t calls[kChainTaskCount] = {};
  uint32_t total[kChainTaskCount] = {};
  uint32_t worst[kChainTaskCount] = {};
  void begin() { start = rv32virt::instret(); }
  void end(int task) {
    const uint32_t spent = rv32virt::instret() - start;
    ++calls[task];
    total[task] += spent;
    if (spent > worst[task]) worst[task] = spent;
  }
};

const char* const kTaskNames[kChainTaskCount] = {"filter", "calibrate", "estimate", "control_attitude", "control_yaw",
                                                 "mix"};

qr::FixedChain chain;
InstructionTimer timer;

}  // namespace

int main() {
  const uint32_t sum = qr::chain::checksum::fly(chain, timer);
  for (int i = 0; i < kChainTaskCount; ++i) {
    rv32virt::puts("{\"task\":\"");
    rv32virt::puts(kTaskNames[i]);
    rv32virt::puts("\",\"calls\":");
    rv32virt::put_u32(timer.calls[i]);
    rv32virt::puts(",\"instr_avg\":");
    rv32virt::put_ratio(timer.total[i], timer.calls[i] == 0 ? 1 : timer.calls[i]);
    rv32virt::puts(",\"instr_max\":");
    rv32virt::put_u32(timer.worst[i]);
    rv32virt::puts("}\n");
  }
  rv32virt::puts("chain checksum ");
  rv32virt::put_u32(sum);
  const bool match = sum == qr::chain::checksum::kExpected;
  rv32virt::puts(match ? " matches the host\n" : " differs from the host's\n");
  return match ? 0 : 1;
}
