// The sensor link's frames (common/sensor_link.hpp): what one end encodes the other decodes, and
// the parser finds frames in a stream with garbage, split and damaged frames in it.
#include <gtest/gtest.h>

#include <vector>

#include <common/sensor_link.hpp>

namespace {

simlink::SensorFrame a_sample(uint32_t kick) {
  simlink::SensorFrame f;
  f.kick = kick;
  f.time_us = kick * 1000u;
  f.gyro[0] = -123, f.gyro[2] = 32767;
  f.accel[2] = -8192;
  f.battery_mv = 11900;
  f.pressure_pa = 101313;
  f.ground_bytes = 0xFFFFFFF0u + kick;  // wraps
  return f;
}

std::vector<simlink::SensorFrame> parse(simlink::LinkParser& parser, const std::vector<uint8_t>& bytes) {
  std::vector<simlink::SensorFrame> out;
  for (uint8_t b : bytes) {
    parser.push(b, [&](const simlink::LinkFrame& frame) {
      simlink::SensorFrame f;
      EXPECT_TRUE(frame.decode(f));
      out.push_back(f);
    });
  }
  return out;
}

void append(std::vector<uint8_t>& bytes, const simlink::LinkFrameBytes& frame) {
  bytes.insert(bytes.end(), frame.bytes, frame.bytes + frame.size);
}

TEST(SensorLink, SensorsFrameRoundTrips) {
  simlink::LinkParser parser(simlink::LinkEnd::qr);
  std::vector<uint8_t> bytes;
  append(bytes, simlink::encode(a_sample(7)));
  EXPECT_EQ(bytes.size(), 34u);  // 'S', type, 31 payload bytes, check
  const auto frames = parse(parser, bytes);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].kick, 7u);
  EXPECT_EQ(frames[0].gyro[0], -123);
  EXPECT_EQ(frames[0].gyro[2], 32767);
  EXPECT_EQ(frames[0].pressure_pa, 101313);
  EXPECT_EQ(frames[0].ground_bytes, 0xFFFFFFF7u);
}

TEST(SensorLink, EngineFrameRoundTripsAtTheSimulatorsEnd) {
  simlink::EngineFrame e;
  e.kick = 42, e.engines[3] = 1000, e.mode = 5, e.ground_bytes = 99;
  e.angles_e4[simlink::EngineFrame::pitch_setpoint] = -1745;
  e.stats_row = 13, e.stats[simlink::EngineFrame::sum_high] = 3;
  const simlink::LinkFrameBytes bytes = simlink::encode(e);
  simlink::LinkParser qr_end(simlink::LinkEnd::qr), sim_end(simlink::LinkEnd::simulator);
  int at_qr = 0, at_sim = 0;
  simlink::EngineFrame got;
  for (uint8_t i = 0; i < bytes.size; ++i) {
    qr_end.push(bytes.bytes[i], [&](const simlink::LinkFrame&) { ++at_qr; });
    sim_end.push(bytes.bytes[i], [&](const simlink::LinkFrame& f) { at_sim += f.decode(got) ? 1 : 0; });
  }
  EXPECT_EQ(at_qr, 0) << "the QR does not listen to its own frames";
  ASSERT_EQ(at_sim, 1);
  EXPECT_EQ(got.kick, 42u);
  EXPECT_EQ(got.engines[3], 1000);
  EXPECT_EQ(got.angles_e4[simlink::EngineFrame::pitch_setpoint], -1745);
  EXPECT_EQ(got.stats[simlink::EngineFrame::sum_high], 3u);
}

// The sensors' I2C bus on the link: a transfer begun goes to the simulator, its end to the QR,
// each heard by its own end only, and a field out of its range is refused.
TEST(SensorLink, I2cTransfersCrossTheLinkEachToItsEnd) {
  simlink::I2cBeginFrame begin;
  begin.channel = 1, begin.address = 0x77, begin.write[0] = 0x48, begin.write_count = 1;
  simlink::I2cDoneFrame done;
  done.channel = 1, done.result = static_cast<uint8_t>(drivers::I2cResult::ok), done.count = 3;
  done.data[0] = 0x8A, done.data[2] = 0x1A;
  simlink::LinkParser qr_end(simlink::LinkEnd::qr), sim_end(simlink::LinkEnd::simulator);
  int at_qr = 0, at_sim = 0;
  simlink::I2cBeginFrame got_begin;
  simlink::I2cDoneFrame got_done;
  const simlink::LinkFrameBytes frames[2] = {simlink::encode(begin), simlink::encode(done)};
  for (const simlink::LinkFrameBytes& f : frames) {
    for (uint8_t i = 0; i < f.size; ++i) {
      qr_end.push(f.bytes[i], [&](const simlink::LinkFrame& frame) { at_qr += frame.decode(got_done) ? 1 : 0; });
      sim_end.push(f.bytes[i], [&](const simlink::LinkFrame& frame) { at_sim += frame.decode(got_begin) ? 1 : 0; });
    }
  }
  EXPECT_EQ(at_qr, 1);
  EXPECT_EQ(at_sim, 1);
  EXPECT_EQ(got_begin.address, 0x77);
  EXPECT_EQ(got_begin.write[0], 0x48);
  EXPECT_EQ(got_begin.write_count, 1);
  EXPECT_EQ(got_done.count, 3);
  EXPECT_EQ(got_done.data[0], 0x8A);
  EXPECT_EQ(got_done.data[2], 0x1A);

  done.result = static_cast<uint8_t>(drivers::I2cResult::bus_stuck) + 1;  // no such result
  const simlink::LinkFrameBytes bad = simlink::encode(done);
  int refused = 0;
  for (uint8_t i = 0; i < bad.size; ++i)
    qr_end.push(bad.bytes[i], [&](const simlink::LinkFrame& frame) { refused += frame.decode(got_done) ? 0 : 1; });
  EXPECT_EQ(refused, 1);
}

TEST(SensorLink, ParserFindsFramesAfterGarbageAndDamage) {
  simlink::LinkParser parser(simlink::LinkEnd::qr);
  std::vector<uint8_t> bytes = {'S', 0x01, 0x00, 'x', 'S'};  // a start that goes nowhere
  append(bytes, simlink::encode(a_sample(1)));
  simlink::LinkFrameBytes damaged = simlink::encode(a_sample(2));
  damaged.bytes[10] ^= 0x10;
  append(bytes, damaged);
  append(bytes, simlink::encode(a_sample(3)));
  const auto frames = parse(parser, bytes);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].kick, 1u);
  EXPECT_EQ(frames[1].kick, 3u);
  EXPECT_GT(parser.bytes_skipped(), 33u);
  EXPECT_EQ(parser.frames(), 2u);
}

}  // namespace
