// The flight firmware's cost per tick on the devboard, mode by mode, in instructions retired
// (exact under QEMU -icount). `scripts/devboard --bench` runs it; one JSON object per line.
//
// The bench board never waits: each kick comes at once and moves time on by one period, so the
// bench runs as fast as QEMU can go while the firmware sees a steady control rate. Between ticks
// (outside what is measured) the board makes the next sensor sample from the synthetic flight
// and a scripted pilot puts frames on the serial line, as the console would: telemetry at
// 100 Hz, control at 50 Hz, the mode requests that arm each mode the legal way, the observable
// table and two observable streams in the modes on the ground.
//
// Then the same firmware with the chain in float (soft-float through libgcc) flies full control:
// the speed comparison the fixed-point design is judged by. Then the hobbyist's hardware
// (docs/drivers.md): the cost of encoding four DShot frames and of parsing one CRSF RC frame, and
// full control flown from a radio (CRSF at 150 Hz on the board's receiver line, armed by its
// switch) with the engines sent as DShot frames.
#include <common/byte_ring.hpp>
#include <common/drivers/crsf.hpp>
#include <common/drivers/crsf_parser.hpp>
#include <common/drivers/dshot_commands.hpp>
#include <common/drivers/rc_sticks.hpp>
#include <common/messages.hpp>
#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/core/chain/flight_chain.hpp>
#include <qr/core/flight.hpp>
#include <qr/core/scheduler.hpp>

#include <qr/host/real_number_policy.hpp>

#include "../../fixedpoint/bench/float_math.hpp"
#include "../chain/synthetic_flight.hpp"
#include "sensor_bench.hpp"

namespace {

using qr::Mode;

// What the float chain needs of a math library: the fixed-point library's own algorithms in
// float (the target has no libm).
struct SoftFloatMath {
  static double ldexp(double x, int e) {  // parameter changes only, never per tick
    for (; e > 0; --e) x *= 2.0;
    for (; e < 0; ++e) x *= 0.5;
    return x;
  }
  static int32_t round_half_up(float x) {
    const float r = x + 0.5f;
    if (!(r > -2147483648.0f)) return INT32_MIN;
    if (!(r < 2147483648.0f)) return INT32_MAX;
    const int32_t t = static_cast<int32_t>(r);  // truncates toward zero
    return static_cast<float>(t) > r ? t - 1 : t;
  }
  static float sqrt(float x) { return bench::flt::sqrt(x); }
  static float atan2(float y, float x) { return bench::flt::atan2(y, x); }
};
using FloatChain = qr::FlightChain<qr::chain::RealNumbers<float, SoftFloatMath>>;

constexpr uint32_t kMeasuredTicks = 2000;
constexpr uint32_t kArmingTicksMax = 5000;


// `Radio`: the board has a receiver line (the rig puts CRSF frames on it) and drives DShot ESCs
// (set_engines encodes the four frames, inside the measured tick).
template <bool Radio>
class BenchBoard {
 public:
  uint32_t wait_kick(uint32_t seen) {
    kicks_ = seen + 1;
    now_us_ += qr::kPeriodUs;
    sample_ = flight_.next().sample;
    return kicks_;
  }
  uint32_t kicks() const { return kicks_; }
  uint32_t now_us() const { return now_us_; }
  uint32_t cycles() const { return rv32virt::instret(); }
  qr::SensorSample read_sensors() const { return sample_; }
  void set_engines(qr::EngineCommand engines) {
    if constexpr (Radio) {
      for (int i = 0; i < 4; ++i)
        dshot[i] = escs_[i].next_frame(engines.value[i], drivers::DshotLine::bidirectional, false);
    }
  }
  bool serial_read(uint8_t& byte) { return rx.pop(byte); }
  bool radio_read(uint8_t& byte) requires Radio { return radio.pop(byte); }
  bool serial_write(uint8_t) { return true; }
  void set_leds(uint8_t) {}
  qr::LogArea log_area() { return {}; }

  template <class M>
  void send(const M& message) {
    const wire::FrameBytes f = wire::encode(message);
    rx.push(f.bytes, f.size);
  }
  qr::ControlInput sticks() { return flight_.next().sticks; }

  wire::ByteRing<256> rx;
  wire::ByteRing<128> radio;
  volatile uint16_t dshot[4] = {0, 0, 0, 0};  // the frames the timer would send

