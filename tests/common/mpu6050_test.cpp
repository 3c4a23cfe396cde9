// The MPU-6050 driver (common/drivers/mpu6050.hpp) against a scripted bus: the start-up's transfers
// one by one, the self-test, the data's decoding, the sample's age, every fault kind, the lost
// sensor's restart and the bus time of each tick. One tick is 1 ms (the default 1 kHz control rate).
#include <gtest/gtest.h>

#include <common/drivers/mpu6050.hpp>
#include <tests/support/mpu6050_self_test_chip.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <functional>
#include <utility>
#include <vector>

namespace {

using drivers::I2cReply;
using drivers::I2cResult;
using drivers::I2cTransfer;
using drivers::Mpu6050;
using drivers::Mpu6050Config;
using drivers::Mpu6050Fault;
using drivers::Mpu6050Phase;
namespace reg = drivers::mpu6050;

// The factory trim of a code by RM 4.1's formulas, in double: what the driver's integer tables
// (mpu6050_self_test.hpp) must give.
double gyro_trim_formula(int code) { return code == 0 ? 0.0 : 25 * 131 * std::pow(1.046, code - 1); }
double accel_trim_formula(int code) {
  return code == 0 ? 0.0 : 4096 * 0.34 * std::pow(0.92 / 0.34, (code - 1) / (std::pow(2.0, 5) - 2));
}

// test_support::kMpu6050Trim's codes, in the data's order (accelerometer x, y, z, gyroscope x, y, z).
constexpr int kTrimCodes[6] = {18, 13, 15, 12, 17, 14};

// A chip behind a bus, as little of it as the tests need: a register file that a write fills from
// its register on and a read reads from, both continuing at the next register (PS 9.3); a write of
// DEVICE_RESET restores the reset values of the registers the driver configures. Its factory trim
// is test_support::kMpu6050Trim's, and its self-test response that trim by the formulas, in
// double, rounded (a test may make it another). The chip answers
// when the transfer is begun (a burst is one instant), the bus reports it at the next poll. Faults
// are scripted: a result per transfer, polls left pending, a refused begin, a reply cut short, a
// register that keeps no value written to it, a chip that is not there.
struct ScriptedBus {
  uint8_t regs[128] = {};
  uint8_t address = reg::kAddressAd0Low;
  uint8_t identity = reg::kIdentity;  // what WHO_AM_I reads after a reset
  bool present = true;
  int deaf_register = -1;     // writes to it are acknowledged and dropped
  bool refuse_begin = false;  // begin() says the bus is busy
  int pending_next = 0;       // the next transfer answers `pending` this many polls
  int pending_left = 0;       // and the one on the wire still so many
  bool forget_next = false;   // the bus loses the next transfer: poll() says idle
  bool forget = false;
  int short_reply = -1;              // reads return this many bytes
  int32_t response[6] = {};          // the self-test's, in the data's order
  std::deque<I2cResult> script;      // the next transfers' results (ok: the chip answers)
  std::vector<I2cTransfer> begun;    // every transfer begun
  std::vector<uint32_t> begun_tick;  // and the tick it was begun by (set by Rig)
  uint32_t tick = 0;

  bool in_flight = false;
  I2cResult result = I2cResult::idle;
  I2cReply reply;

  ScriptedBus() {
    reset_chip();
    std::copy(std::begin(test_support::kMpu6050Trim), std::end(test_support::kMpu6050Trim), regs + reg::kSelfTestX);
    for (int axis = 0; axis < 6; ++axis) response[axis] = healthy_response(axis);
    // A chip lying flat and still at about 25 °C: +1 g on chip z at AFS_SEL 1, a small gyro bias.
    set_data({10, -20, 8192}, -3920, {3, -4, 5});
  }

  static int32_t healthy_response(int axis) {
    const double trim = axis < 3 ? accel_trim_formula(kTrimCodes[axis]) : gyro_trim_formula(kTrimCodes[axis]);
    return static_cast<int32_t>(std::lround(axis == 4 ? -trim : trim));  // gyro y: RM 4.1's minus
  }

  void reset_chip() {
    for (uint8_t r = reg::kSmplrtDiv; r <= reg::kAccelConfig; ++r) regs[r] = 0;
    regs[reg::kIntEnable] = 0;
    regs[reg::kPwrMgmt1] = reg::kPwrMgmt1Reset;
    regs[reg::kWhoAmI] = identity;
  }

  void set_word(uint8_t r, int16_t v) {
    regs[r] = static_cast<uint8_t>(static_cast<uint16_t>(v) >> 8);
    regs[r + 1] = static_cast<uint8_t>(static_cast<uint16_t>(v) & 0xFF);
  }
  void set_data(std::array<int16_t, 3> accel, int16_t temperature, std::array<int16_t, 3> gyro) {
    for (uint8_t i = 0; i < 3; ++i) {
      set_word(static_cast<uint8_t>(reg::kAccelXoutH + 2 * i), accel[i]);
      set_word(static_cast<uint8_t>(reg::kGyroXoutH + 2 * i), gyro[i]);
    }
    set_word(reg::kTempOutH, temperature);
  }
  void fill_data(uint8_t byte) {
    for (uint8_t r = reg::kAccelXoutH; r <= reg::kGyroZoutL; ++r) regs[r] = byte;
  }

  void write(uint8_t r, uint8_t v) {
    if (r == reg::kPwrMgmt1 && (v & reg::kDeviceReset) != 0) {
      reset_chip();
      return;
    }
    if (r == deaf_register) return;
    regs[r] = v;
  }

  bool begin(const I2cTransfer& t) {
    if (refuse_begin || in_flight) return false;
    begun.push_back(t);
    begun_tick.push_back(tick);
    in_flight = true;
    pending_left = pending_next;
    pending_next = 0;
    forget = forget_next;
    forget_next = false;
    reply = I2cReply{};
    result = I2cResult::ok;
    if (!script.empty()) {
      result = script.front();
      script.pop_front();
    }
    if (result == I2cResult::ok && (!present || t.address != address)) result = I2cResult::address_nack;
    if (result != I2cResult::ok) return true;
    const uint8_t first = t.write[0];
    for (uint8_t i = 1; i < t.write_count; ++i) write(static_cast<uint8_t>((first + i - 1) & 0x7F), t.write[i]);
    for (uint8_t i = 0; i < t.read_count; ++i) {
      reply.data[i] = test_support::mpu6050_read(regs, static_cast<uint8_t>((first + i) & 0x7F), response);
    }
    reply.count = short_reply >= 0 ? static_cast<uint8_t>(short_reply) : t.read_count;
    return true;
  }

