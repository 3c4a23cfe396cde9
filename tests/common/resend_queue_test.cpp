// The PC's resend queue: when requests go out again, when they are given up, and which answers
// count.
#include <gtest/gtest.h>

#include <vector>

#include <common/messages.hpp>
#include <common/resend_queue.hpp>

#include "wire_test_support.hpp"

using namespace wire;

namespace {

struct Polled {
  std::vector<ResendEvent> events;
};

Polled poll_all(ResendQueue& queue, uint32_t now_ms) {
  Polled out;
  ResendEvent event;
  while (queue.poll(now_ms, event)) out.events.push_back(event);
  return out;
}

uint8_t seq_in(const FrameBytes& frame) { return frame.bytes[2]; }

}  // namespace

TEST(ResendQueue, StampsEachTypeWithItsOwnRunningSequenceNumber) {
  ResendQueue queue(250);
  const FrameBytes m1 = queue.submit(ModeChange{0, Mode::manual}, 0);
  const FrameBytes p1 = queue.submit(ParamSet{0, 1, 5}, 0);
  const FrameBytes m2 = queue.submit(ModeChange{0, Mode::safe}, 0);
  EXPECT_EQ(seq_in(m1), 250);
  EXPECT_EQ(seq_in(p1), 250);
  EXPECT_EQ(seq_in(m2), 251);
  for (int i = 0; i < 10; ++i) queue.submit(ModeChange{0, Mode::safe}, 0);
  EXPECT_EQ(seq_in(queue.submit(ModeChange{0, Mode::safe}, 0)), 6) << "wraps modulo 256";
  ModeChange decoded;
  ASSERT_TRUE(decode(wire_test::frame_of(m2), decoded));
  EXPECT_EQ(decoded.mode, Mode::safe);
}

TEST(ResendQueue, ResendsTheSameBytesEveryIntervalUntilAcked) {
  ResendQueue queue;
  const FrameBytes sent = queue.submit(LogStart{0, kLogSensor}, 1000);
  EXPECT_TRUE(poll_all(queue, 1000 + kResendIntervalMs - 1).events.empty());
  const Polled at_interval = poll_all(queue, 1000 + kResendIntervalMs);
  ASSERT_EQ(at_interval.events.size(), 1u);
  EXPECT_EQ(at_interval.events[0].kind, ResendEvent::Kind::resend);
  EXPECT_EQ(at_interval.events[0].type, MessageType::log_start);
  EXPECT_TRUE(at_interval.events[0].frame == sent);
  EXPECT_EQ(queue.sends(MessageType::log_start), 2);
  // The next resend is an interval after the last one, not after the first.
  EXPECT_TRUE(poll_all(queue, 1000 + 2 * kResendIntervalMs - 1).events.empty());
  EXPECT_EQ(poll_all(queue, 1000 + 2 * kResendIntervalMs).events.size(), 1u);

  EXPECT_EQ(queue.on_ack(Ack{MessageType::log_start, seq_in(sent)}), AnswerMatch::matched);
  EXPECT_FALSE(queue.pending(MessageType::log_start));
  EXPECT_TRUE(poll_all(queue, 1000 + 10 * kResendIntervalMs).events.empty());
  EXPECT_TRUE(queue.idle());
}

TEST(ResendQueue, GivesUpAfterMaxSendsAndSaysWhich) {
  ResendQueue queue;
  const FrameBytes sent = queue.submit(Exit{}, 0);
  int resends = 0;
  std::vector<ResendEvent> gave_up;
  for (uint32_t t = 0; t <= 3 * kGiveUpAfterMs; ++t) {
    for (const ResendEvent& e : poll_all(queue, t).events) {
      if (e.kind == ResendEvent::Kind::resend) {
        ++resends;
      } else {
        gave_up.push_back(e);
        EXPECT_EQ(t, kGiveUpAfterMs) << "given up one interval after the last send";
      }
    }
  }
  EXPECT_EQ(resends, kMaxSends - 1);
  ASSERT_EQ(gave_up.size(), 1u);
  EXPECT_EQ(gave_up[0].type, MessageType::exit);
  EXPECT_EQ(gave_up[0].seq, seq_in(sent));
  EXPECT_FALSE(queue.pending(MessageType::exit));
  EXPECT_EQ(queue.on_ack(Ack{MessageType::exit, seq_in(sent)}), AnswerMatch::unexpected) << "too late";
}

TEST(ResendQueue, ALateAckForAReplacedRequestIsIgnored) {
  ResendQueue queue;
  const FrameBytes first = queue.submit(ModeChange{0, Mode::manual}, 0);
  const FrameBytes second = queue.submit(ModeChange{0, Mode::safe}, 50);
  EXPECT_EQ(queue.on_ack(Ack{MessageType::mode_change, seq_in(first)}), AnswerMatch::stale);
  EXPECT_TRUE(queue.pending(MessageType::mode_change));
  const Polled p = poll_all(queue, 50 + kResendIntervalMs);
  ASSERT_EQ(p.events.size(), 1u);
  EXPECT_TRUE(p.events[0].frame == second) << "only the newest request of a type is re-sent";
  EXPECT_EQ(queue.on_ack(Ack{MessageType::mode_change, seq_in(second)}), AnswerMatch::matched);
}

TEST(ResendQueue, ANackEndsTheRequestAndAnAckOfAnotherTypeDoesNot) {
  ResendQueue queue;
  const FrameBytes mode = queue.submit(ModeChange{0, Mode::full_control}, 0);
  const FrameBytes param = queue.submit(ParamSet{0, 1, 1}, 0);
  EXPECT_EQ(queue.on_ack(Ack{MessageType::param_get, seq_in(mode)}), AnswerMatch::unexpected);
  EXPECT_EQ(queue.on_nack(Nack{MessageType::mode_change, seq_in(mode), NackReason::not_calibrated}),
            AnswerMatch::matched);
  EXPECT_FALSE(queue.pending(MessageType::mode_change));
  EXPECT_TRUE(queue.pending(MessageType::param_set));
  EXPECT_EQ(poll_all(queue, kResendIntervalMs).events.size(), 1u);
  EXPECT_EQ(queue.on_ack(Ack{MessageType::param_set, seq_in(param)}), AnswerMatch::matched);
  EXPECT_TRUE(queue.idle());
}

TEST(ResendQueue, TimingSurvivesTheMillisecondCounterWrapping) {
  ResendQueue queue;
  const uint32_t start = 0xFFFFFFFFu - 30;
  queue.submit(LogStop{}, start);
  EXPECT_TRUE(poll_all(queue, start + 99).events.empty());
  EXPECT_EQ(poll_all(queue, start + kResendIntervalMs).events.size(), 1u);  // wrapped past 0
}
