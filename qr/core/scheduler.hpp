// The kick-driven cooperative scheduler, in three phases per control period:
//   1. wait for the timer kick;
//   2. run: take the latest sensor sample and a bounded number of received bytes, run the task
//      set of the current mode, hand out engine values and a bounded number of bytes to send;
//   3. finish: account timing, choose the next task set, and when the tick ran into the next
//      kick count a deadline miss and skip that period instead of piling up.
//
// The context (the flight, flight.hpp; test mode's replay, replay_tick.hpp) owns the flight data
// and the task table: what the scheduler calls on it is the `SchedulerContext` concept below, as
// what it calls on a board is the `Board` concept (board.hpp).
//
// The optional exchanges, each only where both the board (board.hpp) and the context have it (a
// concept on each side: OverrunCountingBoard and OverrunCountingContext, ...): a board that counts
// its serial receiver's overruns tells the context (serial_overruns) before the bytes; a board with
// a radio receiver (RadioBoard) gives the context (radio_space, radio_receive) a bounded number of
// radio bytes per tick; after the engines, a board whose ESCs answer (EscAnswerBoard) hands their
// answers to the context (esc_answers), and one whose ESCs take commands (EscCommandBoard) is sent
// the context's (esc_command_due), and the context is told whether the board took it
// (esc_command_sent).
//
// Every rate, phase and budget is in the context's task table (task.hpp); no task divides itself.
//
// The sets are known at compile time, so each is compiled into a straight run of its rows
// (run_set below): no loop, no call through a pointer, a rate check only on the rows that are
// divided, and each row's budget and statistics at a fixed address. What the scheduler adds to
// a tick is then little more than two cycle-counter reads and a count and a sum per task
// (scripts/devboard --bench prints it as scheduler_overhead_instr_mean).
#pragma once

#include <stdint.h>

#include <qr/core/board.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/cycle_stats.hpp>
#include <qr/core/sensor_stage.hpp>
#include <qr/core/task.hpp>

namespace qr {

// What the serial line carries in one control period: 115200 baud, 10 bits a byte (8N1).
inline constexpr uint32_t kLineBytesPerSecond = 115200 / 10;
inline constexpr uint16_t kLineBytesPerTick = static_cast<uint16_t>((kLineBytesPerSecond + kControlHz - 1) /
                                                                    kControlHz);

struct SchedulerLimits {
  // Per-tick I/O bounds: a little more than the line can carry in a period (12 bytes at 1 kHz,
  // 24 at 500 Hz), so the link keeps up while no tick ever sees a burst of link work. Receiving
  // gets twice that, to catch up after a late tick.
  uint16_t rx_bytes_per_tick = static_cast<uint16_t>(2 * kLineBytesPerTick + 8);
  uint16_t tx_bytes_per_tick = static_cast<uint16_t>(kLineBytesPerTick + 4);
  // A CRSF receiver at 420 000 baud delivers up to 42 bytes a millisecond in a burst (an RC frame
  // is 26 bytes, at most 150 of them a second here): a frame and a half per tick.
  uint16_t radio_bytes_per_tick = 40;
};

// What the context learns about each finished tick (for telemetry).
struct TickReport {
  uint32_t busy_us = 0;
  uint32_t deadline_misses = 0;
  uint16_t cpu_load_permille = 0;
};

// One task's runs: count, min, mean, max cycles, and the runs over its budget.
using TaskStats = CycleStats;

template <uint8_t TaskCount>
struct SchedulerStats {
  TaskStats task[TaskCount];
  CycleStats tick;                 // cycles from the kick to the end of the tick's work
  uint32_t ticks = 0;              // executed ticks
  uint32_t deadline_misses = 0;    // kicks that arrived while a tick was still running
  uint16_t cpu_load_permille = 0;  // busy share of the last full second
};

namespace detail {
template <class A, class B>
inline constexpr bool same_type = false;
template <class A>
inline constexpr bool same_type<A, A> = true;
}  // namespace detail
template <class T, class U>
concept SameAs = detail::same_type<T, U>;

// What the scheduler calls on its context, all of it: the task table and its sets (task.hpp),
// then the tick's exchanges in the order a tick makes them (the optional ones apart, below).
template <class C>
concept SchedulerTables = requires {
  {C::kTaskCount};  // rows of the task table (first: SchedulerStats<kTaskCount> is made from it)
  {C::kSetCount};   // task sets
  { C::task(uint8_t{}) } -> SameAs<Task<C>>;      // row `id` of the task table
  { C::task_set(uint8_t{}) } -> SameAs<TaskSet>;  // the rows set `set` runs, in order
};
template <class C>
concept SchedulerContext = SchedulerTables<C> &&
    requires(C& c, const C& cc, uint8_t& byte, const SensorSample& sample, const TickReport& report,
             const SchedulerStats<C::kTaskCount>& stats) {
  c.begin_tick(uint32_t{}, sample);           // the kick's time and the latest sample
  { cc.rx_space() } -> SameAs<uint32_t>;      // bytes from the serial line ...
  c.receive(uint8_t{});                       // ... one at a time
  { cc.engines() } -> SameAs<EngineCommand>;  // to the board once the rows ran
  { cc.leds() } -> SameAs<uint8_t>;           // ...
  { cc.tx_peek(byte) } -> SameAs<bool>;       // bytes for the serial line ...
  c.tx_pop();                                 // ... each taken once the board took it
  c.account(report, stats);                   // the tick's figures, when it finished
  { cc.current_set() } -> SameAs<uint8_t>;    // the set for the mode now: the next tick's
  { cc.running() } -> SameAs<bool>;           // false: tick() says the context stopped
};

// The optional exchanges, on the context's side (the board's are board.hpp's).
template <class C>
concept OverrunCountingContext = requires(C& c) {
  c.serial_overruns(uint32_t{});
};
template <class C>
concept RadioContext = requires(C& c, const C& cc) {
  {cc.radio_space()};
  c.radio_receive(uint8_t{});
};
template <class C>
concept EscAnswerContext = requires(C& c, const EscAnswers& answers) {
  c.esc_answers(answers);
};
template <class C>
concept EscCommandContext = requires(C& c) {
  { c.esc_command_due() } -> SameAs<EscCommand>;
  c.esc_command_sent(bool{});  // whether the board took it
};

template <Board B, SchedulerContext Context>
class Scheduler {
 public:
  static constexpr uint8_t kTaskCount = Context::kTaskCount;
  using Stats = SchedulerStats<kTaskCount>;