  I2cResult poll(I2cReply& out) {
    if (!in_flight) return I2cResult::idle;
    if (pending_left > 0) {
      --pending_left;
      return I2cResult::pending;
    }
    in_flight = false;
    if (forget) {
      forget = false;
      return I2cResult::idle;
    }
    out = reply;
    return result;
  }
};
static_assert(drivers::I2cBus<ScriptedBus>);

struct Rig {
  ScriptedBus bus;
  Mpu6050 mpu;
  uint32_t tick = 0;
  uint32_t clock_offset_us = 0;

  explicit Rig(const Mpu6050Config& config = {}) : mpu(config) {}

  uint32_t now_us() const { return clock_offset_us + tick * 1000u; }
  void step() {
    bus.tick = tick;
    mpu.step(bus, now_us());
    ++tick;
  }
  void run(uint32_t ticks) {
    for (uint32_t i = 0; i < ticks; ++i) step();
  }
  // Steps until the first fresh sample; the documented start-up takes 179 steps (see below).
  void start() {
    for (int i = 0; i < 250 && !mpu.healthy(); ++i) step();
    ASSERT_TRUE(mpu.healthy());
  }
  size_t transfers() const { return bus.begun.size(); }
  const I2cTransfer& last() const { return bus.begun.back(); }
};

struct Expected {
  uint32_t tick;
  std::vector<uint8_t> write;
  uint8_t read_count;
};

void expect_transfers(const Rig& rig, uint8_t address, const std::vector<Expected>& expected) {
  ASSERT_GE(rig.bus.begun.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    const I2cTransfer& t = rig.bus.begun[i];
    EXPECT_EQ(rig.bus.begun_tick[i], expected[i].tick) << "transfer " << i;
    EXPECT_EQ(t.address, address) << "transfer " << i;
    EXPECT_EQ(std::vector<uint8_t>(t.write, t.write + t.write_count), expected[i].write) << "transfer " << i;
    EXPECT_EQ(t.read_count, expected[i].read_count) << "transfer " << i;
  }
}

bool is_reset_write(const I2cTransfer& t) {
  return t.write_count == 2 && t.write[0] == reg::kPwrMgmt1 && t.write[1] == reg::kDeviceReset;
}
bool is_burst(const I2cTransfer& t) {
  return t.write_count == 1 && t.write[0] == reg::kAccelXoutH && t.read_count == reg::kDataBytes;
}

// The self-test's samples: `each` bursts a tick apart from `tick` on, as many from `on`.
std::vector<Expected> self_test_samples(uint32_t tick, uint32_t on, uint32_t each = 8) {
  std::vector<Expected> bursts;
  for (uint32_t i = 0; i < each; ++i) bursts.push_back({tick + i, {0x3B}, 14});
  for (uint32_t i = 0; i < each; ++i) bursts.push_back({on + i, {0x3B}, 14});
  return bursts;
}

// The start-up, transfer by transfer: reset at tick 0 (answered at tick 1), 100 ms for the chip to
// come back (tick 101), identity, wake, the four configuration registers in one write and their
// read-back, the trim (SELF_TEST_X..A), the self-test's full scales (±250 °/s, ±8 g), the power
// register's read-back (answered at tick 108), 30 ms of the gyros settling (tick 138), eight
// samples, the self-test bits (answered at tick 147), the filter's 9.784 ms (tick 157), eight
// samples, the configured full scales back and read back (answered at tick 167), the filter's
// wait again (tick 177), then the 14 data bytes every tick; the first sample is collected at tick
// 178. The self-test adds 41 ticks to the start-up.
TEST(Mpu6050, StartsUpWithTheDocumentedTransfers) {
  Rig rig;
  rig.run(181);
  std::vector<Expected> expected = {
      {0, {0x6B, 0x80}, 0}, {101, {0x75}, 1}, {102, {0x6B, 0x01}, 0},       {103, {0x19, 0x00, 0x01, 0x08, 0x08}, 0},
      {104, {0x19}, 4},     {105, {0x0D}, 4}, {106, {0x1B, 0x00, 0x10}, 0}, {107, {0x6B}, 1}};
  const std::vector<Expected> samples = self_test_samples(138, 157);
  expected.insert(expected.end(), samples.begin(), samples.begin() + 8);
  expected.push_back({146, {0x1B, 0xE0, 0xF0}, 0});
  expected.insert(expected.end(), samples.begin() + 8, samples.end());
  expected.push_back({165, {0x1B, 0x08, 0x08}, 0});
  expected.push_back({166, {0x1B}, 2});
  for (uint32_t tick = 177; tick <= 180; ++tick) expected.push_back({tick, {0x3B}, 14});
  expect_transfers(rig, 0x68, expected);
  EXPECT_EQ(rig.transfers(), 31u);
  EXPECT_EQ(rig.mpu.total_faults(), 0u);
  EXPECT_EQ(rig.mpu.self_tests(), 1u);
  EXPECT_EQ(rig.mpu.self_test_failures(), 0u);
  EXPECT_EQ(rig.mpu.samples(), 3u);  // the self-test's are not the flight's
  EXPECT_TRUE(rig.mpu.healthy());
  // What the chip holds now is what was asked for.
  EXPECT_EQ(rig.bus.regs[reg::kPwrMgmt1], 0x01);
  EXPECT_EQ(rig.bus.regs[reg::kGyroConfig], 0x08);
  EXPECT_EQ(rig.bus.regs[reg::kAccelConfig], 0x08);
  EXPECT_EQ(rig.bus.regs[reg::kIntEnable], 0x00);
}

TEST(Mpu6050, TheFirstSampleComesAtTick178AndNotBefore) {
  Rig rig;
  rig.run(178);
  EXPECT_FALSE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::streaming);  // the first burst is on the wire
  rig.step();
  EXPECT_TRUE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.sample().read_at_us, 177000u);
}

