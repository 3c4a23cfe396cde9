// The flight chain on the RV32 devboard: the synthetic flight through FixedChain, its checksum
// against the host's (chain_checksum.hpp), and instructions retired per task run (average and
// worst over the run, from minstret; exact under QEMU -icount), as the flight's scheduler counts them. Exits 0 only on a match.
#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/core/chain/flight_chain.hpp>

#include "chain_checksum.hpp"

namespace {

struct Instret {
  static uint32_t now() { return rv32virt::instret(); }
};

qr::FixedChain chain;
qr::SchedulerStats<qr::kFlightTaskCount> stats;

}  // namespace

int main() {
  const uint32_t sum = qr::chain::checksum::fly<qr::FixedChain, Instret>(chain, &stats);
  using Replay = qr::ChainReplay<qr::FixedChain, Instret>;
  for (uint8_t i = 0; i < qr::kFlightTaskCount; ++i) {
    const qr::CycleStats& c = stats.task[i];
    if (c.count == 0) continue;
    rv32virt::puts("{\"task\":\"");
    rv32virt::puts(Replay::Context::kTasks[i].name);
    rv32virt::puts("\",\"calls\":");
    rv32virt::put_u32(c.count);
    rv32virt::puts(",\"instr_avg\":");
    rv32virt::put_ratio(static_cast<uint32_t>(c.sum()), c.count);
    rv32virt::puts(",\"instr_max\":");
    rv32virt::put_u32(c.max);
    rv32virt::puts("}\n");
  }
  rv32virt::puts("chain checksum ");
  rv32virt::put_u32(sum);
  const bool match = sum == qr::chain::checksum::kExpected;
  rv32virt::puts(match ? " matches the host\n" : " differs from the host's\n");
  return match ? 0 : 1;
}
