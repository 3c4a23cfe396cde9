// Test mode on the devboard: the recording QEMU put in memory, through the flight chain tick by
// tick, one CSV row per tick on the UART: the same rows as the host replay (docs/replay.md),
// from the same code (qr/core/replay_tick.hpp: the flight's own task table). `scripts/devboard --replay` runs it.
#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/boards/rv32virt/recording.hpp>
#include <qr/boards/rv32virt/virt_map.hpp>
#include <qr/core/chain/flight_chain.hpp>
#include <qr/core/replay_tick.hpp>

namespace {

template <uint32_t Hz>
int replay(const rv32virt::Recording& recording) {
  using Chain = qr::FlightChain<qr::chain::FixedNumbers, Hz>;
  static Chain chain;  // large: not on the stack
  static qr::ChainReplay<Chain> test_mode(
      chain, recording.count() == 0 ? qr::ChainReplay<Chain>::kPeriodUs : recording.time_us(0));
  rv32virt::puts("time_us,mode");
  for (const auto& column : qr::kReplayColumns<Chain>) {
    rv32virt::putc(',');
    rv32virt::puts(column.name);
  }
  rv32virt::putc('\n');

  for (uint32_t i = 0; i < recording.count(); ++i) {
    const rv32virt::RecordedTick tick = recording.at(i);
    const wire::Mode mode = test_mode.tick(tick.sample, tick.sticks);
    rv32virt::put_u32(recording.time_us(i));
    rv32virt::putc(',');
    rv32virt::put_u32(static_cast<uint32_t>(mode));
    for (const auto& column : qr::kReplayColumns<Chain>) {
      rv32virt::putc(',');
      rv32virt::put_i32(column.value(chain));
    }
    rv32virt::putc('\n');
  }
  return 0;
}

}  // namespace

int main() {
  const rv32virt::Recording recording(reinterpret_cast<const uint8_t*>(rv32virt::map::kRecording));
  if (!recording.valid()) {
    rv32virt::puts("replay: no recording at 0x80400000 (scripts/devboard --replay IN.csv loads one)\n");
    return 1;
  }
  if (recording.rate_hz() == 1000) return replay<1000>(recording);
  if (recording.rate_hz() == 500) return replay<500>(recording);
  rv32virt::puts("replay: the recording's rate must be 1000 or 500 Hz\n");
  return 1;
}