// The configuration's every field reaches its register, at the other address.
TEST(Mpu6050, WritesTheConfigurationItIsGiven) {
  Mpu6050Config config;
  config.address = reg::kAddressAd0High;
  config.sample_rate_divider = 1;
  config.dlpf = 3;
  config.gyro_full_scale = 3;
  config.accel_full_scale = 2;
  Rig rig(config);
  rig.bus.address = reg::kAddressAd0High;
  rig.run(300);
  // DLPF_CFG 3 (42 Hz, 4.9 ms): the filter takes 39.004 ms to settle (filter_settle_us), longer
  // than the gyros' 30 ms, and the waits are that long: from tick 108 to 148, 153 to 193, 199 to
  // 239. A sample rate of 500 Hz: four samples each way (8 ms of them).
  std::vector<Expected> expected = {
      {0, {0x6B, 0x80}, 0}, {101, {0x75}, 1}, {102, {0x6B, 0x01}, 0},       {103, {0x19, 0x01, 0x03, 0x18, 0x10}, 0},
      {104, {0x19}, 4},     {105, {0x0D}, 4}, {106, {0x1B, 0x00, 0x10}, 0}, {107, {0x6B}, 1}};
  const std::vector<Expected> samples = self_test_samples(148, 193, 4);
  expected.insert(expected.end(), samples.begin(), samples.begin() + 4);
  expected.push_back({152, {0x1B, 0xE0, 0xF0}, 0});
  expected.insert(expected.end(), samples.begin() + 4, samples.end());
  expected.push_back({197, {0x1B, 0x18, 0x10}, 0});
  expected.push_back({198, {0x1B}, 2});
  expected.push_back({239, {0x3B}, 14});
  expect_transfers(rig, 0x69, expected);
  EXPECT_EQ(drivers::mpu6050::filter_settle_us(3), 39004u);
  EXPECT_TRUE(rig.mpu.healthy());
}

// A microsecond clock wraps every 71 minutes; a start-up across the wrap takes as long.
TEST(Mpu6050, StartsUpAcrossTheClocksWrap) {
  Rig rig;
  rig.clock_offset_us = 0xFFFFFFFFu - 50000u;
  rig.run(178);
  EXPECT_FALSE(rig.mpu.healthy());
  rig.step();
  EXPECT_TRUE(rig.mpu.healthy());
}

// Big-endian two's complement: accelerometer x, y, z, temperature, gyroscope x, y, z.
TEST(Mpu6050, DecodesTheDataBytes) {
  const uint8_t bytes[14] = {0x12, 0x34, 0xFE, 0xDC, 0x80, 0x00, 0xF0, 0x50, 0x7F, 0xFF, 0x00, 0x01, 0xFF, 0xFF};
  const drivers::Mpu6050Raw raw = drivers::decode_mpu6050_data(bytes);
  EXPECT_EQ(raw.accel[0], 0x1234);
  EXPECT_EQ(raw.accel[1], -292);
  EXPECT_EQ(raw.accel[2], -32768);
  EXPECT_EQ(raw.temperature, -4016);
  EXPECT_EQ(raw.gyro[0], 32767);
  EXPECT_EQ(raw.gyro[1], 1);
  EXPECT_EQ(raw.gyro[2], -1);
  // -4016 / 340 + 36.53 = 24.72 °C (RM 4.18).
  EXPECT_EQ(reg::temperature_centi_degrees(-4016), 2472);
  EXPECT_EQ(reg::temperature_centi_degrees(0), 3653);
}

// The default table: the chip flat, X forward. Flat and still it reads +1 g on chip z, which is
// -1 g on body z (docs/conventions.md); chip y is body -y; -32768 negated saturates.
TEST(Mpu6050, MapsTheChipsAxesToTheBodys) {
  Rig rig;
  rig.bus.set_data({1000, 2000, 8192}, -3920, {-32768, 300, -400});
  rig.start();
  const drivers::Mpu6050Sample& s = rig.mpu.sample();
  EXPECT_EQ(s.accel[0], 1000);
  EXPECT_EQ(s.accel[1], -2000);
  EXPECT_EQ(s.accel[2], -8192);
  EXPECT_EQ(s.gyro[0], -32768);
  EXPECT_EQ(s.gyro[1], -300);
  EXPECT_EQ(s.gyro[2], 400);
  EXPECT_EQ(s.temperature, -3920);

  // The chip turned a quarter to the right (its x to the body's right, its y forward): a rotation.
  Mpu6050Config turned;
  turned.chip_to_body = {{1, 0, 2}, {1, 1, -1}};
  ASSERT_TRUE(drivers::valid(turned));
  int16_t body[3];
  drivers::chip_to_body(turned.chip_to_body, {1, 2, 3}, body);
  EXPECT_EQ(body[0], 2);
  EXPECT_EQ(body[1], 1);
  EXPECT_EQ(body[2], -3);
  int16_t extreme[3];
  drivers::chip_to_body(drivers::kChipFlatXForward, {-32768, -32768, -32768}, extreme);
  EXPECT_EQ(extreme[0], -32768);
  EXPECT_EQ(extreme[1], 32767);
  EXPECT_EQ(extreme[2], 32767);
}

// The scales the flight assumes (qr/core/sensor_scale.hpp) are the defaults' (PS 6.1, 6.2).
TEST(Mpu6050, DefaultsAreTheFlightsScalesAndRate) {
  const Mpu6050Config config;
  EXPECT_EQ(reg::kGyroCountsPerDpsX10[config.gyro_full_scale], 655);
  EXPECT_EQ(reg::kAccelCountsPerG[config.accel_full_scale], 8192);
  EXPECT_EQ(drivers::mpu6050_sample_rate_hz(config), 1000u);
  Mpu6050Config slow = config;
  slow.sample_rate_divider = 1;
  EXPECT_EQ(drivers::mpu6050_sample_rate_hz(slow), 500u);
  Mpu6050Config unfiltered = config;
  unfiltered.dlpf = 0;
  EXPECT_EQ(drivers::mpu6050_sample_rate_hz(unfiltered), 8000u);
  unfiltered.sample_rate_divider = 7;
  EXPECT_EQ(drivers::mpu6050_sample_rate_hz(unfiltered), 1000u);
}