 private:
  drivers::DshotCommandSequencer escs_[4];
  qr::chain::synthetic::Flight<qr::kControlHz> flight_;
  qr::SensorSample sample_;
  uint32_t kicks_ = 0;
  uint32_t now_us_ = 0;
};

// The devboard's log area, for the mode that logs (one rig at a time uses it).
uint8_t g_bench_log[256 * 1024];

// `Logging`: the firmware has the devboard's log area and logs both logs at every tick
// (log_divider 1) from arming on: what the packing costs a tick (qr/core/log_pack/).
template <class Chain, bool Radio = false, bool Logging = false>
struct Rig {
  BenchBoard<Radio> board;
  qr::Flight<Chain> flight{Logging ? qr::LogArea{g_bench_log, sizeof g_bench_log} : qr::LogArea{}};
  qr::Scheduler<BenchBoard<Radio>, qr::Flight<Chain>> scheduler{board, flight};
  uint8_t seq = 0;
  uint32_t tick = 0;
  wire::Control sticks;
  drivers::CrsfChannels radio;  // the transmitter's channels (AETR, arm 5, mode 6)
  uint32_t radio_phase = 0;

  // One period: the pilot's frames for it (and the radio's RC frames at 150 Hz), then the
  // firmware's tick.
  void step() {
    if (tick++ % 20 == 0) board.send(sticks);
    if constexpr (Radio) {
      radio_phase += 150;
      if (radio_phase >= qr::kControlHz) {
        radio_phase -= qr::kControlHz;
        const drivers::CrsfFrameBytes f = drivers::encode_rc_channels(radio);
        board.radio.push(f.bytes, f.size);
      }
    }
    scheduler.tick();
  }
  void radio_sticks(const qr::ControlInput& c) {
    radio.value[0] = drivers::rc_channel_of_stick(c.roll);
    radio.value[1] = drivers::rc_channel_of_stick(c.pitch);
    radio.value[2] = drivers::rc_channel_of_lift(c.lift);
    radio.value[3] = drivers::rc_channel_of_stick(c.yaw);
  }
  // The radio arms full control: pilot parameter to the radio, the mode switch high, the arm
  // switch seen off and moved to on with the sticks neutral.
  bool arm_by_radio() {
    board.send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::pilot), 1});
    radio_sticks(qr::ControlInput{});
    radio.value[4] = drivers::kCrsfChannelMin;
    radio.value[5] = drivers::kCrsfChannelMax;
    for (int i = 0; i < 30; ++i) step();
    radio.value[4] = drivers::kCrsfChannelMax;
    for (int i = 0; i < 30; ++i) step();
    return flight.mode() == Mode::full_control && flight.pilot() == qr::Pilot::radio;
  }
  bool request(Mode mode) {
    board.send(wire::ModeChange{++seq, mode});
    for (int i = 0; i < 5; ++i) step();
    return flight.mode() == mode;
  }
  // Arms `mode` the legal way, from safe with neutral sticks; false if the firmware refused.
  // `landing`: a panic out of full control, calibrated and flying, which lands (the vertical
  // loops and the attitude loops run; docs/safety.md rule 6).
  bool arm(Mode mode, bool landing) {
    board.send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::telemetry_rate_hz), 100});
    // Observable streams as a plot asks for them (four observables at 200 Hz, the battery at 2 Hz)
    // and the table being sent, in the modes on the ground, so the stream row's cost is measured
    // under load; stopped for yaw and full control, whose tick figures (the summary) stay those of
    // the flight without a plot. One request a control period, as a console's resend queue sends them.
    constexpr uint8_t kNone = wire::kNoObservable;
    const bool plotting = mode != Mode::yaw_control && mode != Mode::full_control;
    step();
    if (plotting) board.send(wire::ObservableGet{++seq, wire::kAllObservables});
    step();
    board.send(plotting ? wire::StreamRequest{++seq, 0, static_cast<uint16_t>(qr::kControlHz / 200), {0, 1, 6, 10}}
                        : wire::StreamRequest{++seq, 0, 0, {kNone, kNone, kNone, kNone}});
    step();
    board.send(plotting
                   ? wire::StreamRequest{++seq, 1, static_cast<uint16_t>(qr::kControlHz / 2), {26, kNone, kNone, kNone}}
                   : wire::StreamRequest{++seq, 1, 0, {kNone, kNone, kNone, kNone}});
    step();
    if (mode == Mode::yaw_control || mode == Mode::full_control || landing) {
      if (!request(Mode::calibration)) return false;
      for (uint32_t i = 0; i < kArmingTicksMax && flight.mode() != Mode::safe; ++i) step();
    }
    if (mode == Mode::safe) return true;
    if (Radio) return arm_by_radio();
    if (mode == Mode::panic && landing) {
      return request(Mode::full_control) && (fly(300), request(Mode::panic)) && flight.safety().landing();
    }
    if (mode == Mode::panic) return request(Mode::manual) && (fly(200), request(Mode::panic));
    if (!request(mode)) return false;
    if constexpr (Logging) {
      board.send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::log_divider), 1});
      step();
      board.send(wire::LogStart{++seq, wire::kLogSensor | wire::kLogTelemetry});
      fly(10);
      return flight.log().logging();
    }
    return true;
  }
  void fly(uint32_t ticks) {
    for (uint32_t i = 0; i < ticks; ++i) {
      const qr::ControlInput c = board.sticks();
      sticks = wire::Control{c.lift, c.roll, c.pitch, c.yaw};
      if constexpr (Radio) radio_sticks(c);
      step();
    }
  }
};

