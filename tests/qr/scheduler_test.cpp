// The scheduler on the fake board: phases, task sets, dividers, statistics, deadline misses and
// per-tick I/O bounds.
#include <gtest/gtest.h>

#include <deque>
#include <vector>

#include <qr/boards/fake/fake_board.hpp>
#include <qr/core/flight.hpp>
#include <qr/core/scheduler.hpp>

#include "every_call_context.hpp"
#include "scripted_chain.hpp"

namespace qr {
namespace {

using fake::FakeBoard;

// A context whose tasks only record that they ran and take the time a test gives them.
struct TestContext {
  static constexpr uint8_t kTaskCount = 3;
  static constexpr uint8_t kSetCount = 2;
  static constexpr Task<TestContext> task(uint8_t id);
  static constexpr uint8_t kSetA[] = {0, 2};
  static constexpr uint8_t kSetB[] = {1};

  FakeBoard* board = nullptr;
  bool use_b = false;
  uint32_t runs[kTaskCount] = {};
  uint32_t work_us[kTaskCount] = {};
  uint32_t overrun_on_run = 0;  // run number of task 0 that takes overrun_us more
  uint32_t overrun_us = 0;
  bool switch_to_b_in_task = false;  // a task changes the mode, as the link task would
  uint16_t slow_divider = 10;        // the slow task's rate, as a parameter would set it
  std::vector<uint32_t> slow_ticks;  // the ticks (counted from 0) the slow task ran on
  uint32_t tick = 0;
  uint8_t running_seen = kNoTask;  // what the scheduler said was running, seen from task 1
  const void* scheduler = nullptr;
  void (*on_other)(TestContext&) = nullptr;
  std::deque<uint8_t> rx;
  std::deque<uint8_t> tx;

  static constexpr TaskSet task_set(uint8_t set) { return set == 1 ? TaskSet{kSetB, 1} : TaskSet{kSetA, 2}; }
  uint8_t current_set() const { return use_b ? 1 : 0; }
  void begin_tick(uint32_t, const SensorSample&) { ++tick; }
  uint32_t rx_space() const { return 1000; }
  void receive(uint8_t b) { rx.push_back(b); }
  bool tx_peek(uint8_t& b) const {
    if (tx.empty()) return false;
    b = tx.front();
    return true;
  }
  void tx_pop() { tx.pop_front(); }
  EngineCommand engines() const { return {}; }
  uint8_t leds() const { return 0; }
  bool running() const { return true; }
  template <class Stats>
  void account(const TickReport& r, const Stats&) {
    last_report = r;
  }
  TickReport last_report;

