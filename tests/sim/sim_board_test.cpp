// The sim board: the serial line's 115200-baud timing, kicks and physics time, engines to motors.
#include <gtest/gtest.h>

#include <qr/boards/sim/serial_line.hpp>
#include <qr/boards/sim/sim_board.hpp>

namespace {

TEST(SimBoard, TheLineMovesElevenAndAHalfBytesPerMillisecond) {
  qrsim::SerialLine line(1u << 16);
  for (int i = 0; i < 1152; ++i) ASSERT_TRUE(line.send(static_cast<uint8_t>(i), 0));
  // 1152 bytes take 100 ms (100.0005 ms with whole-ns byte times); after 50 ms half are through.
  uint8_t byte = 0;
  int received = 0;
  while (line.receive(50'000'000, byte)) ++received;
  EXPECT_NEAR(received, 576, 1);
  while (line.receive(99'000'000, byte)) ++received;
  EXPECT_EQ(received, 1140);  // 99 ms x 11.52 bytes/ms = 1140.5
  while (line.receive(100'001'000, byte)) ++received;
  EXPECT_EQ(received, 1152);
  EXPECT_EQ(byte, static_cast<uint8_t>(1151));  // in order
}

TEST(SimBoard, AByteArrivesOneByteTimeAfterItIsSent) {
  qrsim::SerialLine line(16);
  ASSERT_TRUE(line.send(0x4D, 1000));
  uint8_t byte = 0;
  EXPECT_FALSE(line.receive(1000 + qrsim::kByteTimeNs - 1, byte));
  EXPECT_TRUE(line.receive(1000 + qrsim::kByteTimeNs, byte));
  EXPECT_EQ(byte, 0x4D);
  EXPECT_EQ(qrsim::kByteTimeNs, 86806u);  // 10 bits at 115200 baud
}

TEST(SimBoard, TheTransmitBufferFillsWhenTheLineCannotKeepUp) {
  qrsim::SerialLine line(32);
  int accepted = 0;
  for (int i = 0; i < 100; ++i) accepted += line.send(1, 0) ? 1 : 0;
  EXPECT_EQ(accepted, 32);
  EXPECT_EQ(line.bytes_refused(), 68u);
  // One byte time later one byte has left the buffer: room for one more.
  EXPECT_TRUE(line.send(1, qrsim::kByteTimeNs));
  EXPECT_FALSE(line.send(1, qrsim::kByteTimeNs));
}

TEST(SimBoard, KicksAdvanceThePhysicsAndSampleTheSensors) {
  sim::World world(sim::default_vehicle(), {});
  qrsim::SimBoard board(world);
  EXPECT_EQ(board.kicks(), 0u);
  const uint32_t kick = board.wait_kick(0);
  EXPECT_EQ(kick, 1u);
  EXPECT_EQ(board.now_us(), qr::kPeriodUs);
  EXPECT_EQ(world.now_us(), qr::kPeriodUs);
  // Standing still, level: about -1 g on z (bias and noise aside).
  EXPECT_NEAR(board.read_sensors().accel[2], -8192, 1200);
  EXPECT_GT(board.read_sensors().battery_mv, 11000);
  // Time stands still during a tick: no kick is missed however long the firmware takes.
  EXPECT_EQ(board.kicks(), kick);
}

TEST(SimBoard, EnginesDriveTheMotors) {
  sim::World world(sim::default_vehicle(), {});
  qrsim::SimBoard board(world);
  board.set_engines({{700, 0, 0, 0}});
  uint32_t kick = 0;
  for (int i = 0; i < 300; ++i) kick = board.wait_kick(kick);
  const auto& speed = world.plant().state().rotor_speed;
  EXPECT_GT(speed[0], 400);
  EXPECT_EQ(speed[1], 0);
  EXPECT_EQ(board.engines().value[0], 700);
}

TEST(SimBoard, TheLogAreaIsTheBoardsRam) {
  sim::World world(sim::default_vehicle(), {});
  qrsim::SimBoard board(world);
  const qr::LogArea area = board.log_area();
  ASSERT_NE(area.data, nullptr);
  EXPECT_EQ(area.size, 256u * 1024u);  // the devboard's
  area.data[area.size - 1] = 0xA5;     // all of it writable (ASan checks)
}

}  // namespace