// One figure of a JSON line after its first: ,"key":value.
void put_field(const char* key, uint32_t value) {
  rv32virt::puts(",\"");
  rv32virt::puts(key);
  rv32virt::puts("\":");
  rv32virt::put_u32(value);
}

void print_task(const char* name, const qr::CycleStats& s, uint32_t budget, uint32_t overruns) {
  rv32virt::puts("\"");
  rv32virt::puts(name);
  rv32virt::puts("\":{\"runs\":");
  rv32virt::put_u32(s.count);
  put_field("mean", s.mean());
  put_field("max", s.max);
  put_field("budget", budget);
  put_field("overruns", overruns);
  rv32virt::puts("}");
}

struct ModeFigures {
  uint32_t tick_mean = 0;
  uint32_t overhead_mean = 0;  // tick mean minus what the tasks it ran cost, per tick
  uint32_t ticks = 0;
  uint32_t row_runs = 0;  // runs of all rows together
};

// Runs one mode and prints its line (per task: runs, mean, max, budget, overruns; and the
// scheduler's own cost per tick); the figures are zero if the mode could not be armed.
template <class Chain, bool Radio, bool Logging>
ModeFigures bench_mode(Rig<Chain, Radio, Logging>& rig, Mode mode, const char* suffix, bool landing) {
  rv32virt::puts("{\"mode\":\"");
  rv32virt::puts(wire::mode_key(mode));
  rv32virt::puts(suffix);
  rv32virt::puts("\"");
  if (!rig.arm(mode, landing)) {
    rv32virt::puts(",\"error\":\"the firmware refused the mode\"}\n");
    return {};
  }
  rig.scheduler.reset_stats();
  uint32_t ticks = 0;
  const bool lifts = mode != Mode::safe && mode != Mode::calibration;
  for (; ticks < kMeasuredTicks && rig.flight.mode() == mode; ++ticks) {
    if (lifts) {
      rig.fly(1);
    } else {
      rig.step();
    }
  }
  const auto& stats = rig.scheduler.stats();
  uint64_t task_sum = 0;
  ModeFigures figures;
  for (uint8_t id = 0; id < qr::kFlightTaskCount; ++id) {
    task_sum += stats.task[id].sum();
    figures.row_runs += stats.task[id].count;
  }
  figures.ticks = stats.ticks;
  figures.tick_mean = stats.tick.mean();
  figures.overhead_mean = stats.ticks == 0 ? 0 : static_cast<uint32_t>((stats.tick.sum() - task_sum) / stats.ticks);
  put_field("ticks", ticks);
  put_field("tick_instr_mean", figures.tick_mean);
  put_field("tick_instr_max", stats.tick.max);
  put_field("scheduler_overhead_instr_mean", figures.overhead_mean);
  rv32virt::puts(",\"tasks\":{");
  bool first = true;
  for (uint8_t id = 0; id < qr::kFlightTaskCount; ++id) {
    if (stats.task[id].count == 0) continue;
    if (!first) rv32virt::putc(',');
    first = false;
    const auto& row = qr::Flight<Chain>::kTasks[id];
    print_task(row.name, stats.task[id], row.budget, stats.task[id].overruns);
  }
  rv32virt::puts("}}\n");
  return figures;
}

template <Mode M, class Chain, bool Landing = false, bool Radio = false, bool Logging = false>
ModeFigures measure(const char* suffix) {
  static Rig<Chain, Radio, Logging> rig;  // one fresh firmware per mode, outside the 8 KiB stack
  return bench_mode(rig, M, suffix, Landing);
}

