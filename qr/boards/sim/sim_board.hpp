// The board the host firmware flies in the simulator: qr::Board over a sim::World.
//
//   wait_kick   advances the physics to the next control period boundary and samples the
//               sensors there (the MPU's data-ready is the kick, as on the IN4073 board);
//   now_us      simulated time; it stands still while a tick runs, so a tick takes no
//               simulated time and no deadline is ever missed. In real time (serve mode) the
//               kicks follow the wall clock; a host that wakes the simulator late gets the
//               periods it missed run back to back (host_timing() counts them), not counted as
//               the firmware's misses (docs/simulator.md section 5, "Serve mode on a loaded host");
//   cycles      the host's nanosecond clock: what the tasks really cost on this machine (a
//               benchmark figure; nothing in the flight depends on it);
//   set_engines the motor commands of the plant;
//   serial      two SerialLines at 115200 baud: the QR's transmit buffer holds 32 bytes;
//   radio       a receiver's line (CRSF, qrsim --rc crsf): what the simulated radio sends arrives
//               at once (a 26-byte frame takes 0.6 ms at 420 000 baud);
//   engines     plain 0..1000 commands to the plant, or (qrsim --esc dshot) DShot frames to four
//               simulated ESCs (sim_esc.hpp) that drive the plant and answer with their eRPM, and
//               take special commands (the lost-model beacon) while stopped;
//   log_area    256 KiB of RAM, the devboard's (a test may give less: a log that fills sooner);
//   i2c         (use_sensor_drivers: qrsim --sensors drivers, its default) the MPU-6050 and the MS5611 as register-level chips
//               (sim/mpu6050_model.hpp, ms5611_model.hpp) on one I2C bus at 400 kHz
//               (sim_i2c_bus.hpp), read by the firmware's own drivers (qr/core/sensor_stage.hpp);
//               the world feeds the chips what the plant's sensors sense. Without it (--sensors
//               direct, serve mode, the soak) read_sensors() hands the core the plant's sample.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <chrono>
#include <deque>
#include <vector>

#include <common/drivers/dshot_commands.hpp>
#include <common/requests.hpp>
#include <qr/boards/sim/serial_line.hpp>
#include <qr/boards/sim/sim_esc.hpp>
#include <qr/boards/sim/sim_i2c_bus.hpp>
#include <qr/core/board.hpp>
#include <qr/core/control_rate.hpp>
#include <sim/world.hpp>

namespace qrsim {

// How the host kept real time in serve mode (the simulator's figures, not the firmware's).
struct HostTiming {
  uint64_t late_wakeups = 0;       // sleeps for a kick that ended a period or more after it
  uint64_t caught_up_periods = 0;  // periods run back to back, behind the wall clock
  uint64_t max_late_us = 0;        // the furthest behind the wall clock a period began
  uint64_t skipped_periods = 0;    // periods never simulated: the host fell kMaxLagUs behind
};

class SimBoard {
 public:
  // Behind the wall clock by more than this, serve mode gives up catching up and skips ahead.
  static constexpr uint64_t kMaxLagUs = 200000;
  static constexpr size_t kTransmitBuffer = 32;
  static constexpr size_t kLogBytes = 256 * 1024;

  explicit SimBoard(sim::World& world, size_t log_bytes = kLogBytes);

  // ---- qr::Board ----
  uint32_t wait_kick(uint32_t seen);
  uint32_t kicks() const;
  uint32_t now_us() const { return static_cast<uint32_t>(world_.now_us()); }
  uint32_t cycles() const;
  qr::SensorSample read_sensors() const { return sample_; }
  void set_engines(qr::EngineCommand engines);
  bool serial_read(uint8_t& byte);
  bool serial_write(uint8_t byte) { return to_pc_.send(byte, world_.now_us() * 1000); }
  void set_leds(uint8_t leds) { leds_ = leds; }
  qr::LogArea log_area() { return {log_.data(), log_.size()}; }
  // ---- qr::RadioBoard, qr::EscAnswerBoard, qr::EscCommandBoard ----
  bool radio_read(uint8_t& byte);
  bool esc_answers(qr::EscAnswers& answers);
  // A DShot special command for the engines of the mask, bit i engine i (with --esc dshot; false
  // without, or while one of them turns): each one's sequencer sends it in place of its next
  // throttle frames.
  bool esc_command(uint8_t command, uint8_t engines);

  // ---- qr::I2cBoard ----
  using I2cBus = SimI2cBus;
  I2cBus& i2c() { return i2c_; }
  bool sensors_on_i2c() const { return sensor_drivers_; }
  uint16_t battery_mv() const { return sample_.battery_mv; }

