// Typed messages: every message survives encode -> frame -> parse -> decode unchanged, every
// out-of-range field is refused by the decoder, and dispatch reaches the right handler.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <type_traits>

#include <common/messages.hpp>

#include "wire_test_support.hpp"

using namespace wire;

namespace {

// Fills every field with a value drawn from the edges of its type and of the ranges the protocol
// uses, or at random, so that both valid and invalid messages come out.
class EdgeFiller {
 public:
  explicit EdgeFiller(uint32_t seed) : rng_(seed) {}

  void operator()(uint8_t& v) { v = pick<uint8_t>({0, 1, 2, 5, 6, 7, 9, 0x12, 0x14, 0x1D, 0x81, 127, 128, 254, 255}); }
  void operator()(char& v) { v = static_cast<char>(pick<uint8_t>({0, 0, 'a', 'Z', '\n', ' ', 0x7F, 0xC3})); }
  void operator()(int8_t& v) { v = pick<int8_t>({-128, -4, -1, 0, 1, 127}); }
  void operator()(uint16_t& v) { v = pick<uint16_t>({0, 1, 500, 999, 1000, 1001, 32768, 65535}); }
  void operator()(int16_t& v) { v = pick<int16_t>({-32768, -1001, -1000, -1, 0, 1, 1000, 1001, 32767}); }
  void operator()(uint32_t& v) { v = pick<uint32_t>({0, 1, 0x80000000u, 0xFFFFFFFFu}); }
  void operator()(int32_t& v) { v = pick<int32_t>({INT32_MIN, -1, 0, 1, 10500, INT32_MAX}); }
  template <WireEnum E>
  void operator()(E& v) {
    underlying_t<E> raw{};
    (*this)(raw);
    v = static_cast<E>(raw);
  }
  template <class T, size_t N>
  void operator()(T (&array)[N]) {
    for (T& element : array) (*this)(element);
  }

 private:
  template <class T>
  T pick(std::initializer_list<T> edges) {
    // One draw in four is uniformly random over the whole type.
    if (std::uniform_int_distribution<int>(0, 3)(rng_) == 0) {
      return static_cast<T>(
          std::uniform_int_distribution<long long>(static_cast<long long>(std::numeric_limits<T>::min()),
                                                   static_cast<long long>(std::numeric_limits<T>::max()))(rng_));
    }
    const size_t i = std::uniform_int_distribution<size_t>(0, edges.size() - 1)(rng_);
    return *(edges.begin() + i);
  }

  std::mt19937 rng_;
};

struct RoundTripCount {
  int valid = 0;
  int invalid = 0;
};

template <class Msg>
RoundTripCount round_trip_edges(uint32_t seed) {
  EdgeFiller filler(seed);
  RoundTripCount count;
  // At least 5000 draws, and more while few were valid: a message whose fields must all land in
  // narrow ranges (an engine and a direction) is valid in fewer than 2 % of draws.
  for (int draw = 0; draw < 5000 || (count.valid < 200 && draw < 100000); ++draw) {
    Msg message{};
    Msg::fields(message, filler);
    const FrameBytes bytes = encode(message);
    EXPECT_EQ(bytes.size, frame_length(*message_spec(Msg::kType)));
    const std::vector<Frame> frames = wire_test::parse_all(wire_test::bytes_of(bytes));
    EXPECT_EQ(frames.size(), 1u);
    if (frames.size() != 1) return count;
    Msg decoded{};
    const bool accepted = decode(frames[0], decoded);
    EXPECT_EQ(accepted, message.valid()) << message_name(Msg::kType) << " "
                                         << wire_test::to_hex(wire_test::bytes_of(bytes));
    if (accepted) {
      EXPECT_TRUE(decoded == message) << message_name(Msg::kType);
      EXPECT_TRUE(encode(decoded) == bytes);
      ++count.valid;
    } else {
      ++count.invalid;
    }
  }
  return count;
}

template <class... Msgs>
void round_trip_all(MessageList<Msgs...>) {
  uint32_t seed = 1;
  (
      [&] {
        const RoundTripCount count = round_trip_edges<Msgs>(seed++);
        EXPECT_GT(count.valid, 100) << message_name(Msgs::kType) << ": too few valid draws to mean anything";
      }(),
      ...);
}

}  // namespace

TEST(Messages, EveryMessageRoundTripsAndEveryOutOfRangeFieldIsRefused) { round_trip_all(AllMessages{}); }