// What the scheduler costs by itself, over a context that does nothing: a tick with no row (the
// scheduler's own steps around the rows) and what each timed row adds besides its own run (the
// running index, two counter reads, the call, and count, sum, last and the range check of its
// statistics). Two sets: none of the rows, and all ten.
struct EmptyRows {
  static constexpr uint8_t kTaskCount = 10;
  static constexpr uint8_t kSetCount = 2;
  static constexpr uint8_t kAll[kTaskCount] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  static constexpr qr::Task<EmptyRows> task(uint8_t) {
    return {"empty", [](EmptyRows&) {}, 1, 0, 100};
  }
  static constexpr qr::TaskSet task_set(uint8_t set) { return {kAll, static_cast<uint8_t>(set == 0 ? 0 : kTaskCount)}; }
  uint8_t current_set() const { return set; }
  void begin_tick(uint32_t, const qr::SensorSample&) {}
  uint32_t rx_space() const { return 0; }
  void receive(uint8_t) {}
  bool tx_peek(uint8_t&) const { return false; }
  void tx_pop() {}
  qr::EngineCommand engines() const { return {}; }
  uint8_t leds() const { return 0; }
  bool running() const { return true; }
  void account(const qr::TickReport&, const qr::SchedulerStats<kTaskCount>&) {}
  uint8_t set = 0;
};

struct SchedulerFloor {
  uint32_t bare_tick = 0;  // a tick that runs no row
  uint32_t per_row = 0;    // what a timed row adds beyond its own run
};

SchedulerFloor bench_scheduler_floor() {
  static BenchBoard<false> board;
  static EmptyRows rows;
  static qr::Scheduler<BenchBoard<false>, EmptyRows> scheduler{board, rows};
  uint32_t tick_mean[2] = {0, 0};
  uint32_t rows_mean = 0;  // the rows' own runs, per tick
  for (uint8_t set = 0; set < 2; ++set) {
    rows.set = set;
    scheduler.tick();  // the set takes effect from the next tick
    scheduler.reset_stats();
    for (uint32_t i = 0; i < kMeasuredTicks; ++i) scheduler.tick();
    tick_mean[set] = scheduler.stats().tick.mean();
    if (set == 1) {
      for (uint8_t id = 0; id < EmptyRows::kTaskCount; ++id) rows_mean += scheduler.stats().task[id].mean();
    }
  }
  SchedulerFloor f;
  f.bare_tick = tick_mean[0];
  f.per_row = (tick_mean[1] - tick_mean[0] - rows_mean) / EmptyRows::kTaskCount;
  return f;
}

// The drivers' own cost, each piece timed alone (the cycle counter's own reads subtracted): four
// DShot frames from the engine values, and one CRSF RC frame through the parser (its 26 bytes as
// the board's receiver line delivered them), the six channels the map names decoded and mapped to
// sticks and switches, as the flight does. The inputs change every run, as they do in flight.
struct DriverFigures {
  uint32_t dshot4_mean = 0;
  uint32_t crsf_rc_mean = 0;
};

// Keeps a result the compiler would otherwise find unused and drop with the work that made it.
inline void keep(uint32_t value) { asm volatile("" : : "r"(value)); }

DriverFigures bench_drivers() {
  constexpr uint32_t kRuns = 500;
  static drivers::DshotCommandSequencer escs[4];
  static drivers::CrsfParser parser;
  const drivers::RcChannelMap map;
  drivers::CrsfChannels channels;
  for (uint16_t& v : channels.value) v = drivers::kCrsfChannelMid;
  const uint32_t t0 = rv32virt::instret();
  const uint32_t overhead = rv32virt::instret() - t0;
  uint32_t dshot_sum = 0, crsf_sum = 0, frames = 0;
  for (uint32_t run = 0; run < kRuns; ++run) {
    const uint16_t engine[4] = {static_cast<uint16_t>(300 + run % 400), static_cast<uint16_t>(310 + run % 390),
                                static_cast<uint16_t>(290 + run % 410), static_cast<uint16_t>(305 + run % 395)};
    for (uint32_t ch = 0; ch < 4; ++ch) channels.value[ch] = static_cast<uint16_t>(600 + (run * 7 + ch * 131) % 800);
    const drivers::CrsfFrameBytes f = drivers::encode_rc_channels(channels);

    const uint32_t a = rv32virt::instret();
    for (int i = 0; i < 4; ++i) keep(escs[i].next_frame(engine[i], drivers::DshotLine::bidirectional, false));
    const uint32_t b = rv32virt::instret();
    parser.push(f.bytes, f.size, [&](const drivers::CrsfFrame& frame) {
      drivers::RcSticks sticks;
      if (drivers::rc_sticks(frame, map, sticks)) {
        keep(sticks.lift);
        ++frames;
      }
    });
    const uint32_t c = rv32virt::instret();
    dshot_sum += b - a - overhead;
    crsf_sum += c - b - overhead;
  }
  DriverFigures d;
  if (frames != kRuns) return d;  // every frame must have been read
  d.dshot4_mean = dshot_sum / kRuns;
  d.crsf_rc_mean = crsf_sum / kRuns;
  return d;
}

}  // namespace

