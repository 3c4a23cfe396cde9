// What the flight tests on the fake board share: the firmware with a scripted signal chain on the
// fake board, the console's end of the serial line, and the console's clock, which runs the
// firmware's periods as it passes. Each test's fixture adds its own traffic (heartbeat, radio, a
// line at 115200 baud) around pass_ms().
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <common/messages.hpp>
#include <qr/boards/fake/fake_board.hpp>
#include <qr/core/flight.hpp>
#include <qr/core/scheduler.hpp>

#include "scripted_chain.hpp"

namespace qr::test {

using Firmware = Flight<ScriptedChain>;

template <class BoardT = fake::FakeBoard>
struct FakeFlight : ::testing::Test {
  BoardT board;
  Firmware flight;
  Scheduler<BoardT, Firmware> scheduler{board, flight};
  wire::FrameParser pc{wire::Listen::qr_to_pc};
  std::vector<wire::Frame> received;  // what the console has read of the QR's bytes
  uint8_t seq = 0;
  uint32_t elapsed_us = 0;  // the console's time
  uint32_t ticked_us = 0;   // firmware periods run so far

  FakeFlight() { board.sensors.battery_mv = 12000; }

  template <class M>
  void send(const M& m) {
    const wire::FrameBytes f = wire::encode(m);
    board.rx.insert(board.rx.end(), f.bytes, f.bytes + f.size);
  }
  // One millisecond of the console's time: the firmware runs the periods that ended in it, and
  // after_tick() sees each.
  template <class AfterTick>
  void pass_ms(AfterTick&& after_tick) {
    elapsed_us += 1000;
    for (; ticked_us + kPeriodUs <= elapsed_us; ticked_us += kPeriodUs) {
      scheduler.tick();
      after_tick();
    }
  }
  void pass_ms() {
    pass_ms([] {});
  }
  // Every byte the QR wrote so far reaches the console at once.
  void receive() {
    for (uint8_t b : board.tx) pc.push(b, [&](const wire::Frame& f) { received.push_back(f); });
    board.tx.clear();
  }
  template <class M>
  std::vector<M> got() const {
    std::vector<M> out;
    for (const wire::Frame& f : received) {
      M m;
      if (f.type == M::kType && wire::decode(f, m)) out.push_back(m);
    }
    return out;
  }
  // The debug text the QR sent, joined.
  std::string debug_text() const {
    std::string s;
    for (const auto& d : got<wire::DebugText>()) s.append(d.text, d.length());
    return s;
  }
};

}  // namespace qr::test
