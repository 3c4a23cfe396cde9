// The QR's transmit queue: frames leave whole and in order, and an answer goes in ahead of every
// frame not yet begun, behind the answers before it, never inside a frame.
#include <gtest/gtest.h>

#include <vector>

#include <common/messages.hpp>
#include <qr/core/transmit_queue.hpp>

namespace qr {
namespace {

using Bytes = std::vector<uint8_t>;

Bytes bytes_of(const wire::FrameBytes& f) { return {f.bytes, f.bytes + f.size}; }
Bytes joined(std::initializer_list<wire::FrameBytes> frames) {
  Bytes out;
  for (const wire::FrameBytes& f : frames) {
    const Bytes b = bytes_of(f);
    out.insert(out.end(), b.begin(), b.end());
  }
  return out;
}

Bytes take(TransmitQueue& q, size_t max) {
  Bytes out;
  uint8_t byte = 0;
  while (out.size() < max && q.peek(byte)) {
    out.push_back(byte);
    q.pop();
  }
  return out;
}

const wire::FrameBytes kAttitude = wire::encode(wire::TelemetryAttitude{7, wire::Mode::safe, 0, 1, 2, 3});
const wire::FrameBytes kRates = wire::encode(wire::TelemetryRates{4, 5, 6});
const wire::FrameBytes kAck = wire::encode(wire::Ack{wire::MessageType::mode_change, 9});
const wire::FrameBytes kNack = wire::encode(wire::Nack{wire::MessageType::param_set, 10, wire::NackReason::busy});

TEST(TransmitQueue, FramesLeaveWholeAndInOrder) {
  TransmitQueue q;
  ASSERT_TRUE(q.push(kAttitude));
  ASSERT_TRUE(q.push(kRates));
  EXPECT_EQ(q.size(), uint32_t{kAttitude.size} + kRates.size);
  EXPECT_EQ(take(q, 1000), joined({kAttitude, kRates}));
  EXPECT_TRUE(q.empty());
}

TEST(TransmitQueue, AnAnswerGoesAheadOfWhatWasQueuedButNotInsideAFrameOnItsWay) {
  TransmitQueue q;
  ASSERT_TRUE(q.push(kAttitude));
  ASSERT_TRUE(q.push(kRates));
  Bytes out = take(q, 3);  // the attitude frame is on its way
  ASSERT_TRUE(q.push_answer(kAck));
  ASSERT_TRUE(q.push_answer(kNack));  // behind the answer before it
  const Bytes rest = take(q, 1000);
  out.insert(out.end(), rest.begin(), rest.end());
  EXPECT_EQ(out, joined({kAttitude, kAck, kNack, kRates}));

  // Between frames an answer goes first at once; frames queued after it go behind it.
  ASSERT_TRUE(q.push(kRates));
  ASSERT_TRUE(q.push_answer(kAck));
  ASSERT_TRUE(q.push(kAttitude));
  EXPECT_EQ(take(q, 1000), joined({kAck, kRates, kAttitude}));
}

// Round and round the ring, with an answer put in at every point of a frame: every byte comes out
// once, the frames whole, the answer straight after the frame it found on its way.
TEST(TransmitQueue, AnswersAcrossTheRingsWrapKeepEveryFrameWhole) {
  TransmitQueue q;
  constexpr size_t kFrames = 15;  // 185 bytes a round with the ack: the ring's wrap moves every round
  for (size_t round = 0; round < 200; ++round) {
    for (size_t i = 0; i < kFrames; ++i) ASSERT_TRUE(q.push(kAttitude));
    const Bytes before = take(q, round % (kAttitude.size + 1u));
    ASSERT_TRUE(q.push_answer(kAck)) << round;
    const Bytes after = take(q, 1000);
    ASSERT_TRUE(q.empty());
    const size_t rest = (kAttitude.size - before.size() % kAttitude.size) % kAttitude.size;
    ASSERT_EQ(after.size(), kFrames * kAttitude.size - before.size() + kAck.size) << round;
    const auto at = after.begin() + static_cast<long>(rest);
    EXPECT_EQ(Bytes(at, at + kAck.size), bytes_of(kAck)) << round;
    Bytes frames = before;
    frames.insert(frames.end(), after.begin(), at);
    frames.insert(frames.end(), at + kAck.size, after.end());
    Bytes want;
    for (size_t i = 0; i < kFrames; ++i) want.insert(want.end(), kAttitude.bytes, kAttitude.bytes + kAttitude.size);
    ASSERT_EQ(frames, want) << round;
  }
}

TEST(TransmitQueue, AFullQueueRefusesAWholeFrameOrAnswer) {
  TransmitQueue q;
  uint32_t queued = 0;
  while (q.push(kAttitude)) queued += kAttitude.size;
  EXPECT_LT(q.space(), uint32_t{kAttitude.size});
  EXPECT_EQ(q.size(), queued);
  EXPECT_FALSE(q.push_answer(kAck)) << "no room for its 5 bytes";
  EXPECT_EQ(take(q, 100000).size(), queued);
}

}  // namespace
}  // namespace qr