TEST(Messages, RangeChecksOfTheDocumentedFields) {
  auto accepted = [](const auto& message) {
    using Msg = std::decay_t<decltype(message)>;
    Msg out{};
    return decode(wire_test::frame_of(encode(message)), out);
  };
  EXPECT_TRUE(accepted(Control{1000, -1000, 1000, -1000}));
  EXPECT_FALSE(accepted(Control{1001, 0, 0, 0}));
  EXPECT_FALSE(accepted(Control{0, -1001, 0, 0}));
  EXPECT_TRUE(accepted(ModeChange{0, Mode::full_control}));
  // A mode number with no mode is well formed: the QR answers it unknown_mode, not bad_value.
  for (int mode = wire::kModeCount; mode <= 255; ++mode) {
    ModeChange decoded{};
    ASSERT_TRUE(decode(wire_test::frame_of(encode(ModeChange{3, static_cast<Mode>(mode)})), decoded)) << mode;
    EXPECT_EQ(static_cast<int>(decoded.mode), mode);
  }
  EXPECT_FALSE(accepted(LogStart{0, 0}));
  EXPECT_FALSE(accepted(LogStart{0, 4}));
  EXPECT_FALSE(accepted(LogDownload{0, static_cast<LogKind>(2), 0, 0}));
  EXPECT_TRUE(accepted(Ack{MessageType::exit, 1}));
  EXPECT_FALSE(accepted(Ack{MessageType::control, 1})) << "control is never acked";
  EXPECT_FALSE(accepted(Nack{MessageType::mode_change, 1, NackReason::none}));
  EXPECT_FALSE(accepted(Nack{MessageType::mode_change, 1, static_cast<NackReason>(200)}));
  EXPECT_FALSE(accepted(TelemetryEngines{{0, 0, 1001, 0}}));
  EXPECT_FALSE(accepted(TelemetrySystem{0, 1001, 0, 0}));
}

TEST(Messages, DecodeRefusesAFrameOfAnotherType) {
  ModeChange mode{};
  EXPECT_FALSE(decode(wire_test::frame_of(encode(Exit{3})), mode));
}

TEST(Messages, FramingRefusesAPayloadOfTheWrongLength) {
  const uint8_t payload[3] = {1, 2, 3};
  EXPECT_EQ(make_frame(MessageType::mode_change, payload, 3).size, 0);
  EXPECT_EQ(make_frame(static_cast<MessageType>(0x00), payload, 0).size, 0);
  EXPECT_EQ(make_frame(MessageType::mode_change, payload, 2).size, 8) << "start, type, 2 bytes, guard, check";
  EXPECT_EQ(make_frame(MessageType::param_get, payload, 2).size, 5) << "start, type, 2 bytes, check";
}

TEST(Messages, DebugTextCarriesALongLineAsNineCharacterPieces) {
  const std::string line = "calibration done, bias 12 -3 7\n";
  std::string received;
  size_t offset = 0;
  int pieces = 0;
  while (offset < line.size()) {
    DebugText piece;
    const size_t taken = piece.fill(line.data() + offset, line.size() - offset);
    ASSERT_GT(taken, 0u);
    offset += taken;
    ++pieces;
    DebugText decoded;
    ASSERT_TRUE(decode(wire_test::frame_of(encode(piece)), decoded));
    received.append(decoded.text, decoded.length());
  }
  EXPECT_EQ(received, line);
  EXPECT_EQ(pieces, static_cast<int>((line.size() + 8) / 9));

  DebugText padded_wrongly;
  std::memcpy(padded_wrongly.text, "ab\0cd", 5);
  EXPECT_FALSE(padded_wrongly.valid()) << "NUL only as trailing padding, so each text has one encoding";
}

TEST(Messages, DispatchCallsTheOverloadForTheDecodedMessage) {
  struct Handler {
    int controls = 0;
    int acks = 0;
    Control last{};
    void operator()(const Control& c) { ++controls, last = c; }
    void operator()(const Ack&) { ++acks; }
  } handler;

  EXPECT_EQ(dispatch(wire_test::frame_of(encode(Control{10, 20, 30, 40})), handler), DispatchResult::handled);
  EXPECT_EQ(handler.controls, 1);
  EXPECT_TRUE(handler.last == (Control{10, 20, 30, 40}));
  EXPECT_EQ(dispatch(wire_test::frame_of(encode(Ack{MessageType::exit, 2})), handler), DispatchResult::handled);
  EXPECT_EQ(handler.acks, 1);
  EXPECT_EQ(dispatch(wire_test::frame_of(encode(Exit{1})), handler), DispatchResult::not_handled);
  EXPECT_EQ(dispatch(wire_test::frame_of(encode(Control{2000, 0, 0, 0})), handler), DispatchResult::invalid_payload);
  EXPECT_EQ(handler.controls, 1);
}

TEST(Messages, OutOfScaleValuesSaturateInsteadOfWrapping) {
  // 40 rad/s in 1e-3 rad/s does not fit an int16: it must show as the end of the scale.
  EXPECT_EQ(saturate_i16(40 * kRateUnitsPerRadS), 32767);
  EXPECT_EQ(saturate_i16(-40 * kRateUnitsPerRadS), -32768);
  EXPECT_EQ(saturate_i16(-1234), -1234);
  EXPECT_EQ(saturate_u16(70000u), 65535);
  EXPECT_EQ(saturate_u16(612u), 612);
}
