// Test mode, one tick at a time: recorded samples and sticks through the flight's own tick
// (the task table and mode table of qr/core/flight_tasks.hpp, run by the flight's scheduler), and
// the columns it reports. Shared by the host replay (qr/host/replay.cpp) and the devboard's
// (qr/boards/rv32virt/replay_main.cpp), so both write the same CSV, bit for bit.
//
// The replay is calibration until it is done, then full control: the chain's tasks of those
// modes' sets, at their rates and phases, with the modes' entry actions. The link, safety,
// telemetry and logger rows have nothing to do here: the recording is the pilot.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/mode.hpp>
#include <qr/core/board.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/flight_tasks.hpp>
#include <qr/core/flight_types.hpp>
#include <qr/core/scheduler.hpp>

namespace qr {

// A cycle counter for the replay's task statistics: none on the host (`NoCycles`); the devboard
// passes one that reads minstret.
struct NoCycles {
  static uint32_t now() { return 0; }
};

// Test mode as a scheduler context (SchedulerContext, scheduler.hpp): the rows' side of the
// flight's task table (flight_tasks.hpp) over the chain, and the scheduler's side, which has no
// line, no engines and no LEDs.
template <class Chain>
class ReplayContext {
 public:
  using ChainType = Chain;
  static constexpr uint8_t kTaskCount = kFlightTaskCount;
  static const Task<ReplayContext> (&kTasks)[kFlightTaskCount];

  explicit ReplayContext(Chain& chain) : chain_(chain) { enter(wire::Mode::calibration); }

  // The recorded sticks for the next tick (the sample comes through the scheduler, begin_tick).
  void take_sticks(const ControlInput& sticks) { sticks_ = sticks; }
  wire::Mode mode() const { return mode_; }

  // ---- the rows' side (flight_tasks.hpp) ----
  Chain& chain() { return chain_; }
  void run_link() { chain_.set_pilot(sticks_); }
  void run_filter() { chain_.filter(sample_); }
  void run_calibration() {
    if (chain_.calibrate()) enter(wire::Mode::full_control);
  }
  void run_mixer() { chain_.mix(); }
  void run_manual_mixer() { chain_.mix(chain::kOpenLoop); }
  void run_safety() {}
  void enter_panic() {}  // test mode never panics
  void run_telemetry() {}
  void run_logger() {}
  void run_stream() {}
  uint16_t telemetry_divider() const { return 1; }
  uint16_t log_divider() const { return 1; }

  // ---- the scheduler's side ----
  static constexpr uint8_t kSetCount = kModeCount;  // the flight's sets, one per mode
  static constexpr Task<ReplayContext> task(uint8_t id) { return flight_tasks<ReplayContext>()[id]; }
  static constexpr TaskSet task_set(uint8_t set) { return flight_modes<ReplayContext>()[set].tasks; }
  uint8_t current_set() const { return index(mode_); }
  void begin_tick(uint32_t, const SensorSample& sample) { sample_ = sample; }
  uint32_t rx_space() const { return 0; }
  void receive(uint8_t) {}
  bool tx_peek(uint8_t&) const { return false; }
  void tx_pop() {}
  EngineCommand engines() const { return {}; }
  uint8_t leds() const { return 0; }
  bool running() const { return true; }
  void account(const TickReport&, const SchedulerStats<kTaskCount>&) {}

 private:
  // Test mode's door: the recording's modes follow each other (calibration, then full control).
  void enter(wire::Mode m) {
    const FlightMode<ReplayContext>& row = flight_modes<ReplayContext>()[index(m)];
    const wire::Mode from = mode_;
    mode_ = m;
    chain_.fly(row.sources);
    if (row.enter != nullptr) row.enter(*this, from);
  }

  Chain& chain_;
  SensorSample sample_;
  ControlInput sticks_;
  wire::Mode mode_ = wire::Mode::calibration;
};

template <class Chain>
const Task<ReplayContext<Chain>> (&ReplayContext<Chain>::kTasks)[kFlightTaskCount] =
    kFlightTaskTable<ReplayContext<Chain>>;

// A recording, one tick at a time, through the flight's scheduler over test mode's context.
template <class Chain, class Cycles = NoCycles>
class ChainReplay {
 public:
  using Context = ReplayContext<Chain>;

  // `first_time_us`: the QR clock of the first recorded tick. The flight's tick t runs at
  // (t + 1) periods (its first kick comes one period after start), so the recording's time says
  // which tick of the flight it starts at, and the divided rows fall on the ticks they fell on
  // in flight.
  static constexpr uint32_t kPeriodUs = 1000000u / Chain::kSampleHz;  // the recording's rate

  explicit ChainReplay(Chain& chain, uint32_t first_time_us = kPeriodUs)
      : context_(chain), scheduler_{board_, context_, SchedulerLimits{}, first_tick(first_time_us)} {}

  // One recorded tick; returns the mode the tick ran in.
  wire::Mode tick(const SensorSample& sample, const ControlInput& sticks) {
    board_.sample = sample;
    context_.take_sticks(sticks);
    const wire::Mode ran_in = context_.mode();
    scheduler_.tick();
    return ran_in;
  }
  const SchedulerStats<Context::kTaskCount>& stats() const { return scheduler_.stats(); }