  // The sensors as chips on the I2C bus, read by the firmware's drivers (set before the first tick).
  void use_sensor_drivers();
  bool sensor_drivers() const { return sensor_drivers_; }
  const sim::Mpu6050Model& mpu6050() const { return mpu6050_; }
  const sim::Ms5611Model& ms5611() const { return ms5611_; }
  // The chips themselves, for the faults a scenario injects (set_faults, overflow_fifo).
  sim::Mpu6050Model& mpu6050_chip() { return mpu6050_; }
  sim::Ms5611Model& ms5611_chip() { return ms5611_; }

  // ---- the radio's end of the receiver line ----
  void radio_send(const uint8_t* bytes, size_t size) { radio_.insert(radio_.end(), bytes, bytes + size); }

  // The engines as DShot frames through simulated ESCs (set before the first tick). `pole_pairs`:
  // the simulated motors' (their answers' eRPM is the rotor speed times it). `corrupt_every`: a
  // frame with one bit flipped every that many frames (0: none), to show the ESCs keep the last
  // good value.
  void use_dshot(uint8_t pole_pairs, uint32_t corrupt_every = 0) {
    dshot_ = true;
    pole_pairs_ = pole_pairs;
    corrupt_every_ = corrupt_every;
  }
  bool dshot() const { return dshot_; }
  const std::array<SimEsc, 4>& escs() const { return escs_; }

  // ---- the PC's end of the line ----
  bool pc_send(uint8_t byte) { return to_qr_.send(byte, world_.now_us() * 1000); }
  bool pc_receive(uint8_t& byte) { return to_pc_.receive(world_.now_us() * 1000, byte); }
  // Bytes the QR sent that pc_receive() has not given yet (on the line or arrived).
  bool pc_bytes_pending() const { return !to_pc_.empty(); }
  // When the QR queued the byte pc_receive() gives next (a frame's start byte: its tick).
  bool pc_next_sent_at_us(uint64_t& us) const;
  // The byte pc_receive() gave last: when its stop bit reached the PC, when the QR queued it (ns).
  uint64_t pc_last_arrived_ns() const { return to_pc_.last_taken_arrived_ns(); }
  uint64_t pc_last_sent_ns() const { return to_pc_.last_taken_sent_ns(); }
  // When the byte pc_send() queued last reaches the QR (ns), and when the line towards it is idle.
  uint64_t to_qr_busy_until_ns() const { return to_qr_.busy_until_ns(); }

  // Real time: from now on the kick count follows the wall clock (serve mode).
  void follow_wall_clock();
  bool real_time() const { return real_time_; }
  const HostTiming& host_timing() const { return host_; }
  // Simulated µs of the next kick after `seen`.
  uint64_t kick_time_us(uint32_t seen) const { return (static_cast<uint64_t>(seen) + 1) * qr::kPeriodUs; }

  sim::World& world() { return world_; }
  const sim::World& world() const { return world_; }
  uint8_t leds() const { return leds_; }
  const qr::EngineCommand& engines() const { return engines_; }
  uint64_t bytes_to_qr_refused() const { return to_qr_.bytes_refused(); }

 private:
  uint64_t wall_us() const;

  sim::World& world_;
  // The chips powered with the board, at its first instant.
  sim::Mpu6050Model mpu6050_{sim::Mpu6050Model::kAddressAd0Low, static_cast<double>(world_.now_us()) * 1e-6};
  sim::Ms5611Model ms5611_{sim::Ms5611Model::kAddressCsbLow, sim::ms5611_example_prom(),
                           static_cast<double>(world_.now_us()) * 1e-6};
  SimI2cBus i2c_{world_};
  bool sensor_drivers_ = false;
  SerialLine to_qr_{1u << 20};  // the PC side's buffer: a USB serial adapter's, large
  SerialLine to_pc_{kTransmitBuffer};
  qr::SensorSample sample_{};
  qr::EngineCommand engines_{};
  uint8_t leds_ = 0;
  std::vector<uint8_t> log_;
  std::deque<uint8_t> radio_;
  bool dshot_ = false;
  uint8_t pole_pairs_ = 7;
  uint32_t corrupt_every_ = 0;
  uint64_t dshot_frames_ = 0;
  bool answered_ = false;
  drivers::DshotCommandSequencer sequencers_[4];
  std::array<SimEsc, 4> escs_{};
  std::array<bool, 4> esc_reversed_{};  // what the plant was last told of each ESC's direction
  bool real_time_ = false;
  HostTiming host_;
  std::chrono::steady_clock::time_point wall_start_{};
  uint64_t sim_at_wall_start_us_ = 0;
};

static_assert(qr::Board<SimBoard>);
static_assert(qr::I2cBoard<SimBoard>);

// A world sample as the firmware's SensorSample.
qr::SensorSample to_sensor_sample(const sim::SensorReading& reading);

}  // namespace qrsim
