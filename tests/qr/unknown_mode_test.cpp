// A mode number with no mode is a well-formed request: the QR answers it nack unknown_mode (not
// bad_value, which says a field was malformed) and stays where it is.
#include <gtest/gtest.h>

#include <vector>

#include <common/messages.hpp>
#include <qr/boards/fake/fake_board.hpp>
#include <qr/core/flight.hpp>
#include <qr/core/scheduler.hpp>

#include "scripted_chain.hpp"

namespace qr {
namespace {

using Firmware = Flight<test::ScriptedChain>;

struct UnknownModeTest : ::testing::Test {
  fake::FakeBoard board;
  Firmware flight;
  Scheduler<fake::FakeBoard, Firmware> scheduler{board, flight};
  wire::FrameParser pc{wire::Listen::qr_to_pc};
  std::vector<wire::Nack> nacks;
  std::vector<wire::Ack> acks;

  UnknownModeTest() { board.sensors.battery_mv = 12000; }

  void send_mode(uint8_t seq, uint8_t mode) {
    const wire::FrameBytes f = wire::encode(wire::ModeChange{seq, static_cast<Mode>(mode)});
    board.rx.insert(board.rx.end(), f.bytes, f.bytes + f.size);
    board.rx.insert(board.rx.end(), neutral.bytes, neutral.bytes + neutral.size);  // the heartbeat
    for (uint32_t t = 0; t < 20000; t += kPeriodUs) scheduler.tick();              // 20 ms
    for (uint8_t b : board.tx) {
      pc.push(b, [&](const wire::Frame& frame) {
        wire::Nack nack;
        wire::Ack ack;
        if (frame.type == wire::Nack::kType && wire::decode(frame, nack)) nacks.push_back(nack);
        if (frame.type == wire::Ack::kType && wire::decode(frame, ack)) acks.push_back(ack);
      });
    }
    board.tx.clear();
  }

  const wire::FrameBytes neutral = wire::encode(wire::Control{});
};

TEST_F(UnknownModeTest, EveryNumberBeyondTheModesIsAnsweredUnknownMode) {
  uint8_t seq = 0;
  for (unsigned mode : {unsigned{wire::kModeCount}, unsigned{wire::kModeCount} + 1, 128u, 255u}) {
    nacks.clear();
    send_mode(++seq, static_cast<uint8_t>(mode));
    ASSERT_EQ(nacks.size(), 1u) << "mode " << mode;
    EXPECT_EQ(nacks[0].type, wire::MessageType::mode_change);
    EXPECT_EQ(nacks[0].seq, seq);
    EXPECT_EQ(nacks[0].reason, wire::NackReason::unknown_mode) << "mode " << mode;
    EXPECT_EQ(flight.mode(), Mode::safe);
  }
  EXPECT_TRUE(acks.empty());
}

TEST_F(UnknownModeTest, TheLastModeIsStillAMode) {
  // The last mode number (the autotune) is known: refused for another reason (entered from full
  // control only, docs/safety.md rule 23); so is the one before it (the motor test: its own
  // request says the engine, rule 22).
  static_assert(wire::kModeCount - 1 == index(Mode::autotune));
  send_mode(1, wire::kModeCount - 1);
  send_mode(2, index(Mode::motor_test));
  ASSERT_EQ(nacks.size(), 2u);
  EXPECT_EQ(nacks[0].reason, wire::NackReason::not_from_this_mode);
  EXPECT_EQ(nacks[1].reason, wire::NackReason::bad_value);
}

}  // namespace
}  // namespace qr