  // `first_tick`: the number of the first tick, for the dividers' phases (a replay that starts
  // part-way through a flight continues the flight's count).
  Scheduler(B& board, Context& context, SchedulerLimits limits = {}, uint32_t first_tick = 0)
      : board_(board), context_(context), limits_(limits), seen_kick_(board.kicks()), next_set_(context.current_set()),
        ticks_(first_tick), window_start_us_(board.now_us()) {
    retime_all();
  }

  // One control period. Returns false once the context has stopped.
  bool tick() {
    seen_kick_ = board_.wait_kick(seen_kick_);
    const uint32_t kick = seen_kick_;
    const uint32_t start_us = board_.now_us();
    const uint32_t start_cycles = board_.cycles();
    run(start_us);
    finish(kick, start_us, start_cycles);
    return context_.running();
  }

  void run_until_stopped() {
    while (tick()) {
    }
  }

  const Stats& stats() const { return stats_; }
  void reset_stats() { stats_ = Stats{}; }
  // The row running now, kNoTask between tasks: what a fault handler reports.
  uint8_t running_task() const { return running_; }
  // Where that index lives: a fault handler, which cannot be handed the scheduler, reads it there.
  const volatile uint8_t* running_task_cell() const { return &running_; }
  uint16_t divider(uint8_t id) const { return slots_[id].divider; }
  // A board with its sensors on an I2C bus: the drivers, their faults and the stage's cycles.
  const SensorStage<B>& sensor_stage() const { return sensors_; }

 private:
  void run(uint32_t now_us) {
    if constexpr (I2cBoard<B>) {
      context_.begin_tick(now_us, sensors_.read(board_, now_us));  // the drivers' (sensor_stage.hpp)
    } else {
      context_.begin_tick(now_us, board_.read_sensors());
    }
    if constexpr (OverrunCountingBoard<B> && OverrunCountingContext<Context>) {
      context_.serial_overruns(board_.rx_overruns());
    }
    uint8_t byte = 0;
    for (uint16_t n = 0; n < limits_.rx_bytes_per_tick && context_.rx_space() > 0; ++n) {
      if (!board_.serial_read(byte)) break;
      context_.receive(byte);
    }
    if constexpr (RadioBoard<B> && RadioContext<Context>) {
      for (uint16_t n = 0; n < limits_.radio_bytes_per_tick && context_.radio_space() > 0; ++n) {
        if (!board_.radio_read(byte)) break;
        context_.radio_receive(byte);
      }
    }

    run_current_set(next_set_, ticks_);
    running_ = kNoTask;

    board_.set_engines(context_.engines());
    if constexpr (EscAnswerBoard<B> && EscAnswerContext<Context>) {
      EscAnswers answers;
      if (board_.esc_answers(answers)) context_.esc_answers(answers);
    }
    if constexpr (EscCommandBoard<B> && EscCommandContext<Context>) {
      const EscCommand due = context_.esc_command_due();
      if (due.command != 0) context_.esc_command_sent(board_.esc_command(due.command, due.engines));
    }
    board_.set_leds(context_.leds());
    for (uint16_t n = 0; n < limits_.tx_bytes_per_tick && context_.tx_peek(byte); ++n) {
      if (!board_.serial_write(byte)) break;
      context_.tx_pop();
    }
  }