  void work(int id) {
    ++runs[id];
    board->spend_us(work_us[id]);
    if (id == 0 && overrun_us != 0 && runs[0] == overrun_on_run) board->spend_us(overrun_us);
    if (id == 0 && switch_to_b_in_task) use_b = true;
    if (id == 2) slow_ticks.push_back(tick - 1);
    if (id == 1 && on_other != nullptr) on_other(*this);
  }
};

// Budgets in the fake board's cycles (kCyclesPerUs a µs).
constexpr Task<TestContext> kTestTasks[TestContext::kTaskCount] = {
    {"fast", [](TestContext& c) { c.work(0); }, 1, 0, 50 * FakeBoard::kCyclesPerUs},
    {"other", [](TestContext& c) { c.work(1); }, 1, 0, 50 * FakeBoard::kCyclesPerUs},
    {"slow", [](TestContext& c) { c.work(2); }, 10, 3, 50 * FakeBoard::kCyclesPerUs,
     [](const TestContext& c) { return c.slow_divider; }},
};
constexpr Task<TestContext> TestContext::task(uint8_t id) { return kTestTasks[id]; }

// What the scheduler calls on its context is the SchedulerContext concept: the test's context and
// the flight are contexts; a context without any one of the calls is not.
static_assert(SchedulerContext<TestContext>);
static_assert(SchedulerContext<Flight<test::ScriptedChain>>);

// Every call the scheduler makes (every_call_context.hpp), to take away one at a time.
using test_context::EveryCall;
struct Whole : EveryCall<Whole> {};
static_assert(SchedulerContext<Whole>);
struct WithoutLeds : EveryCall<WithoutLeds> {
  uint8_t leds() const = delete;
};
static_assert(!SchedulerContext<WithoutLeds>, "a context that cannot say its LEDs");
struct WithoutTaskTable : EveryCall<WithoutTaskTable> {
  static constexpr Task<WithoutTaskTable> task(uint8_t) = delete;
};
static_assert(!SchedulerContext<WithoutTaskTable>);
struct WithoutAccount : EveryCall<WithoutAccount> {
  void account(const TickReport&, const SchedulerStats<kTaskCount>&) = delete;
};
static_assert(!SchedulerContext<WithoutAccount>);
struct WithoutRunning : EveryCall<WithoutRunning> {
  bool running() const = delete;
};
static_assert(!SchedulerContext<WithoutRunning>);
// The task table's rows must be the context's own: rows of another context's table are not.
struct AnothersRows : EveryCall<AnothersRows> {
  static constexpr Task<Whole> task(uint8_t) { return Whole::task(0); }
};
static_assert(!SchedulerContext<AnothersRows>);
// A context with no members at all, and one missing only its set count (no deletion needed).
struct Nothing {};
static_assert(!SchedulerContext<Nothing>);
struct NoSetCount : test_context::EveryCallButTheSetCount<NoSetCount> {};
static_assert(!SchedulerContext<NoSetCount>, "a context that does not say how many task sets it has");

struct SchedulerTest : ::testing::Test {
  FakeBoard board;
  TestContext context;
  SchedulerTest() { context.board = &board; }
};

TEST_F(SchedulerTest, OverrunCountsOneMissAndNextPeriodStartsOnTime) {
  context.work_us[0] = kPeriodUs / 10;
  context.overrun_on_run = 6;      // the 6th tick runs ...
  context.overrun_us = kPeriodUs;  // ... 1.1 periods: it runs into the next kick
  Scheduler scheduler(board, context);
  for (int i = 0; i < 10; ++i) scheduler.tick();

  EXPECT_EQ(scheduler.stats().deadline_misses, 1u);
  EXPECT_EQ(context.last_report.deadline_misses, 1u);
  ASSERT_EQ(board.kick_times_us.size(), 10u);
  // Ticks 1..6 start at kicks 1..6; kick 7 fell inside tick 6 and is skipped; tick 7 starts
  // exactly on kick 8, and every later tick stays on the period grid.
  for (uint32_t i = 0; i < 6; ++i) EXPECT_EQ(board.kick_times_us[i], (i + 1) * kPeriodUs);
  for (uint32_t i = 6; i < 10; ++i) EXPECT_EQ(board.kick_times_us[i], (i + 2) * kPeriodUs);
}

TEST_F(SchedulerTest, OverrunOfSeveralPeriodsCountsEachSkippedKick) {
  context.overrun_on_run = 2;
  context.overrun_us = 3 * kPeriodUs + kPeriodUs / 2;  // runs into kicks 3, 4 and 5
  Scheduler scheduler(board, context);
  for (int i = 0; i < 5; ++i) scheduler.tick();
  EXPECT_EQ(scheduler.stats().deadline_misses, 3u);
  EXPECT_EQ(board.kick_times_us[2], 6 * kPeriodUs);
}

TEST_F(SchedulerTest, NoMissesWhenTasksFitThePeriod) {
  context.work_us[0] = kPeriodUs - 1;
  Scheduler scheduler(board, context);
  for (int i = 0; i < 100; ++i) scheduler.tick();
  EXPECT_EQ(scheduler.stats().deadline_misses, 0u);
  EXPECT_EQ(scheduler.stats().ticks, 100u);
}

TEST_F(SchedulerTest, RunsTheTaskSetOfTheCurrentModeChosenAtFinish) {
  context.switch_to_b_in_task = true;
  Scheduler scheduler(board, context);
  scheduler.tick();  // runs set A, whose task changes the mode: the finish phase picks set B
  scheduler.tick();
  scheduler.tick();
  EXPECT_EQ(context.runs[0], 1u);
  EXPECT_EQ(context.runs[1], 2u);
}

TEST_F(SchedulerTest, SlowTasksRunAtTheirDivider) {
  Scheduler scheduler(board, context);
  for (int i = 0; i < 100; ++i) scheduler.tick();
  EXPECT_EQ(context.runs[0], 100u);
  EXPECT_EQ(context.runs[2], 10u);
}

TEST_F(SchedulerTest, ADividedTaskRunsOnItsPhaseAndTakesANewRateAfterItsNextRun) {
  Scheduler scheduler(board, context);
  for (int i = 0; i < 30; ++i) scheduler.tick();
  EXPECT_EQ(context.slow_ticks, (std::vector<uint32_t>{3, 13, 23}));
  context.slow_divider = 4;  // the parameter changes: read again after the next run
  context.slow_ticks.clear();
  for (int i = 0; i < 22; ++i) scheduler.tick();  // ticks 30..51
  EXPECT_EQ(context.slow_ticks, (std::vector<uint32_t>{33, 35, 39, 43, 47, 51}));
  EXPECT_EQ(scheduler.divider(2), 4);
}

TEST_F(SchedulerTest, ARunOverItsBudgetIsAnOverrunOfThatTask) {
  Scheduler scheduler(board, context);
  context.work_us[0] = 50;  // at the budget: not an overrun
  scheduler.tick();
  context.work_us[0] = 51;
  scheduler.tick();
  scheduler.tick();
  EXPECT_EQ(scheduler.stats().task[0].overruns, 2u);
  EXPECT_EQ(scheduler.stats().task[2].overruns, 0u);
}

TEST_F(SchedulerTest, TheRunningTaskIsKnownWhileItRunsAndNoneBetweenTasks) {
  struct Spy {
    static void check(TestContext& c) {
      c.running_seen = static_cast<const Scheduler<FakeBoard, TestContext>*>(c.scheduler)->running_task();
    }
  };
  context.use_b = true;  // set B: task 1 only
  Scheduler scheduler(board, context);
  context.scheduler = &scheduler;
  context.on_other = &Spy::check;
  scheduler.tick();
  EXPECT_EQ(context.running_seen, 1);
  EXPECT_EQ(scheduler.running_task(), kNoTask);
}

TEST_F(SchedulerTest, TaskStatisticsInCycles) {
  Scheduler scheduler(board, context);
  for (uint32_t us : {10u, 30u, 20u}) {
    context.work_us[0] = us;
    scheduler.tick();
  }
  const CycleStats& s = scheduler.stats().task[0];
  EXPECT_EQ(s.count, 3u);
  EXPECT_EQ(s.min, 10u * FakeBoard::kCyclesPerUs);
  EXPECT_EQ(s.max, 30u * FakeBoard::kCyclesPerUs);
  EXPECT_EQ(s.mean(), 20u * FakeBoard::kCyclesPerUs);
  EXPECT_GE(scheduler.stats().tick.max, s.max);
}

TEST_F(SchedulerTest, CpuLoadIsTheBusyShareOfTheLastSecond) {
  context.work_us[0] = kPeriodUs / 4;
  Scheduler scheduler(board, context);
  for (uint32_t i = 0; i < kControlHz + 1; ++i) scheduler.tick();
  EXPECT_NEAR(scheduler.stats().cpu_load_permille, 250, 2);
}

TEST_F(SchedulerTest, ReceivedBytesPerTickAreBounded) {
  for (int i = 0; i < 100; ++i) board.rx.push_back(static_cast<uint8_t>(i));
  SchedulerLimits limits;
  Scheduler scheduler(board, context, limits);
  scheduler.tick();
  EXPECT_EQ(context.rx.size(), limits.rx_bytes_per_tick);
  EXPECT_EQ(board.rx.size(), 100u - limits.rx_bytes_per_tick);
}

TEST_F(SchedulerTest, SentBytesPerTickAreBoundedAndNothingIsLostWhenTheUartIsFull) {
  for (int i = 0; i < 100; ++i) context.tx.push_back(static_cast<uint8_t>(i));
  SchedulerLimits limits;
  Scheduler scheduler(board, context, limits);
  scheduler.tick();
  EXPECT_EQ(board.tx.size(), limits.tx_bytes_per_tick);
  board.tx_capacity = board.tx.size() + 3;  // the transmitter takes only 3 more
  scheduler.tick();
  EXPECT_EQ(board.tx.size(), limits.tx_bytes_per_tick + 3u);
  EXPECT_EQ(context.tx.size(), 100u - limits.tx_bytes_per_tick - 3u);
  EXPECT_EQ(context.tx.front(), limits.tx_bytes_per_tick + 3u);  // next byte in order
}

}  // namespace
}  // namespace qr