// The burst a tick begins is collected by the next: what the chip holds at tick k is the sample
// after tick k + 1, read at tick k's time.
TEST(Mpu6050, TheSampleIsOneTickOld) {
  Rig rig;
  rig.start();
  rig.bus.set_data({111, 0, 8192}, -3920, {0, 0, 0});
  const uint32_t k = rig.tick;
  rig.step();  // collects the burst of tick k - 1, begins one that reads 111
  EXPECT_TRUE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.sample().accel[0], 10);
  EXPECT_EQ(rig.mpu.sample().read_at_us, (k - 1) * 1000u);
  rig.step();
  EXPECT_EQ(rig.mpu.sample().accel[0], 111);
  EXPECT_EQ(rig.mpu.sample().read_at_us, k * 1000u);
}

// Every kind of bad answer while streaming: counted once under its own kind, the tick without a
// fresh sample (the last one kept), and the next read good again. Each fault is set up to hit the
// transfer the next step begins (a refusal: that step's begin), so the step after shows it.
struct FaultCase {
  const char* name;
  Mpu6050Fault kind;
  std::function<void(ScriptedBus&)> inject;
  std::function<void(ScriptedBus&)> heal;
};

TEST(Mpu6050, CountsEachBadAnswerWhileStreamingByItsKind) {
  const auto none = [](ScriptedBus&) {};
  const auto good_data = [](ScriptedBus& b) { b.set_data({10, -20, 8192}, -3920, {3, -4, 5}); };
  const std::vector<FaultCase> cases = {
      {"address NACK", Mpu6050Fault::address_nack, [](ScriptedBus& b) { b.script = {I2cResult::address_nack}; }, none},
      {"data NACK", Mpu6050Fault::data_nack, [](ScriptedBus& b) { b.script = {I2cResult::data_nack}; }, none},
      {"bus stuck", Mpu6050Fault::bus_stuck, [](ScriptedBus& b) { b.script = {I2cResult::bus_stuck}; }, none},
      {"all zeros", Mpu6050Fault::impossible_value, [](ScriptedBus& b) { b.fill_data(0x00); }, good_data},
      {"all ones", Mpu6050Fault::impossible_value, [](ScriptedBus& b) { b.fill_data(0xFF); }, good_data},
      {"below -40 °C", Mpu6050Fault::impossible_value, [](ScriptedBus& b) { b.set_word(reg::kTempOutH, -26021); },
       good_data},
      {"above 85 °C", Mpu6050Fault::impossible_value, [](ScriptedBus& b) { b.set_word(reg::kTempOutH, 16480); },
       good_data},
      {"short reply", Mpu6050Fault::impossible_value, [](ScriptedBus& b) { b.short_reply = 13; },
       [](ScriptedBus& b) { b.short_reply = -1; }},
      {"bus refused", Mpu6050Fault::bus_refused, [](ScriptedBus& b) { b.refuse_begin = true; },
       [](ScriptedBus& b) { b.refuse_begin = false; }},
      {"still pending", Mpu6050Fault::no_answer, [](ScriptedBus& b) { b.pending_next = 1; }, none},
      {"forgotten", Mpu6050Fault::no_answer, [](ScriptedBus& b) { b.forget_next = true; }, none},
  };
  for (const FaultCase& c : cases) {
    SCOPED_TRACE(c.name);
    Rig rig;
    rig.start();
    c.inject(rig.bus);
    rig.step();
    EXPECT_TRUE(rig.mpu.healthy());  // this tick's sample was read before the fault
    c.heal(rig.bus);
    rig.step();
    EXPECT_FALSE(rig.mpu.healthy());
    EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::streaming);
    EXPECT_EQ(rig.mpu.fault_count(c.kind), 1u);
    EXPECT_EQ(rig.mpu.total_faults(), 1u);
    EXPECT_EQ(rig.mpu.last_fault(), c.kind);
    EXPECT_EQ(rig.mpu.consecutive_failures(), 1u);
    EXPECT_EQ(rig.mpu.sample().accel[2], -8192);  // the last good sample stays
    // The next tick has a good sample again (a transfer answered late: its own, a tick older).
    rig.step();
    EXPECT_TRUE(rig.mpu.healthy());
    EXPECT_EQ(rig.mpu.consecutive_failures(), 0u);
    EXPECT_EQ(rig.mpu.total_faults(), 1u);
    EXPECT_EQ(rig.mpu.lost_count(), 0u);
  }
}

// The edges of the temperature range are readings a chip may give.
TEST(Mpu6050, TemperaturesAtTheEdgesOfTheRangeAreGood) {
  for (int16_t t : {int16_t{-26020}, int16_t{16479}}) {
    Rig rig;
    rig.bus.set_word(reg::kTempOutH, t);
    rig.start();
    EXPECT_EQ(rig.mpu.sample().temperature, t);
    EXPECT_EQ(rig.mpu.total_faults(), 0u);
  }
  EXPECT_EQ(reg::temperature_centi_degrees(-26020), -3999);
  EXPECT_EQ(reg::temperature_centi_degrees(16479), 8499);
}

// A configuration register that does not keep its value: counted, start over 100 ms later, never
// stream. Also the power register (a chip that stays asleep).
TEST(Mpu6050, AConfigurationThatDoesNotStickIsAFault) {
  // The read-back begun at tick 104, collected at 105; the power register's at 107, 108.
  for (const auto& [deaf, collected] : {std::pair{int{reg::kGyroConfig}, 105u}, std::pair{int{reg::kPwrMgmt1}, 108u}}) {
    SCOPED_TRACE(deaf);
    Rig rig;
    rig.bus.deaf_register = deaf;
    rig.run(collected);
    EXPECT_EQ(rig.mpu.total_faults(), 0u);
    rig.step();
    EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::readback_mismatch), 1u);
    EXPECT_EQ(rig.mpu.restart_count(), 1u);
    rig.run(1000);
    for (const I2cTransfer& t : rig.bus.begun) EXPECT_FALSE(is_burst(t));
    EXPECT_FALSE(rig.mpu.healthy());
    EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::starting);
    EXPECT_GE(rig.mpu.fault_count(Mpu6050Fault::readback_mismatch), 5u);
    EXPECT_EQ(rig.mpu.total_faults(), rig.mpu.fault_count(Mpu6050Fault::readback_mismatch));
  }
}

