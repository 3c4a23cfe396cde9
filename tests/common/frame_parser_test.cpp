// The byte-at-a-time parser: framing, counters, bounds, and finding frames again after damage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include <common/crc8.hpp>
#include <common/frame_parser.hpp>
#include <common/messages.hpp>

#include "wire_test_support.hpp"

using namespace wire;
using wire_test::bytes_of;
using wire_test::parse_all;

namespace {

std::vector<uint8_t> concat(std::initializer_list<std::vector<uint8_t>> parts) {
  std::vector<uint8_t> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

std::vector<uint8_t> frame(const auto& message) { return bytes_of(encode(message)); }

}  // namespace

TEST(FrameParser, DeliversBackToBackFramesInOrder) {
  const auto stream = concat({frame(Control{1, 2, 3, 4}), frame(Exit{5}), frame(TelemetryRates{6, 7, 8})});
  const std::vector<Frame> frames = parse_all(stream);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0].type, MessageType::control);
  EXPECT_EQ(frames[1].type, MessageType::exit);
  EXPECT_EQ(frames[2].type, MessageType::telemetry_rates);
}

TEST(FrameParser, CountsWhatItSawAndSkipped) {
  FrameParser parser(Listen::both);
  const auto good = frame(ModeChange{1, Mode::manual});
  auto bad_check = good;
  bad_check.back() = static_cast<uint8_t>(bad_check.back() ^ 0x01);
  const auto stream = concat({{0x00, 0x11, 0x22}, {kStartByte, 0x00}, bad_check, good});
  const std::vector<Frame> frames = parse_all(parser, stream);

  ASSERT_EQ(frames.size(), 1u);
  const LinkCounters& c = parser.counters();
  EXPECT_EQ(c.bytes_received, stream.size());
  EXPECT_EQ(c.frames_ok, 1u);
  EXPECT_EQ(c.unknown_types, 1u);
  EXPECT_EQ(c.check_failures, 1u);
  EXPECT_EQ(c.bytes_skipped, 3u + 2u + bad_check.size());
  EXPECT_EQ(parser.buffered(), 0);
}

TEST(FrameParser, AReceiverTakesOnlyTheOtherSidesMessages) {
  const auto stream = concat({frame(Control{}), frame(TelemetryRates{}), frame(Ack{MessageType::exit, 1})});
  FrameParser qr(Listen::pc_to_qr);
  FrameParser pc(Listen::qr_to_pc);
  EXPECT_EQ(parse_all(qr, stream).size(), 1u);
  EXPECT_EQ(qr.counters().unknown_types, 2u);
  EXPECT_EQ(parse_all(pc, stream).size(), 2u);
  EXPECT_EQ(pc.counters().unknown_types, 1u);
}

TEST(FrameParser, FindsAFrameThatStartsInsideACutOffOne) {
  // A control frame cut off after 3 payload bytes: the next frames' bytes complete it as far as
  // the parser can tell, the check fails, and the re-scan finds them where they begin.
  const auto control = frame(Control{100, 0, 0, 0});
  const std::vector<uint8_t> cut(control.begin(), control.begin() + 5);
  const auto stream = concat({cut, frame(LogStop{1}), frame(Exit{2}), frame(Control{5, 5, 5, 5})});
  const std::vector<Frame> frames = parse_all(stream);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0].type, MessageType::log_stop);
  EXPECT_EQ(frames[1].type, MessageType::exit);
  EXPECT_EQ(frames[2].type, MessageType::control);
}

TEST(FrameParser, OneByteCanCompleteSeveralFramesFoundByTheRescan) {
  // 'M' + debug_text type, then two acks: 12 bytes, the length of a debug_text frame, complete
  // with the second ack's last byte. Pick the second ack's seq so the would-be debug_text frame
  // fails its check: that one byte then delivers both acks.
  const auto first = frame(Ack{MessageType::exit, 1});
  uint8_t seq = 0;
  std::vector<uint8_t> stream;
  for (;; ++seq) {
    stream = concat({{kStartByte, type_byte(MessageType::debug_text)}, first, frame(Ack{MessageType::exit, seq})});
    if (crc8(&stream[1], stream.size() - 2) != stream.back()) break;
  }
  ASSERT_EQ(stream.size(), kMaxFrameBytes);

  FrameParser parser(Listen::both);
  for (size_t i = 0; i + 1 < stream.size(); ++i)
    parser.push(stream[i], [](const Frame&) { ADD_FAILURE() << "too early"; });
  std::vector<Frame> frames;
  parser.push(stream.back(), [&](const Frame& f) { frames.push_back(f); });
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].type, MessageType::ack);
  EXPECT_EQ(frames[1].type, MessageType::ack);
  EXPECT_EQ(frames[1].payload[1], seq);
}