int main() {
  measure<Mode::safe, qr::FixedChain>("");
  measure<Mode::panic, qr::FixedChain>("");
  measure<Mode::panic, qr::FixedChain, true>("-landing");
  measure<Mode::manual, qr::FixedChain>("");
  measure<Mode::calibration, qr::FixedChain>("");
  measure<Mode::yaw_control, qr::FixedChain>("");
  const ModeFigures full = measure<Mode::full_control, qr::FixedChain>("");
  const ModeFigures full_float = measure<Mode::full_control, FloatChain>("-float");
  const ModeFigures full_radio = measure<Mode::full_control, qr::FixedChain, false, true>("-radio-dshot");
  const ModeFigures full_logging = measure<Mode::full_control, qr::FixedChain, false, false, true>("-log-1khz");
  const DriverFigures drivers_cost = bench_drivers();
  const SchedulerFloor floor = bench_scheduler_floor();
  rv32virt::puts(
      "{\"scheduler\":\"the scheduler alone, on rows that do nothing: a tick with no row, and what each timed row "
      "adds beyond its own run\",\"bare_tick_instr_mean\":");
  rv32virt::put_u32(floor.bare_tick);
  put_field("row_instr_mean", floor.per_row);
  // What timing every run of full control's rows costs a tick at that price.
  put_field("full_row_timing_instr_mean", full.ticks == 0 ? 0 : floor.per_row * full.row_runs / full.ticks);
  rv32virt::puts("}\n");
  rv32virt::puts(
      "{\"drivers\":\"four DShot frames and one CRSF RC frame (parse, channels, sticks); target: together <= 400 "
      "instructions per tick mean\",\"dshot4_instr_mean\":");
  rv32virt::put_u32(drivers_cost.dshot4_mean);
  put_field("crsf_rc_instr_mean", drivers_cost.crsf_rc_mean);
  put_field("together_instr_mean", drivers_cost.dshot4_mean + drivers_cost.crsf_rc_mean);
  put_field("full_radio_dshot_tick_instr_mean", full_radio.tick_mean);
  put_field("full_tick_instr_mean", full.tick_mean);
  rv32virt::puts("}\n");
  const sensor_bench::Figures sensors = sensor_bench::measure(kMeasuredTicks);
  rv32virt::puts(
      "{\"sensor_stage\":\"the MPU-6050 and MS5611 drivers stepped a tick over a bus whose chips answer at once "
      "(qr/core/sensor_stage.hpp), streaming; bus time at 400 kHz\",\"instr_mean\":");
  rv32virt::put_u32(sensors.instr_mean);
  put_field("instr_max", sensors.instr_max);
  put_field("bus_us_per_tick_mean", sensors.bus_us_mean);
  put_field("bus_us_per_tick_max", sensors.bus_us_max);
  put_field("imu_samples", sensors.imu_samples);
  put_field("baro_readings", sensors.baro_readings);
  put_field("faults", sensors.faults);
  put_field("ticks", kMeasuredTicks);
  rv32virt::puts("}\n");
  rv32virt::puts(
      "{\"summary\":\"full-control tick with link, telemetry at 100 Hz and logger; targets: mean <= 2400, scheduler "
      "overhead <= 150, max <= 8000 instructions, float_over_fixed >= 10\",\"full_tick_instr_mean\":");
  rv32virt::put_u32(full.tick_mean);
  put_field("scheduler_overhead_instr_mean", full.overhead_mean);
  put_field("full_float_tick_instr_mean", full_float.tick_mean);
  rv32virt::puts(",\"float_over_fixed\":");
  rv32virt::put_ratio(full_float.tick_mean, full.tick_mean == 0 ? 1 : full.tick_mean);
  rv32virt::puts("}\n");
  return full.tick_mean == 0 || full_float.tick_mean == 0 || full_radio.tick_mean == 0 || full_logging.tick_mean == 0 ||
                 drivers_cost.dshot4_mean == 0 || sensors.imu_samples != kMeasuredTicks || sensors.faults != 0
             ? 1
             : 0;
}