  void finish(uint32_t kick, uint32_t start_us, uint32_t start_cycles) {
    stats_.tick.add(board_.cycles() - start_cycles);
    ++stats_.ticks;
    ++ticks_;

    // Kicks that came while we ran are periods we cannot have on time: count each one and skip
    // them, so the next tick starts on the next fresh kick, in phase.
    const uint32_t now_kick = board_.kicks();
    if (now_kick != kick) {
      stats_.deadline_misses += now_kick - kick;
      seen_kick_ = now_kick;
    }

    const uint32_t end_us = board_.now_us();
    const uint32_t busy_us = end_us - start_us;
    window_busy_us_ += busy_us;
    const uint32_t window_us = end_us - window_start_us_;
    if (window_us >= 1000000u) {
      stats_.cpu_load_permille = static_cast<uint16_t>(static_cast<uint64_t>(window_busy_us_) * 1000u / window_us);
      window_busy_us_ = 0;
      window_start_us_ = end_us;
    }

    context_.account(TickReport{busy_us, stats_.deadline_misses, stats_.cpu_load_permille}, stats_);
    next_set_ = context_.current_set();
  }

  // A row's work, one copy in the image however many sets run it (inlined into every set, the
  // task bodies would take the image past the board's budget, docs/devboard.md).
  template <uint8_t Id>
  [[gnu::noinline]] static void run_row(Context& context) {
    Context::task(Id).run(context);
  }

  // One row: run it when its rate and phase say so, and account for it.
  template <uint8_t Id>
  [[gnu::always_inline]] inline void run_task(uint32_t t) {
    constexpr Task<Context> row = Context::task(Id);
    if constexpr (row.divider_from != nullptr) {
      if (t % slots_[Id].divider != slots_[Id].phase) return;
    } else if constexpr (row.divider > 1) {
      // The table's own rate: constants, so a power of two is a mask and nothing is loaded.
      if (t % row.divider != row.phase % row.divider) return;
    }
    running_ = Id;
    const uint32_t before = board_.cycles();
    run_row<Id>(context_);
    stats_.task[Id].add(board_.cycles() - before, row.budget);
    if constexpr (row.divider_from != nullptr) retime<Id>();
  }

  // The rows of set `Set` from the I-th on, one after the other.
  template <uint8_t Set, uint8_t I = 0>
  [[gnu::always_inline]] inline void run_rows(uint32_t t) {
    constexpr TaskSet set = Context::task_set(Set);
    if constexpr (I < set.count) {
      run_task<set.ids[I]>(t);
      run_rows<Set, I + 1>(t);
    }
  }
  template <uint8_t Set>
  [[gnu::noinline]] void run_set(uint32_t t) {
    run_rows<Set>(t);
  }

  // The set `set` by direct calls, one compare per set: a table of pointers would make every set
  // a target of every indirect call to the stack bound of scripts/elfcheck.
  template <uint8_t Set = 0>
  [[gnu::always_inline]] inline void run_current_set(uint8_t set, uint32_t t) {
    if constexpr (Set < Context::kSetCount) {
      if (set == Set) {
        run_set<Set>(t);
      } else {
        run_current_set<Set + 1>(set, t);
      }
    }
  }

  // A row's rate from the table, or from the context where the row says so. Rows are only ever
  // named at compile time, so the table itself is not kept in the image.
  template <uint8_t Id>
  void retime() {
    constexpr Task<Context> row = Context::task(Id);
    const uint16_t d = row.divider_from != nullptr ? row.divider_from(context_) : row.divider;
    slots_[Id].divider = d == 0 ? uint16_t{1} : d;
    slots_[Id].phase = static_cast<uint16_t>(row.phase % slots_[Id].divider);
  }
  template <uint8_t Id = 0>
  void retime_all() {
    if constexpr (Id < kTaskCount) {
      retime<Id>();
      retime_all<Id + 1>();
    }
  }

  B& board_;
  Context& context_;
  [[no_unique_address]] SensorStage<B> sensors_;
  SchedulerLimits limits_;
  uint32_t seen_kick_;
  uint8_t next_set_;
  uint32_t ticks_;  // executed ticks since start: the clock of dividers and phases
  Stats stats_{};
  // The rate of each row as of its last retime(): the table's, or the context's where the rate is
  // a parameter.
  struct Slot {
    uint16_t divider;
    uint16_t phase;  // < divider
  };
  Slot slots_[kTaskCount] = {};
  volatile uint8_t running_ = kNoTask;
  uint32_t window_start_us_;
  uint32_t window_busy_us_ = 0;
};

}  // namespace qr