TEST(FrameParser, NeverKeepsMoreThanOneFrameAndAccountsForEveryByte) {
  std::mt19937 rng(7);
  FrameParser parser(Listen::both);
  uint32_t bytes_in_frames = 0;
  for (int i = 0; i < 200000; ++i) {
    // Mostly noise rich in start bytes and type bytes, the hardest input for the re-scan.
    const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
    const uint8_t b = kind == 0 ? kStartByte
                      : kind == 1
                          ? type_byte(
                                kMessageTable[std::uniform_int_distribution<size_t>(0, kMessageCount - 1)(rng)].type)
                          : static_cast<uint8_t>(rng());
    parser.push(b, [&](const Frame& f) { bytes_in_frames += frame_length(*find_message(type_byte(f.type))); });
    ASSERT_LT(parser.buffered(), kMaxFrameBytes);
  }
  const LinkCounters& c = parser.counters();
  EXPECT_EQ(c.bytes_received, c.bytes_skipped + bytes_in_frames + parser.buffered());
}

TEST(FrameParser, ResynchronisesAfterRandomGarbage) {
  std::mt19937 rng(2024);
  const auto a = frame(Control{321, -5, 6, 7});
  const auto b = frame(ModeChange{9, Mode::yaw_control});
  const auto c = frame(ParamSet{3, 2, 777});
  int first_frame_lost = 0;
  int later_frame_lost = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<uint8_t> garbage(std::uniform_int_distribution<size_t>(1, 64)(rng));
    for (uint8_t& g : garbage) g = static_cast<uint8_t>(rng());
    const std::vector<Frame> frames = parse_all(concat({garbage, a, b, c}), Listen::pc_to_qr);
    // Frames that came out of the garbage itself are possible (1 in 256 per 'M' + type in it);
    // what matters is that the real frames after it are found.
    std::vector<MessageType> real;
    for (const Frame& f : frames) {
      if (f == wire_test::frame_of(encode(Control{321, -5, 6, 7})) ||
          f == wire_test::frame_of(encode(ModeChange{9, Mode::yaw_control})) ||
          f == wire_test::frame_of(encode(ParamSet{3, 2, 777}))) {
        real.push_back(f.type);
      }
    }
    const bool has_b = std::count(real.begin(), real.end(), MessageType::mode_change) == 1;
    const bool has_c = std::count(real.begin(), real.end(), MessageType::param_set) == 1;
    if (std::count(real.begin(), real.end(), MessageType::control) != 1) ++first_frame_lost;
    if (!has_b || !has_c) ++later_frame_lost;
  }
  EXPECT_EQ(later_frame_lost, 0) << "a garbage burst may cost at most the frame right after it";
  // Losing the first frame needs a false frame to pass its check (1 in 256) across the boundary.
  EXPECT_LT(first_frame_lost, 20000 / 256);
  std::printf("resync: first frame lost after %d of 20000 garbage bursts\n", first_frame_lost);
}

TEST(FrameParser, AnIdleLineDropsTheRestOfAFrameWhoseSenderStopped) {
  const auto control = frame(Control{100, 0, 0, 0});
  FrameParser parser(Listen::both);
  const std::vector<uint8_t> cut(control.begin(), control.begin() + 6);
  EXPECT_TRUE(parse_all(parser, cut).empty());
  EXPECT_EQ(parser.buffered(), 6);
  parser.line_idle();
  EXPECT_EQ(parser.buffered(), 0);
  EXPECT_EQ(parse_all(parser, frame(Exit{1})).size(), 1u);
  EXPECT_EQ(parser.counters().bytes_skipped, 6u);
  EXPECT_EQ(parser.counters().check_failures, 0u) << "nothing was mistaken for part of the cut-off frame";
}

// A commanding request whose check is right but whose guard is not is damage, not a request: noise
// that passes the 8-bit check (1 time in 256) must pass the 24-bit guard too before the QR acts on
// it. Every guarded type, every guard byte: dropped, counted as a check failure, and the next
// frame still arrives.
TEST(FrameParser, AGuardedRequestWithAWrongGuardIsDroppedAsDamaged) {
  const std::vector<std::vector<uint8_t>> requests = {frame(ModeChange{3, Mode::manual}), frame(ParamSet{4, 1, 300}),
                                                      frame(LogStart{5, kLogSensor}), frame(LogStop{6}),
                                                      frame(Exit{7})};
  for (const std::vector<uint8_t>& good : requests) {
    const MessageSpec& spec = *find_message(good[1]);
    ASSERT_TRUE(spec.guarded) << spec.name;
    ASSERT_EQ(good.size(), frame_length(spec));
    for (size_t k = 0; k < kGuardBytes; ++k) {
      std::vector<uint8_t> bad = good;
      bad[2 + spec.payload_length + k] ^= 0x5A;
      bad.back() = crc8(&bad[1], bad.size() - 2);  // the check agrees with the damaged guard
      FrameParser parser(Listen::pc_to_qr);
      std::vector<Frame> frames;
      for (uint8_t b : concat({bad, good})) parser.push(b, [&](const Frame& f) { frames.push_back(f); });
      ASSERT_EQ(frames.size(), 1u) << spec.name << " guard byte " << k;
      EXPECT_EQ(frames[0].type, spec.type);
      EXPECT_GE(parser.counters().check_failures, 1u);
    }
  }
}
