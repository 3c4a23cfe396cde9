// The QR's transmit queue: frames leave whole and in order within a lane, and an answer goes
// ahead of the other lane at the next frame boundary, never inside a frame.
#include <gtest/gtest.h>

#include <vector>

#include <common/messages.hpp>
#include <qr/core/transmit_queue.hpp>

namespace qr {
namespace {

std::vector<uint8_t> bytes_of(const wire::FrameBytes& f) { return {f.bytes, f.bytes + f.size}; }

std::vector<uint8_t> take(TransmitQueue& q, size_t max) {
  std::vector<uint8_t> out;
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

TEST(TransmitQueue, FramesOfOneLaneLeaveWholeAndInOrder) {
  TransmitQueue q;
  ASSERT_TRUE(q.push(kAttitude));
  ASSERT_TRUE(q.push(kRates));
  EXPECT_EQ(q.size(), size_t{kAttitude.size} + kRates.size);
  std::vector<uint8_t> want = bytes_of(kAttitude);
  const std::vector<uint8_t> rates = bytes_of(kRates);
  want.insert(want.end(), rates.begin(), rates.end());
  EXPECT_EQ(take(q, 1000), want);
  EXPECT_TRUE(q.empty());
}

TEST(TransmitQueue, AnAnswerGoesAheadOfWhatWasQueuedButNotInsideAFrameOnItsWay) {
  TransmitQueue q;
  ASSERT_TRUE(q.push(kAttitude));
  ASSERT_TRUE(q.push(kRates));
  const std::vector<uint8_t> first = take(q, 3);  // the attitude frame is on its way
  ASSERT_TRUE(q.push_answer(kAck));
  EXPECT_FALSE(q.empty());
  EXPECT_EQ(q.size(), size_t{kAttitude.size} - 3 + kRates.size) << "size() is the other lane's";

  std::vector<uint8_t> want = bytes_of(kAttitude);
  const std::vector<uint8_t> ack = bytes_of(kAck), rates = bytes_of(kRates);
  want.insert(want.end(), ack.begin(), ack.end());
  want.insert(want.end(), rates.begin(), rates.end());
  std::vector<uint8_t> out = first;
  const std::vector<uint8_t> rest = take(q, 1000);
  out.insert(out.end(), rest.begin(), rest.end());
  EXPECT_EQ(out, want) << "the attitude frame whole, then the ack, then the rates";

  // Between frames an answer goes first at once.
  ASSERT_TRUE(q.push(kRates));
  ASSERT_TRUE(q.push_answer(kAck));
  EXPECT_EQ(take(q, kAck.size), ack);
}

TEST(TransmitQueue, AnswersBeyondTheirLaneGoInTheOtherNotLost) {
  TransmitQueue q;
  const size_t fit = TransmitQueue::kAnswerBytes / kAck.size;
  for (size_t i = 0; i <= fit; ++i) ASSERT_TRUE(q.push_answer(kAck)) << i;
  EXPECT_EQ(q.size(), size_t{kAck.size}) << "the one beyond the lane";
  EXPECT_EQ(take(q, 10000).size(), (fit + 1) * kAck.size);
  EXPECT_TRUE(q.empty());
}

TEST(TransmitQueue, AFullLaneRefusesAWholeFrame) {
  TransmitQueue q;
  size_t queued = 0;
  while (q.push(kAttitude)) queued += kAttitude.size;
  EXPECT_LE(q.space(), size_t{kAttitude.size} - 1);
  EXPECT_EQ(q.size(), queued);
  EXPECT_EQ(take(q, 100000).size(), queued);
}

}  // namespace
}  // namespace qr
