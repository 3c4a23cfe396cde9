// The QR's request dedup: a request re-sent because its answer was lost is answered again, the
// same way, and not applied again.
#include <gtest/gtest.h>

#include <common/messages.hpp>
#include <common/request_dedup.hpp>

#include "wire_test_support.hpp"

using namespace wire;

namespace {
Frame request(const auto& message) { return wire_test::frame_of(encode(message)); }
}  // namespace

TEST(RequestDedup, ANewRequestIsAdmittedAndItsResendIsADuplicateWithTheSameAnswer) {
  RequestDedup dedup;
  const Frame mode = request(ModeChange{7, Mode::manual});
  Admission a = dedup.admit(mode, 0);
  EXPECT_TRUE(a.request);
  EXPECT_FALSE(a.duplicate);
  EXPECT_EQ(a.seq, 7);
  dedup.record(mode, NackReason::controls_not_neutral, 0);

  a = dedup.admit(mode, kResendIntervalMs);
  EXPECT_TRUE(a.duplicate);
  EXPECT_EQ(a.previous, NackReason::controls_not_neutral) << "re-answered as it was answered";
  EXPECT_EQ(dedup.duplicates(), 1u);
}

TEST(RequestDedup, ANewSequenceNumberOrAnotherTypeIsANewRequest) {
  RequestDedup dedup;
  const Frame first = request(ParamSet{3, 1, 100});
  dedup.record(first, NackReason::none, 0);
  EXPECT_FALSE(dedup.admit(request(ParamSet{4, 1, 100}), 10).duplicate);
  EXPECT_FALSE(dedup.admit(request(ModeChange{3, Mode::safe}), 10).duplicate) << "sequence numbers are per type";
}

TEST(RequestDedup, TheSameSequenceNumberWithOtherContentIsANewRequest) {
  // A console restarted part-way through its numbers reuses a seq for another request: it must be
  // applied (or refused with a reason), never acked from memory.
  RequestDedup dedup;
  dedup.record(request(ParamSet{17, 9, 300}), NackReason::none, 0);
  EXPECT_FALSE(dedup.admit(request(ParamSet{17, 9, 250}), 500).duplicate) << "another value";
  EXPECT_FALSE(dedup.admit(request(ParamSet{17, 8, 300}), 500).duplicate) << "another parameter";
  EXPECT_TRUE(dedup.admit(request(ParamSet{17, 9, 300}), 500).duplicate) << "byte for byte the same";

  dedup.record(request(LogDownload{17, LogKind::sensor, 0, 40}), NackReason::none, 0);
  EXPECT_FALSE(dedup.admit(request(LogDownload{17, LogKind::sensor, 40, 40}), 500).duplicate);
}

TEST(RequestDedup, AStopIsNeverAResend) {
  RequestDedup dedup;
  for (const Mode stop : {Mode::safe, Mode::panic}) {
    const Frame frame = request(ModeChange{17, stop});
    dedup.record(frame, NackReason::none, 0);
    EXPECT_FALSE(dedup.admit(frame, kResendIntervalMs).duplicate) << "a stop is applied every time it arrives";
    EXPECT_TRUE(is_stop_request(frame));
  }
  EXPECT_FALSE(is_stop_request(request(ModeChange{17, Mode::manual})));
  EXPECT_FALSE(is_stop_request(request(Exit{17})));
}

TEST(RequestDedup, UnacknowledgedMessagesAreNotRequests) {
  RequestDedup dedup;
  const Admission a = dedup.admit(request(Control{}), 0);
  EXPECT_FALSE(a.request);
  EXPECT_FALSE(a.duplicate);
}

TEST(RequestDedup, EveryResendWithinTheGiveUpTimeIsRecognised) {
  RequestDedup dedup;
  const Frame exit = request(Exit{1});
  dedup.record(exit, NackReason::none, 500);
  for (uint32_t t = 500 + kResendIntervalMs; t < 500 + kGiveUpAfterMs; t += kResendIntervalMs) {
    EXPECT_TRUE(dedup.admit(exit, t).duplicate) << t;
  }
}

TEST(RequestDedup, TheSameNumberLongAfterTheWindowIsANewRequest) {
  // A console restarted with the same sequence numbers must not have its first request ignored
  // for long.
  RequestDedup dedup;
  const Frame mode = request(ModeChange{0, Mode::manual});
  dedup.record(mode, NackReason::none, 1000);
  EXPECT_TRUE(dedup.admit(mode, 1000 + kDedupWindowMs - 1).duplicate);
  EXPECT_FALSE(dedup.admit(mode, 1000 + kDedupWindowMs - 1 + kDedupWindowMs).duplicate);
}

TEST(RequestDedup, ReplyFrameIsAnAckOrANackForTheRequest) {
  Ack ack;
  ASSERT_TRUE(decode(wire_test::frame_of(reply_frame(MessageType::log_start, 5, NackReason::none)), ack));
  EXPECT_TRUE(ack == (Ack{MessageType::log_start, 5}));
  Nack nack;
  ASSERT_TRUE(decode(wire_test::frame_of(reply_frame(MessageType::log_download, 6, NackReason::busy)), nack));
  EXPECT_TRUE(nack == (Nack{MessageType::log_download, 6, NackReason::busy}));
}