// An MPU-6500 (WHO_AM_I 0x70) where an MPU-6050 should be: refused, never woken or configured.
// Each try is the reset, 100 ms, the identity read (answered a tick later), 100 ms before the next:
// 202 ticks, so 5 tries in a second.
TEST(Mpu6050, RefusesAWrongIdentity) {
  Rig rig;
  rig.bus.identity = rig.bus.regs[reg::kWhoAmI] = 0x70;
  rig.run(1000);
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::wrong_identity), 5u);
  EXPECT_EQ(rig.mpu.total_faults(), 5u);
  EXPECT_EQ(rig.mpu.restart_count(), 5u);
  EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::starting);
  EXPECT_FALSE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.samples(), 0u);
  for (const I2cTransfer& t : rig.bus.begun) {
    EXPECT_TRUE(is_reset_write(t) || (t.write[0] == reg::kWhoAmI && t.read_count == 1));
  }
  EXPECT_EQ(rig.bus.regs[reg::kPwrMgmt1], reg::kPwrMgmt1Reset);  // still asleep
  // The same chip answering right is taken at the next try.
  rig.bus.identity = reg::kIdentity;
  rig.run(400);
  EXPECT_TRUE(rig.mpu.healthy());
}

// No chip at all: one reset write NACKed every 100 ms, not one every tick.
TEST(Mpu6050, AMissingChipIsTriedEvery100Ms) {
  Rig rig;
  rig.bus.present = false;
  rig.run(1000);
  EXPECT_EQ(rig.transfers(), 10u);
  for (const I2cTransfer& t : rig.bus.begun) EXPECT_TRUE(is_reset_write(t));
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::address_nack), 10u);
  EXPECT_EQ(rig.mpu.lost_count(), 0u);  // never found, so never lost
}

// kLostAfterFailures: 10 failed reads in a row (10 ms at 1 kHz) and the sensor is lost and started
// over from the reset; 9 are ridden through on the last sample. The numbers are written out here so
// that a changed constant fails this test.
TEST(Mpu6050, TenFailedReadsInARowLoseTheSensorAndStartOver) {
  Rig rig;
  rig.start();
  rig.bus.present = false;
  rig.step();  // collects a good sample, begins a burst that will be NACKed
  ASSERT_TRUE(rig.mpu.healthy());
  for (int failures = 1; failures <= 9; ++failures) {
    rig.step();
    EXPECT_EQ(rig.mpu.consecutive_failures(), failures);
    EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::streaming) << failures;
    EXPECT_FALSE(rig.mpu.healthy());
    EXPECT_TRUE(is_burst(rig.last())) << failures;
  }
  EXPECT_EQ(rig.mpu.lost_count(), 0u);
  rig.step();  // the tenth
  EXPECT_EQ(rig.mpu.lost_count(), 1u);
  EXPECT_EQ(rig.mpu.restart_count(), 1u);
  EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::starting);
  EXPECT_TRUE(is_reset_write(rig.last()));  // at once, the same tick
  EXPECT_EQ(rig.bus.begun_tick.back(), rig.tick - 1);
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::address_nack), 10u);
  EXPECT_EQ(rig.mpu.sample().accel[2], -8192);  // the last good sample, not fresh

  // Still gone for 300 ms: the reset tried every 100 ms, the sensor lost once, not again.
  rig.run(300);
  EXPECT_EQ(rig.mpu.lost_count(), 1u);
  EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::starting);
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::address_nack), 13u);

  // Back: the whole start-up again, then streaming.
  rig.bus.present = true;
  rig.run(250);
  EXPECT_TRUE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.lost_count(), 1u);
}

// One good read among the failures starts the count again: 9, a good one, 9 is no loss.
TEST(Mpu6050, AGoodReadStartsTheCountAgain) {
  Rig rig;
  rig.start();
  for (int round = 0; round < 3; ++round) {
    rig.bus.script.assign(9, I2cResult::bus_stuck);
    rig.run(10);
    EXPECT_EQ(rig.mpu.consecutive_failures(), 9);
    rig.step();
    EXPECT_TRUE(rig.mpu.healthy());
  }
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::bus_stuck), 27u);
  EXPECT_EQ(rig.mpu.lost_count(), 0u);
  EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::streaming);
}

// A bus that never finishes the burst: no answer for 10 ticks loses the sensor; nothing new is begun
// while the old transfer holds the bus, and its answer, when it comes, is dropped.
TEST(Mpu6050, ABusThatNeverAnswersLosesTheSensor) {
  Rig rig;
  rig.start();
  rig.bus.pending_next = 1000000;
  rig.step();  // the burst now on the wire hangs
  const size_t begun = rig.transfers();
  rig.run(9);
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::no_answer), 9u);
  EXPECT_EQ(rig.mpu.lost_count(), 0u);
  rig.step();
  EXPECT_EQ(rig.mpu.lost_count(), 1u);
  EXPECT_EQ(rig.transfers(), begun);  // the reset waits for the bus
  rig.bus.pending_left = 0;           // the hung burst finally ends, with good data
  const uint32_t samples = rig.mpu.samples();
  rig.step();
  EXPECT_EQ(rig.mpu.samples(), samples);
  EXPECT_TRUE(is_reset_write(rig.last()));
  rig.run(200);
  EXPECT_TRUE(rig.mpu.healthy());
}

// At start-up a NACK or a stuck bus starts over 100 ms later; a refused begin is tried again next
// tick.
TEST(Mpu6050, StartUpFaultsStartOver) {
  for (I2cResult r : {I2cResult::address_nack, I2cResult::data_nack, I2cResult::bus_stuck}) {
    Rig rig;
    rig.run(103);
    rig.bus.script = {r};  // the configuration write
    rig.run(2);
    EXPECT_EQ(rig.mpu.total_faults(), 1u);
    EXPECT_EQ(rig.mpu.restart_count(), 1u);
    EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::starting);
    const size_t before = rig.transfers();
    rig.run(99);  // nothing for 100 ms
    EXPECT_EQ(rig.transfers(), before);
    rig.run(1);  // 100 ms after the fault (tick 104): the reset again
    EXPECT_EQ(rig.transfers(), before + 1);
    EXPECT_TRUE(is_reset_write(rig.last()));
    rig.run(250);
    EXPECT_TRUE(rig.mpu.healthy());
  }
  Rig rig;
  rig.bus.refuse_begin = true;
  rig.run(3);
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::bus_refused), 3u);
  EXPECT_EQ(rig.mpu.restart_count(), 0u);
  rig.bus.refuse_begin = false;
  rig.step();
  EXPECT_TRUE(is_reset_write(rig.last()));
}

