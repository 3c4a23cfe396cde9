// Observable streams on the wire (docs/protocol.md section 13): the table's rows, the stream
// request's layout rules, packing samples into frames and back, and the budget arithmetic.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include <common/messages.hpp>
#include <common/observable_table.hpp>
#include <common/sample_packing.hpp>
#include <common/stream_budget.hpp>

namespace {

TEST(ObservableTable, NamesAreUniqueAndTheSetPointsSitBesideWhatFollowsThem) {
  std::set<std::string> names;
  for (const wire::ObservableSpec& spec : wire::kObservableTable) {
    EXPECT_TRUE(names.insert(spec.name).second) << spec.name;
    EXPECT_GT(std::string(spec.unit).size(), 0u) << spec.name;
  }
  for (const char* pair : {"phi", "theta"}) {
    EXPECT_TRUE(names.count(pair) == 1 && names.count(std::string(pair) + "_sp") == 1) << pair;
  }
}

TEST(StreamRequest, ObservablesFirstThenEmptyPlacesAndNoneWhenStopping) {
  using wire::kNoObservable;
  EXPECT_TRUE((wire::StreamRequest{1, 0, 5, {0, 6, kNoObservable, kNoObservable}}.valid()));
  EXPECT_EQ((wire::StreamRequest{1, 0, 5, {0, 6, kNoObservable, kNoObservable}}.count()), 2);
  EXPECT_FALSE((wire::StreamRequest{1, 0, 5, {0, kNoObservable, 6, kNoObservable}}.valid())) << "a hole";
  EXPECT_FALSE((wire::StreamRequest{1, 4, 5, {0, kNoObservable, kNoObservable, kNoObservable}}.valid())) << "stream 4";
  EXPECT_FALSE((wire::StreamRequest{1, 0, 0, {0, kNoObservable, kNoObservable, kNoObservable}}.valid()));
  EXPECT_TRUE((wire::StreamRequest{1, 0, 0, {kNoObservable, kNoObservable, kNoObservable, kNoObservable}}.valid()));
  EXPECT_FALSE((wire::StreamRequest{1, 0, 5, {kNoObservable, kNoObservable, kNoObservable, kNoObservable}}.valid()));
}

// Every stream width: what goes in comes out, in order, whole samples to a frame.
TEST(SamplePacking, RoundTripsEveryWidthSampleBySample) {
  for (uint8_t n = 1; n <= wire::kStreamObservablesMax; ++n) {
    wire::SamplePacker packer;
    wire::SampleUnpacker unpacker;
    packer.start(2, n);
    unpacker.start(n);
    std::vector<int16_t> sent, got;
    int frames = 0;
    for (int s = 0; s < 40; ++s) {
      int16_t values[4];
      for (uint8_t i = 0; i < n; ++i) values[i] = static_cast<int16_t>(s * 100 - i * 7 - 2000);
      sent.insert(sent.end(), values, values + n);
      wire::ObservableSamples frame;
      if (!packer.add(values, frame)) continue;
      ++frames;
      EXPECT_EQ(frame.stream(), 2);
      // Through the bytes of the wire, as a client sees it.
      const wire::FrameBytes bytes = wire::encode(frame);
      wire::Frame parsed;
      parsed.type = frame.kType;
      parsed.length = static_cast<uint8_t>(bytes.size - wire::kFrameOverhead);
      for (uint8_t i = 0; i < parsed.length; ++i) parsed.payload[i] = bytes.bytes[2 + i];
      wire::ObservableSamples decoded;
      ASSERT_TRUE(wire::decode(parsed, decoded));
      unpacker.unpack(decoded, [&](const int16_t* v) { got.insert(got.end(), v, v + n); });
    }
    EXPECT_EQ(frames, 40 / wire::samples_per_frame(n)) << int(n);
    EXPECT_EQ(got, sent) << int(n) << " observables";
    EXPECT_EQ(unpacker.lost(), 0u);
  }
}

TEST(SamplePacking, AGapInTheFrameCountIsCountedAsLostSamples) {
  wire::SamplePacker packer;
  wire::SampleUnpacker unpacker;
  packer.start(0, 2);  // two samples a frame
  unpacker.start(2);
  int delivered = 0;
  for (int s = 0; s < 200; ++s) {
    const int16_t values[2] = {static_cast<int16_t>(s), 0};
    wire::ObservableSamples frame;
    if (!packer.add(values, frame)) continue;
    if (s / 2 % 10 == 3) continue;  // every tenth frame lost on the line
    delivered += unpacker.unpack(frame, [](const int16_t*) {});
  }
  EXPECT_EQ(delivered, 180);
  EXPECT_EQ(unpacker.lost(), 20u);
}

// docs/protocol.md section 13.4, in numbers.
TEST(StreamBudget, TheRuleAsTheProtocolDocumentStatesIt) {
  EXPECT_EQ(wire::stream_room_bytes_per_s(50), 8370u);
  EXPECT_EQ(wire::stream_room_bytes_per_s(100), 6220u);
  EXPECT_EQ(wire::stream_room_bytes_per_s(300), 0u) << "never negative";
  EXPECT_EQ(wire::samples_per_frame(1), 4);
  EXPECT_EQ(wire::samples_per_frame(2), 2);
  EXPECT_EQ(wire::samples_per_frame(3), 1);
  EXPECT_EQ(wire::samples_per_frame(4), 1);
  EXPECT_EQ(wire::stream_bytes_per_s(1000, 5, 4), 2400u);  // 200 frames of 12 bytes
  EXPECT_EQ(wire::stream_bytes_per_s(1000, 5, 2), 1200u);
  EXPECT_EQ(wire::stream_bytes_per_s(1000, 500, 1), 6u) << "2 Hz battery: a frame every 2 s";
  EXPECT_EQ(wire::stream_bytes_per_s(1000, 0, 4), 0u) << "stopped";
  EXPECT_EQ(wire::stream_bytes_per_s(500, 1, 4), 6000u);
  // The document's example selections fit; attitude at 1 kHz does not.
  EXPECT_LE(wire::stream_bytes_per_s(1000, 2, 4), wire::stream_room_bytes_per_s(50));
  EXPECT_LE(2 * wire::stream_bytes_per_s(1000, 5, 4) + 2 * wire::stream_bytes_per_s(1000, 5, 2),
            wire::stream_room_bytes_per_s(50));
  EXPECT_GT(wire::stream_bytes_per_s(1000, 1, 4), wire::stream_room_bytes_per_s(50));
}

}  // namespace
