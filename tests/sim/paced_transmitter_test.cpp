// The devboard's paced ground transmitter (qr/boards/rv32virt/paced_transmitter.hpp) against the
// simulator's line (qr/boards/sim/serial_line.hpp): the firmware must see the same refusals on
// both boards, or the host build and the binary would not fly the same flight.
#include <gtest/gtest.h>

#include <stdint.h>

#include <qr/boards/rv32virt/paced_transmitter.hpp>
#include <qr/boards/sim/serial_line.hpp>

namespace {

TEST(PacedTransmitter, HoldsThirtyTwoBytesAndFreesOneAByteTimeLater) {
  rv32virt::PacedTransmitter tx;
  for (int i = 0; i < 32; ++i) EXPECT_TRUE(tx.accept(1000)) << i;
  EXPECT_FALSE(tx.accept(1000));
  EXPECT_FALSE(tx.accept(1000 + qrsim::kByteTimeNs - 1));
  EXPECT_TRUE(tx.accept(1000 + qrsim::kByteTimeNs));
  EXPECT_FALSE(tx.accept(1000 + qrsim::kByteTimeNs));
}

TEST(PacedTransmitter, RefusesExactlyWhenTheSimulatedLineDoes) {
  // Ticks of 1 ms with now and then a late one, bursts of 0 to 20 bytes: the bursts the
  // scheduler hands out (16 at most) and more.
  rv32virt::PacedTransmitter paced;
  qrsim::SerialLine line(32);
  uint64_t state = 0x9E3779B97F4A7C15ull;
  const auto next = [&state] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return state;
  };
  uint64_t now_ns = 0;
  int refusals = 0;
  for (int tick = 0; tick < 20000; ++tick) {
    now_ns += 1000000ull * (next() % 50 == 0 ? 1 + next() % 5 : 1);
    const int burst = static_cast<int>(next() % 21);
    for (int i = 0; i < burst; ++i) {
      const bool simulated = line.send(0x55, now_ns);
      ASSERT_EQ(paced.accept(now_ns), simulated) << "tick " << tick << ", byte " << i;
      refusals += simulated ? 0 : 1;
    }
    uint8_t byte = 0;
    while (line.receive(now_ns, byte)) {
    }
  }
  EXPECT_GT(refusals, 1000) << "the bursts must fill the buffer often for the comparison to mean something";
}

// The receiving end (docs/devboard.md, "The ground line"): bytes are taken no faster than the
// line brings them, a FIFO's worth at once after a pause, twice the pace while a backlog waits.
TEST(PacedReceiver, OnceCaughtUpTakesOneByteAByteTime) {
  rv32virt::PacedReceiver rx;
  const uint64_t t0 = 50'000'000;
  while (rx.take(t0, false)) {
  }
  for (uint64_t k = 1; k <= 100; ++k) {
    EXPECT_FALSE(rx.take(t0 + k * qrsim::kByteTimeNs - 1, false)) << k;
    EXPECT_TRUE(rx.take(t0 + k * qrsim::kByteTimeNs, false)) << k;
    EXPECT_FALSE(rx.take(t0 + k * qrsim::kByteTimeNs, false)) << k;
  }
}

TEST(PacedReceiver, TakesAtMostTheLinesRateOverAnyStretch) {
  // Polled once a millisecond, as the board's kick wait does, with bytes always waiting: over 10 s
  // no more than the line's 11,520 bytes a second (and its FIFO's 16 once), and no fewer.
  rv32virt::PacedReceiver rx;
  uint64_t taken = 0;
  for (uint64_t ms = 1; ms <= 10000; ++ms) {
    while (rx.take(ms * 1'000'000, false)) ++taken;
  }
  const uint64_t line = 10'000'000'000ull / qrsim::kByteTimeNs;
  EXPECT_LE(taken, line + rv32virt::PacedReceiver::kFifoBytes);
  EXPECT_GE(taken, line - 1);
}

TEST(PacedReceiver, AfterAPauseTakesAFifosWorthAtOnce) {
  rv32virt::PacedReceiver rx;
  int burst = 0;
  while (rx.take(1'000'000'000, false)) ++burst;
  EXPECT_EQ(burst, static_cast<int>(rv32virt::PacedReceiver::kFifoBytes) + 1);
}

TEST(PacedReceiver, CatchesUpAtTwiceThePaceWhileBehind) {
  rv32virt::PacedReceiver fast, plain;
  uint64_t taken_fast = 0, taken_plain = 0;
  for (uint64_t ms = 1; ms <= 1000; ++ms) {
    while (fast.take(ms * 1'000'000, true)) ++taken_fast;
    while (plain.take(ms * 1'000'000, false)) ++taken_plain;
  }
  EXPECT_NEAR(static_cast<double>(taken_fast), 2.0 * static_cast<double>(taken_plain), 20.0);
}

}  // namespace