// A start-up read that returns other than the bytes asked for is not believed, even when the bytes
// that came are the right ones.
TEST(Mpu6050, AStartUpReplyOfTheWrongLengthIsAFault) {
  Rig rig;
  rig.run(104);
  rig.bus.short_reply = 3;  // the four configuration registers' read-back, one byte short
  rig.run(2);
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::impossible_value), 1u);
  EXPECT_EQ(rig.mpu.total_faults(), 1u);
  EXPECT_EQ(rig.mpu.restart_count(), 1u);
  rig.bus.short_reply = -1;
  rig.run(300);
  EXPECT_TRUE(rig.mpu.healthy());
}

// The bus time of what each tick begins (i2c.hpp's bits; 2.5 us a bit at 400 kHz): the reset write
// 29 bits, the waits nothing, the configuration write 56 bits, each burst 156 bits, 390 us, the
// most any tick takes.
TEST(Mpu6050, ReportsTheBusTimeOfEachTick) {
  Rig rig;
  std::vector<uint32_t> ns;
  for (int i = 0; i < 180; ++i) {
    rig.step();
    ns.push_back(rig.mpu.bus_time_ns_this_tick(400000));
  }
  EXPECT_EQ(ns[0], 72500u);    // write PWR_MGMT_1
  EXPECT_EQ(ns[50], 0u);       // waiting for the reset
  EXPECT_EQ(ns[101], 97500u);  // read WHO_AM_I: 39 bits
  EXPECT_EQ(ns[103], 140000u);
  EXPECT_EQ(ns[104], 165000u);  // read the four back: 66 bits
  EXPECT_EQ(ns[105], 165000u);  // the four trim registers
  EXPECT_EQ(ns[106], 95000u);   // GYRO_CONFIG and ACCEL_CONFIG: 38 bits
  EXPECT_EQ(ns[120], 0u);       // the gyros settling
  EXPECT_EQ(ns[138], 390000u);  // the self-test's samples are bursts
  EXPECT_EQ(ns[150], 0u);       // the filter settling
  EXPECT_EQ(ns[177], 390000u);
  EXPECT_EQ(ns[179], 390000u);
  EXPECT_EQ(rig.mpu.bus_bits_this_tick(), 156u);
  EXPECT_EQ(*std::max_element(ns.begin(), ns.end()), 390000u);
  EXPECT_EQ(rig.mpu.bus_time_ns_this_tick(100000), 1560000u);  // more than a 1 kHz tick at 100 kHz
  // A tick that begins nothing (the bus refused) costs nothing.
  rig.bus.refuse_begin = true;
  rig.step();
  EXPECT_EQ(rig.mpu.bus_time_ns_this_tick(400000), 0u);
}

// Settings the chip cannot take are refused before the bus is touched.
TEST(Mpu6050, RefusesAConfigurationTheChipCannotTake) {
  std::vector<Mpu6050Config> bad(6);
  bad[0].dlpf = 7;
  bad[1].gyro_full_scale = 4;
  bad[2].accel_full_scale = 4;
  bad[3].address = 0x50;
  bad[4].chip_to_body = {{0, 1, 2}, {1, 1, -1}};  // a mirror
  bad[5].chip_to_body = {{0, 0, 2}, {1, 1, 1}};   // an axis twice
  for (const Mpu6050Config& config : bad) {
    EXPECT_FALSE(drivers::valid(config));
    Rig rig(config);
    rig.run(300);
    EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::refused);
    EXPECT_EQ(rig.transfers(), 0u);
    EXPECT_FALSE(rig.mpu.healthy());
  }
  EXPECT_TRUE(drivers::valid(Mpu6050Config{}));
  Mpu6050Config identity;
  identity.chip_to_body = {{0, 1, 2}, {1, 1, 1}};
  EXPECT_TRUE(drivers::valid(identity));
}

TEST(Mpu6050, FaultNamesFollowTheEnumeration) {
  EXPECT_STREQ(drivers::kMpu6050FaultNames[static_cast<size_t>(Mpu6050Fault::wrong_identity)], "wrong identity");
  EXPECT_STREQ(drivers::kMpu6050FaultNames[static_cast<size_t>(Mpu6050Fault::no_answer)], "no answer");
  EXPECT_STREQ(drivers::kMpu6050FaultNames[static_cast<size_t>(Mpu6050Fault::self_test)], "self-test");
}

// ---- The self-test (RM 4.1; PS 6.1, 6.2; common/drivers/mpu6050_self_test.hpp) ----

// The integer tables, computed at compile time without floating point, are RM 4.1's formulas
// computed in double and rounded, for every code; code 0 is no trim.
TEST(Mpu6050SelfTest, TrimTablesAreTheFormulasRounded) {
  for (int code = 0; code < 32; ++code) {
    SCOPED_TRACE(code);
    EXPECT_EQ(reg::kGyroTrim.counts[code], std::lround(gyro_trim_formula(code)));
    EXPECT_EQ(reg::kAccelTrim.counts[code], std::lround(accel_trim_formula(code)));
  }
  EXPECT_EQ(reg::kGyroTrim.counts[0], 0);
  EXPECT_EQ(reg::kAccelTrim.counts[0], 0);
  // The ends: 25 °/s and 0.34 g at code 1; 0.92 g at code 31 (RM 4.1), 96.4 °/s.
  EXPECT_EQ(reg::kGyroTrim.counts[1], 3275);
  EXPECT_EQ(reg::kAccelTrim.counts[1], 1393);
  EXPECT_EQ(reg::kGyroTrim.counts[31], 12623);
  EXPECT_EQ(reg::kAccelTrim.counts[31], 3768);
}

