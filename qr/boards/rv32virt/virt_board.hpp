// The flight computer's board on QEMU `virt`. Two ways to run, chosen at start by what QEMU has
// plugged in:
//   on its own: the CLINT timer interrupt is the kick, sensor samples come from a recording in
//     memory (or a vehicle resting level when there is none);
//   on the sensor link (a virtio console, docs/devboard.md): the simulator's sensors frame is
//     the kick, its time stamp the clock and its samples the sensors, and the board answers each
//     tick with its engines (answer()): lock-step with the simulated plant. When the simulator
//     says so (its frames' sensors_on_i2c) the gyro, accelerometer and barometer are its chip
//     models instead, on an I2C bus the link carries (LinkI2cBus), read by the firmware's drivers
//     (qr/core/sensor_stage.hpp) as on a board with the chips.
// Either way the ground link is the 16550 UART: received by interrupt into a ring, transmitted a
// bounded number of bytes per tick (on the link, at the line's pace, PacedTransmitter).
// Either way a watchdog on the timer interrupt cuts the engines when a tick stalls (fail_safe.hpp).
#pragma once

#include <stdint.h>

#include <common/sensor_link.hpp>
#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/boards/rv32virt/recording.hpp>
#include <qr/boards/rv32virt/sensor_link_port.hpp>
#include <qr/core/board.hpp>
#include <qr/core/cycle_stats.hpp>
#include <qr/core/observable_readers.hpp>
#include <qr/core/sensor_stage.hpp>

namespace rv32virt {

static_assert(sizeof(simlink::EngineFrame::sensor_counts) / sizeof(uint32_t) == qr::SensorCounts::kCounts,
              "the engines frame carries every count of the sensor stage");

class VirtBoard {
 public:
  // Starts the kick at `control_hz` (or the sensor link) and the UART receive interrupt.
  explicit VirtBoard(uint32_t control_hz);

  uint32_t wait_kick(uint32_t seen);
  uint32_t kicks() const;
  uint32_t now_us() const;
  uint32_t cycles() const { return instret(); }  // instructions retired: exact and repeatable under -icount
  qr::SensorSample read_sensors() const;
  qr::ControlInput recorded_sticks() const;
  bool recording_ended() const;
  // ---- qr::I2cBoard: the sensors' bus, on the link ----
  using I2cBus = LinkI2cBus;
  I2cBus& i2c();
  bool sensors_on_i2c() const { return sensors_on_i2c_; }
  uint16_t battery_mv() const { return sample_.battery_mv; }
  void set_engines(qr::EngineCommand engines) { engines_ = engines; }
  qr::EngineCommand engines() const { return engines_; }
  // The fail-safe's cut (fail_safe.hpp): zero to every engine, and to the plant on the link.
  void cut_engines();
  bool serial_read(uint8_t& byte);
  bool serial_write(uint8_t byte);
  void set_leds(uint8_t leds) { leds_ = leds; }
  qr::LogArea log_area();

  const Recording& recording() const { return recording_; }
  uint32_t rx_overruns() const;

  // ---- the sensor link ----
  bool on_sensor_link() const { return linked_; }
  // The core's speed in MHz when the simulator gave one (docs/devboard.md, "A core of a given
  // speed"), else 0: time stands still while a tick runs.
  uint32_t core_mhz() const { return core_mhz_; }
  // Where the scheduler keeps its statistics, reported to the simulator a row a tick.
  void attach_statistics(const qr::CycleStats* tasks, uint8_t task_count, const qr::CycleStats* tick) {
    task_stats_ = tasks;
    task_count_ = task_count;
    tick_stats_ = tick;
  }
  // After each tick: on the link, the engines frame for the tick's kick, with what the
  // simulator scores the flight on (the mode, estimate and set-points); else nothing.
  // Out of line and small: it runs after the tick, outside what the scheduler measures, and the
  // image has little room.
  template <class Flight, class Stage>
  [[gnu::noinline, gnu::optimize("Os")]] void answer(const Flight& flight, uint32_t deadline_misses,
                                                     const Stage& sensors) {
    if (!linked_) return;
    simlink::EngineFrame f;
    f.kick = kick_;
    for (int i = 0; i < 4; ++i) f.engines[i] = engines_.value[i];
    f.mode = static_cast<uint8_t>(flight.mode());
    f.flags = flight.telemetry_flags();
    f.ground_bytes = ground_sent_;
    f.deadline_misses = deadline_misses;
    using Id = wire::ObservableId;  // the estimate and set-points as a stream shows them
    f.angles_e4[f.roll_estimate] = qr::observe<Id::phi>(flight);
    f.angles_e4[f.pitch_estimate] = qr::observe<Id::theta>(flight);
    f.angles_e4[f.roll_setpoint] = qr::observe<Id::phi_sp>(flight);
    f.angles_e4[f.pitch_setpoint] = qr::observe<Id::theta_sp>(flight);
    f.yaw_rate_setpoint_e3 = qr::observe<Id::r_sp>(flight);
    if (sensors_on_i2c_) {
      const qr::SensorCounts c = sensors.counts();
      f.sensors_healthy = c.healthy;
      for (int i = 0; i < qr::SensorCounts::kCounts; ++i) f.sensor_counts[i] = c.value[i];
    }
    send_engines(f);
  }

 private:
  // Adds this tick's row of the statistics and sends the frame; with a core speed, a tick that
  // ran past its period answers with the engines the outputs still held.
  void send_engines(simlink::EngineFrame& frame);
  // With a core speed: the periods gone by since the kick, at core_mhz_ instructions a µs.
  uint32_t core_us_since_kick() const;
  // With a core speed, a sensors frame whose period the core missed: answered with the engines
  // on the outputs in that period, and no tick.
  void answer_missed(uint32_t kick);

  Recording recording_;
  uint32_t first_kick_ = 0;
  qr::EngineCommand engines_;
  uint8_t leds_ = 0;

  bool linked_ = false;
  uint32_t kick_ = 0;            // on the link: the kick of the sensors frame flown now
  uint32_t time_us_ = 0;         // its time stamp
  uint64_t time_ns_ = 0;         // the same, not wrapping, for the paced transmitter
  qr::SensorSample sample_;      // its samples
  bool sensors_on_i2c_ = false;  // its sensors_on_i2c: the chips on the link's I2C bus
  uint32_t ground_sent_ = 0;     // bytes written to the UART
  const qr::CycleStats* task_stats_ = nullptr;
  const qr::CycleStats* tick_stats_ = nullptr;
  uint8_t task_count_ = 0;

  // A core of a given speed (core_mhz_ != 0): the board's clock runs on from the kick's stamp by
  // the instructions retired since it, and an engine value reaches the outputs when its tick ends.
  uint32_t core_mhz_ = 0;
  uint32_t kick_instret_ = 0;  // minstret when the kick was taken
  qr::EngineCommand held_;     // on the outputs now
  qr::EngineCommand pending_;  // from a tick that ended in a later period: out from that period
  uint32_t pending_kick_ = 0;  // that period
  simlink::EngineFrame last_answer_;
};

}  // namespace rv32virt
