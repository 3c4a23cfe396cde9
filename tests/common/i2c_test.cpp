// Several drivers on one I2C wire (common/drivers/i2c.hpp): the queue's channels, each one transfer
// at a time, run back to back in the order begun, each seeing only its own results.
#include <gtest/gtest.h>

#include <common/drivers/i2c.hpp>

#include <vector>

namespace {

using drivers::I2cChannel;
using drivers::I2cQueue;
using drivers::I2cReply;
using drivers::I2cResult;
using drivers::I2cTransfer;

I2cReply reply_of(uint8_t byte) {
  I2cReply r;
  r.data[0] = byte;
  r.count = 1;
  return r;
}

TEST(I2cQueue, AChannelHoldsOneTransferAndGivesItsResultOnce) {
  I2cQueue<2> bus;
  I2cChannel<I2cQueue<2>> mpu(bus, 0);
  I2cReply reply;
  EXPECT_EQ(mpu.poll(reply), I2cResult::idle);
  ASSERT_TRUE(mpu.begin(drivers::read_registers(0x68, 0x75, 1)));
  EXPECT_FALSE(mpu.begin(drivers::read_registers(0x68, 0x75, 1))) << "queued: one at a time";
  EXPECT_EQ(mpu.poll(reply), I2cResult::pending);

  uint8_t channel = 9;
  I2cTransfer on_wire;
  ASSERT_TRUE(bus.next(channel, on_wire));
  EXPECT_EQ(channel, 0);
  EXPECT_EQ(on_wire.write[0], 0x75);
  EXPECT_FALSE(mpu.begin(drivers::read_registers(0x68, 0x75, 1))) << "on the wire: still one at a time";
  EXPECT_EQ(mpu.poll(reply), I2cResult::pending);

  bus.finish(channel, I2cResult::ok, reply_of(0x68));
  ASSERT_EQ(mpu.poll(reply), I2cResult::ok);
  EXPECT_EQ(reply.count, 1);
  EXPECT_EQ(reply.data[0], 0x68);
  EXPECT_EQ(mpu.poll(reply), I2cResult::idle) << "a result is given once";
}

TEST(I2cQueue, TheWireTakesTheTransfersInTheOrderBegunOneAtATime) {
  I2cQueue<3> bus;
  ASSERT_TRUE(bus.begin(2, drivers::write_command(0x77, 0x48)));
  ASSERT_TRUE(bus.begin(0, drivers::read_registers(0x68, 0x3B, 14)));
  ASSERT_TRUE(bus.begin(1, drivers::write_command(0x50, 0x01)));
  EXPECT_EQ(bus.queued(), 3);

  std::vector<uint8_t> order;
  uint8_t channel = 0;
  I2cTransfer t;
  while (bus.next(channel, t)) {
    EXPECT_FALSE(bus.next(channel, t)) << "a second transfer while one is on the wire";
    order.push_back(channel);
    bus.finish(channel, I2cResult::ok, I2cReply{});
    // A channel whose result is in may begin again: it goes to the back of the queue.
    if (order.size() == 1) ASSERT_TRUE(bus.begin(2, drivers::write_command(0x77, 0x58)));
  }
  EXPECT_EQ(order, (std::vector<uint8_t>{2, 0, 1, 2}));
}

TEST(I2cQueue, EachChannelSeesOnlyItsOwnResult) {
  I2cQueue<2> bus;
  I2cChannel<I2cQueue<2>> a(bus, 0), b(bus, 1);
  ASSERT_TRUE(a.begin(drivers::read_registers(0x68, 0x75, 1)));
  ASSERT_TRUE(b.begin(drivers::read_registers(0x77, 0xA2, 2)));
  uint8_t channel = 0;
  I2cTransfer t;
  ASSERT_TRUE(bus.next(channel, t));
  bus.finish(channel, I2cResult::address_nack, I2cReply{});
  I2cReply reply;
  EXPECT_EQ(b.poll(reply), I2cResult::pending) << "b's transfer waits behind a's";
  EXPECT_EQ(a.poll(reply), I2cResult::address_nack);
  ASSERT_TRUE(bus.next(channel, t));
  EXPECT_EQ(channel, 1);
  bus.finish(0, I2cResult::ok, reply_of(1));  // not a's turn: ignored
  EXPECT_EQ(a.poll(reply), I2cResult::idle);
  bus.finish(channel, I2cResult::ok, reply_of(0x9C));
  ASSERT_EQ(b.poll(reply), I2cResult::ok);
  EXPECT_EQ(reply.data[0], 0x9C);
  EXPECT_FALSE(bus.begin(7, t)) << "no channel 7";
}

}  // namespace