// Each gyroscope code is bits 4:0 of its axis' register; each accelerometer code is bits 7:5 of
// that register (its high three) and two bits of SELF_TEST_A (X 5:4, Y 3:2, Z 1:0).
TEST(Mpu6050SelfTest, TheCodesAreSplitAcrossTheRegistersAsRm41Says) {
  uint8_t codes[6] = {};
  reg::trim_codes(test_support::kMpu6050Trim, codes);
  for (int axis = 0; axis < 6; ++axis) EXPECT_EQ(codes[axis], kTrimCodes[axis]) << axis;
  EXPECT_EQ(test_support::kMpu6050Trim[0], 0x8C);    // XA_TEST[4:2] 100, XG_TEST 01100
  EXPECT_EQ(test_support::kMpu6050Trim[3], 0x27);    // XA_TEST[1:0] 10, YA 01, ZA 11
  reg::trim_codes({0xFF, 0xFF, 0xFF, 0xFF}, codes);  // bits 7:6 of SELF_TEST_A are reserved
  for (int axis = 0; axis < 6; ++axis) EXPECT_EQ(codes[axis], 31) << axis;
  reg::trim_codes({0x00, 0x00, 0x00, 0x30}, codes);  // X's low bits only
  EXPECT_EQ(codes[0], 3);
  EXPECT_EQ(codes[1] | codes[2] | codes[3] | codes[4] | codes[5], 0);
  int32_t trim[6] = {};
  reg::factory_trim(test_support::kMpu6050Trim, trim);
  EXPECT_LT(trim[4], 0) << "the gyroscope's Y axis responds the other way (RM 4.1)";
  for (int axis : {0, 1, 2, 3, 5}) EXPECT_GT(trim[axis], 0) << axis;
}

// (STR - FT) / FT within ±14 %: for 8 samples of a trim of 3275 counts the sum may be 26 200 less
// 3 668 to 26 200 plus 3 668, not a count beyond; a response of the wrong sign fails; no trim
// (code 0) fails whatever the response.
TEST(Mpu6050SelfTest, PassesWithin14PercentOfTheTrimAndNoFurther) {
  EXPECT_TRUE(reg::self_test_passes(26200 + 3668, 8, 3275));
  EXPECT_FALSE(reg::self_test_passes(26200 + 3669, 8, 3275));
  EXPECT_TRUE(reg::self_test_passes(26200 - 3668, 8, 3275));
  EXPECT_FALSE(reg::self_test_passes(26200 - 3669, 8, 3275));
  EXPECT_TRUE(reg::self_test_passes(-26200 - 3668, 8, -3275));
  EXPECT_FALSE(reg::self_test_passes(-26200 + 3669, 8, -3275));
  EXPECT_FALSE(reg::self_test_passes(26200, 8, -3275));
  EXPECT_FALSE(reg::self_test_passes(0, 8, 0));
  EXPECT_FALSE(reg::self_test_passes(26200, 8, 0));
  // The largest sums the driver can form: 8 differences of full-scale outputs.
  EXPECT_FALSE(reg::self_test_passes(8 * 65535, 8, 12623));
  EXPECT_FALSE(reg::self_test_passes(-8 * 65535, 8, -12623));
}

// The default part, self-tested at start-up: every axis' response within bounds, so it streams.
// Each axis in turn responding 16 % over or under its trim (or the gyroscope's y the wrong way)
// fails the self-test, that axis alone named, counted as its own kind, and the IMU never streams;
// 12 % over or under passes. Both kinds of sensor, each axis.
TEST(Mpu6050, TheSelfTestFailsAnAxisThatRespondsOutsideItsBounds) {
  for (int axis = 0; axis < 6; ++axis) {
    for (const double factor : {1.16, 0.84, 1.12, 0.88, -1.0}) {
      SCOPED_TRACE(testing::Message() << "axis " << axis << " response x " << factor);
      Rig rig;
      rig.bus.response[axis] = static_cast<int32_t>(std::lround(rig.bus.response[axis] * factor));
      rig.run(400);
      const bool passes = factor > 0.86 && factor < 1.14;
      EXPECT_EQ(rig.mpu.healthy(), passes);
      EXPECT_GE(rig.mpu.self_tests(), 1u);
      if (passes) {
        EXPECT_EQ(rig.mpu.self_test_failures(), 0u);
        EXPECT_EQ(rig.mpu.total_faults(), 0u);
        continue;
      }
      EXPECT_EQ(rig.mpu.self_test_failures(), 1u << axis);
      EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::self_test), rig.mpu.self_tests());
      EXPECT_EQ(rig.mpu.total_faults(), rig.mpu.self_tests());
      EXPECT_EQ(rig.mpu.last_fault(), Mpu6050Fault::self_test);
      EXPECT_EQ(rig.mpu.samples(), 0u);
      EXPECT_EQ(rig.mpu.phase(), Mpu6050Phase::starting);
    }
  }
}

// A dead part (no response at all) fails its self-test at tick 165 and starts over 100 ms later,
// as for a wrong identity: 265 ticks a try, four in a second, never healthy, every one counted.
// Healed, it passes at the next try, self-tested again (the IMU had never streamed), and streams.
TEST(Mpu6050, AFailedSelfTestIsTriedAgainAndTheImuNeverStreams) {
  Rig rig;
  for (int32_t& r : rig.bus.response) r = 0;
  bool ever_healthy = false;
  for (int i = 0; i < 1000; ++i) {
    rig.step();
    ever_healthy = ever_healthy || rig.mpu.healthy();
  }
  EXPECT_FALSE(ever_healthy);
  EXPECT_EQ(rig.mpu.self_tests(), 4u);
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::self_test), 4u);
  EXPECT_EQ(rig.mpu.total_faults(), 4u);
  EXPECT_EQ(rig.mpu.restart_count(), 4u);
  EXPECT_EQ(rig.mpu.self_test_failures(), 0x3Fu);
  EXPECT_EQ(rig.mpu.samples(), 0u);
  // Its configured scales are never restored: the start-up stopped at the verdict.
  EXPECT_EQ(rig.bus.regs[reg::kGyroConfig], 0xE0);
  for (int axis = 0; axis < 6; ++axis) rig.bus.response[axis] = ScriptedBus::healthy_response(axis);
  rig.run(300);
  EXPECT_TRUE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.self_tests(), 5u);
  EXPECT_EQ(rig.mpu.self_test_failures(), 0u);
  EXPECT_EQ(rig.mpu.total_faults(), 4u);
}

