// The core's sensor stage (qr/core/sensor_stage.hpp): a board whose sensors are on an I2C bus has
// the scheduler step the MPU-6050 and MS5611 drivers each tick and compose the sample from them;
// without the bus, or with it switched off, the board's own sample is read as before.
#include <gtest/gtest.h>

#include <common/drivers/i2c.hpp>
#include <qr/boards/fake/fake_board.hpp>
#include <qr/core/scheduler.hpp>
#include <qr/core/sensor_stage.hpp>
#include <tests/common/i2c_two_chips.hpp>
#include <tests/qr/every_call_context.hpp>

#include <vector>

namespace qr {
namespace {

// The fake board with the two chips on a shared bus; the wire runs what a tick began before the
// next tick (test::TwoChips::run_wire).
struct I2cFakeBoard : fake::FakeBoard {
  using I2cBus = drivers::I2cQueue<2>;
  I2cBus& i2c() { return bus; }
  bool sensors_on_i2c() const { return on_i2c; }
  uint16_t battery_mv() const { return 11100; }

  I2cBus bus;
  bool on_i2c = true;
};
static_assert(I2cBoard<I2cFakeBoard>);
static_assert(!I2cBoard<fake::FakeBoard>);

// A context that keeps the samples it was given.
struct Samples : test_context::EveryCall<Samples> {
  void begin_tick(uint32_t, const SensorSample& s) { seen.push_back(s); }

  std::vector<SensorSample> seen;
};

constexpr uint32_t ticks_in(uint32_t ms) { return ms * 1000 / kPeriodUs; }

TEST(SensorStage, TheSampleIsTheDriversOnceTheyStream) {
  I2cFakeBoard board;
  Samples context;
  Scheduler<I2cFakeBoard, Samples> scheduler(board, context);
  test::TwoChips chips;  // flat and still: +1 g on chip z, a small gyro bias
  for (uint32_t i = 0; i < ticks_in(500); ++i) {
    scheduler.tick();
    chips.run_wire(board.bus);
  }
  const auto& stage = scheduler.sensor_stage();
  ASSERT_TRUE(stage.imu().healthy());
  EXPECT_EQ(stage.imu().total_faults(), 0u);
  EXPECT_EQ(stage.barometer().total_faults(), 0u);
  EXPECT_EQ(stage.stats().count, ticks_in(500));

  // The first samples are zeros (the chip is being started), the last the chip's in body axes: chip
  // (x, y, z) is body (x, -y, -z), the chip flat with its X forward.
  EXPECT_EQ(context.seen.front().accel[2], 0);
  EXPECT_EQ(context.seen.front().pressure_pa, 0);
  const SensorSample& last = context.seen.back();
  EXPECT_EQ(last.accel[0], 10);
  EXPECT_EQ(last.accel[1], -20);
  EXPECT_EQ(last.accel[2], -8192);
  EXPECT_EQ(last.gyro[0], 3);
  EXPECT_EQ(last.gyro[1], -4);
  EXPECT_EQ(last.gyro[2], -5);
  EXPECT_EQ(last.battery_mv, 11100) << "the board's, not the bus'";
  EXPECT_EQ(last.pressure_pa, 100009) << "the datasheet's example, through the driver's compensation";

  // Once the barometer has read, its pressure is held between its conversions: no tick sees 0.
  size_t first = 0;
  while (context.seen[first].pressure_pa == 0) ++first;
  for (size_t i = first; i < context.seen.size(); ++i) ASSERT_EQ(context.seen[i].pressure_pa, 100009) << i;

  // A sample is one tick old: the burst a tick begins is collected by the next.
  chips.set_data({100, 200, 300, -3920, 7, 8, 9});
  scheduler.tick();  // collects the burst read before the change, begins one of the new data
  chips.run_wire(board.bus);
  EXPECT_EQ(context.seen.back().accel[0], 10);
  scheduler.tick();
  EXPECT_EQ(context.seen.back().accel[0], 100);
  EXPECT_EQ(context.seen.back().gyro[2], -9);
}

TEST(SensorStage, SwitchedOffTheBoardsSampleIsReadAndTheBusIsNotTouched) {
  I2cFakeBoard board;
  board.on_i2c = false;
  board.sensors.accel[2] = -8000;
  board.sensors.pressure_pa = 101325;
  Samples context;
  Scheduler<I2cFakeBoard, Samples> scheduler(board, context);
  for (int i = 0; i < 10; ++i) scheduler.tick();
  EXPECT_EQ(board.bus.queued(), 0);
  EXPECT_EQ(context.seen.back().accel[2], -8000);
  EXPECT_EQ(context.seen.back().pressure_pa, 101325);
  EXPECT_EQ(scheduler.sensor_stage().stats().count, 0u);
}

}  // namespace
}  // namespace qr