 private:
  // Time is the recording's: one tick a kick, never late.
  struct ReplayBoard {
    SensorSample sample;
    uint32_t kick = 0;
    uint32_t wait_kick(uint32_t seen) { return kick = seen + 1; }
    uint32_t kicks() const { return kick; }
    uint32_t now_us() const { return kick * kPeriodUs; }
    uint32_t cycles() const { return Cycles::now(); }
    SensorSample read_sensors() const { return sample; }
    void set_engines(EngineCommand) {}
    bool serial_read(uint8_t&) { return false; }
    bool serial_write(uint8_t) { return true; }
    void set_leds(uint8_t) {}
    LogArea log_area() { return {}; }
  };

  static uint32_t first_tick(uint32_t time_us) { return time_us < kPeriodUs ? 0 : time_us / kPeriodUs - 1; }

  Context context_;
  ReplayBoard board_;
  Scheduler<ReplayBoard, Context> scheduler_;  // last: it reads the rows at construction
};

template <class Chain>
struct ReplayColumn {
  const char* name;
  int32_t (*value)(const Chain&);
};

// The output columns after time_us and mode, in the order the host/devboard checksum folds them
// (tests/chain/chain_checksum.hpp), so a replay's output can be checked against it.
template <class Chain>
inline constexpr ReplayColumn<Chain> kReplayColumns[] = {
    {"roll_e4", [](const Chain& c) -> int32_t { return c.roll_e4(); }},
    {"pitch_e4", [](const Chain& c) -> int32_t { return c.pitch_e4(); }},
    {"yaw_e4", [](const Chain& c) -> int32_t { return c.yaw_e4(); }},
    {"p_e3", [](const Chain& c) -> int32_t { return c.p_e3(); }},
    {"q_e3", [](const Chain& c) -> int32_t { return c.q_e3(); }},
    {"r_e3", [](const Chain& c) -> int32_t { return c.r_e3(); }},
    {"roll_sp_e4", [](const Chain& c) -> int32_t { return c.roll_setpoint_e4(); }},
    {"pitch_sp_e4", [](const Chain& c) -> int32_t { return c.pitch_setpoint_e4(); }},
    {"yaw_rate_sp_e3", [](const Chain& c) -> int32_t { return c.yaw_rate_setpoint_e3(); }},
    {"p_sp_e3", [](const Chain& c) -> int32_t { return c.p_setpoint_e3(); }},
    {"q_sp_e3", [](const Chain& c) -> int32_t { return c.q_setpoint_e3(); }},
    {"tilt_mrad", [](const Chain& c) -> int32_t { return c.tilt_mrad(); }},
    {"roll_acc_e4", [](const Chain& c) -> int32_t { return c.roll_from_accel_e4(); }},
    {"pitch_acc_e4", [](const Chain& c) -> int32_t { return c.pitch_from_accel_e4(); }},
    {"p_bias_e6", [](const Chain& c) -> int32_t { return c.p_bias_e6(); }},
    {"q_bias_e6", [](const Chain& c) -> int32_t { return c.q_bias_e6(); }},
    {"gyro_f_x", [](const Chain& c) -> int32_t { return c.gyro_filtered(0); }},
    {"gyro_f_y", [](const Chain& c) -> int32_t { return c.gyro_filtered(1); }},
    {"gyro_f_z", [](const Chain& c) -> int32_t { return c.gyro_filtered(2); }},
    {"accel_f_x", [](const Chain& c) -> int32_t { return c.accel_filtered(0); }},
    {"accel_f_y", [](const Chain& c) -> int32_t { return c.accel_filtered(1); }},
    {"accel_f_z", [](const Chain& c) -> int32_t { return c.accel_filtered(2); }},
    {"moment_roll_e3", [](const Chain& c) -> int32_t { return c.moments_e3().roll; }},
    {"moment_pitch_e3", [](const Chain& c) -> int32_t { return c.moments_e3().pitch; }},
    {"moment_yaw_e3", [](const Chain& c) -> int32_t { return c.moments_e3().yaw; }},
    {"applied_roll_e3", [](const Chain& c) -> int32_t { return c.applied_moments_e3().roll; }},
    {"applied_pitch_e3", [](const Chain& c) -> int32_t { return c.applied_moments_e3().pitch; }},
    {"applied_yaw_e3", [](const Chain& c) -> int32_t { return c.applied_moments_e3().yaw; }},
    {"ae0", [](const Chain& c) -> int32_t { return c.engines().value[0]; }},
    {"ae1", [](const Chain& c) -> int32_t { return c.engines().value[1]; }},
    {"ae2", [](const Chain& c) -> int32_t { return c.engines().value[2]; }},
    {"ae3", [](const Chain& c) -> int32_t { return c.engines().value[3]; }},
    {"calibrated", [](const Chain& c) -> int32_t { return c.calibrated() ? 1 : 0; }},
    {"height_mm", [](const Chain& c) -> int32_t { return c.height_mm(); }},
    {"climb_mm_s", [](const Chain& c) -> int32_t { return c.climb_mm_s(); }},
    {"accel_bias_mm_s2", [](const Chain& c) -> int32_t { return c.accel_bias_mm_s2(); }},
    {"baro_height_mm", [](const Chain& c) -> int32_t { return c.baro_height_mm(); }},
};

}  // namespace qr