// 8 ms of samples each way, a burst a tick at a sample a tick: 8 at 1 kHz, 4 at 500 Hz (the 500 Hz
// build's SMPLRT_DIV 1), at most 8 (8 kHz without the filter), at least 1 (a slow sample rate).
TEST(Mpu6050SelfTest, TakesEightMillisecondsOfSamplesEachWay) {
  Mpu6050Config config;
  EXPECT_EQ(drivers::self_test_samples(config), 8);
  config.sample_rate_divider = 1;
  EXPECT_EQ(drivers::self_test_samples(config), 4);
  config.sample_rate_divider = 99;
  EXPECT_EQ(drivers::self_test_samples(config), 1);
  config.sample_rate_divider = 0;
  config.dlpf = 0;
  EXPECT_EQ(drivers::self_test_samples(config), 8);
}

// At 500 Hz (a tick of 2 ms, SMPLRT_DIV 1) four samples each way, judged by four: the same part
// passes; one whose gyroscope z responds 16 % short fails.
TEST(Mpu6050, AtFiveHundredHertzTheSelfTestTakesFourSamplesEachWay) {
  Mpu6050Config config;
  config.sample_rate_divider = 1;
  for (const double factor : {1.0, 0.84}) {
    SCOPED_TRACE(factor);
    Rig rig(config);
    rig.bus.response[5] = static_cast<int32_t>(std::lround(rig.bus.response[5] * factor));
    rig.run(200);  // 200 ticks of 1 ms: the waits in microseconds; the count of bursts is what matters
    size_t bursts = 0;
    for (const I2cTransfer& t : rig.bus.begun) bursts += is_burst(t) ? 1u : 0u;
    EXPECT_EQ(rig.mpu.self_tests(), 1u);
    if (factor == 1.0) {
      EXPECT_TRUE(rig.mpu.healthy());
      EXPECT_EQ(bursts - rig.mpu.samples() - 1, 8u) << "four and four, then the flight's (one on the wire)";
    } else {
      EXPECT_FALSE(rig.mpu.healthy());
      EXPECT_EQ(rig.mpu.self_test_failures(), 1u << 5);
      EXPECT_EQ(bursts, 8u);
    }
  }
}

// A part with no trim recorded (every code 0): nothing to compare with, so no axis passes.
TEST(Mpu6050, APartWithoutTrimFailsItsSelfTest) {
  Rig rig;
  for (uint8_t r = reg::kSelfTestX; r < reg::kSelfTestX + reg::kTrimRegisters; ++r) rig.bus.regs[r] = 0;
  rig.run(400);
  EXPECT_FALSE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.self_test_failures(), 0x3Fu);
  EXPECT_GE(rig.mpu.fault_count(Mpu6050Fault::self_test), 1u);
}

// A fault during the self-test's samples starts the start-up over, and the self-test with it,
// its sums from nothing: the second try passes.
TEST(Mpu6050, AFaultDuringTheSelfTestStartsItOverFromNothing) {
  Rig rig;
  rig.run(160);  // three samples with the bits set taken (157, 158, 159)
  rig.bus.script = {I2cResult::bus_stuck};
  rig.run(2);
  EXPECT_EQ(rig.mpu.fault_count(Mpu6050Fault::bus_stuck), 1u);
  EXPECT_EQ(rig.mpu.restart_count(), 1u);
  EXPECT_EQ(rig.mpu.self_tests(), 0u);
  rig.run(300);
  EXPECT_TRUE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.self_tests(), 1u);
  EXPECT_EQ(rig.mpu.self_test_failures(), 0u);
  EXPECT_EQ(rig.mpu.total_faults(), 1u);
}

// Lost while streaming (perhaps in the air: the vehicle moves, and a self-test would judge its
// motion), the driver starts over without the self-test: no trim read, no self-test scales or
// bits written, and it streams 138 ticks after its reset as it did before the self-test was
// added, even from a part whose self-test would now fail.
TEST(Mpu6050, ALostSensorStartsOverWithoutTheSelfTest) {
  Rig rig;
  rig.start();
  ASSERT_EQ(rig.mpu.self_tests(), 1u);
  for (int32_t& r : rig.bus.response) r = 0;
  rig.bus.present = false;
  rig.run(11);
  ASSERT_EQ(rig.mpu.lost_count(), 1u);
  const size_t reset_at = rig.transfers() - 1;
  ASSERT_TRUE(is_reset_write(rig.bus.begun[reset_at]));
  const uint32_t reset_tick = rig.bus.begun_tick[reset_at];
  rig.bus.present = true;
  rig.run(1);  // the reset, NACKed: started over 100 ms later
  rig.run(400);
  EXPECT_TRUE(rig.mpu.healthy());
  EXPECT_EQ(rig.mpu.self_tests(), 1u);
  size_t after = reset_at;
  while (!is_reset_write(rig.bus.begun[after]) || rig.bus.begun_tick[after] == reset_tick) ++after;
  const uint32_t restarted = rig.bus.begun_tick[after];
  for (size_t i = reset_at; i < rig.transfers(); ++i) {
    const I2cTransfer& t = rig.bus.begun[i];
    EXPECT_NE(t.write[0], reg::kSelfTestX) << "transfer " << i;
    EXPECT_FALSE(t.write[0] == reg::kGyroConfig && t.write_count > 1 && (t.write[1] & reg::kSelfTestBits) != 0);
    EXPECT_FALSE(t.write[0] == reg::kGyroConfig && t.write_count == 3 && t.write[1] == 0x00) << "self-test scales";
  }
  size_t first_burst = after;
  while (!is_burst(rig.bus.begun[first_burst])) ++first_burst;
  EXPECT_EQ(rig.bus.begun_tick[first_burst] - restarted, 136u);
  EXPECT_EQ(rig.bus.begun[first_burst - 1].write[0], reg::kPwrMgmt1) << "the configuration, then the settling";
}

}  // namespace
