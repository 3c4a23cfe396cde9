#include <qr/boards/sim/sim_board.hpp>

#include <thread>

#include <common/payload_codec.hpp>

namespace qrsim {

qr::SensorSample to_sensor_sample(const sim::SensorReading& reading) {
  qr::SensorSample s;
  for (size_t i = 0; i < 3; ++i) {
    s.gyro[i] = reading.imu.gyro[i];
    s.accel[i] = reading.imu.accel[i];
  }
  s.battery_mv = reading.battery_mv;
  s.pressure_pa = reading.pressure_pa;  // MS5611 model, a new reading every 20 ms
  return s;
}

SimBoard::SimBoard(sim::World& world, size_t log_bytes) : world_(world), log_(log_bytes) {
  sample_ = to_sensor_sample(world_.sample());
}

// Simulated time, in real time too: a tick takes none of it, so the firmware never misses a
// deadline here (its cost on the target is the devboard's to measure). The host's lateness is
// the simulator's, counted in host_timing().
uint32_t SimBoard::kicks() const { return static_cast<uint32_t>(world_.now_us() / qr::kPeriodUs); }

uint32_t SimBoard::wait_kick(uint32_t seen) {
  uint32_t kick = seen + 1;
  if (real_time_) {
    // Sleep until the wall clock reaches the next kick. A host that wakes us late (a loaded
    // machine: the sleep ends a few ms after it should) does not cost the firmware the period:
    // the periods run back to back until the simulation has caught up with the wall clock. Only
    // a host too slow to catch up at all, kMaxLagUs behind, skips ahead.
    const uint64_t due = kick_time_us(seen) - sim_at_wall_start_us_;
    uint64_t wall = wall_us();
    const bool slept = wall < due;
    if (slept) {
      std::this_thread::sleep_for(std::chrono::microseconds(due - wall));
      wall = wall_us();
    }
    const uint64_t late = wall > due ? wall - due : 0;
    if (slept && late >= qr::kPeriodUs) ++host_.late_wakeups;
    if (!slept) ++host_.caught_up_periods;
    host_.max_late_us = std::max(host_.max_late_us, late);
    if (late > kMaxLagUs) {
      const auto behind = static_cast<uint32_t>(late / qr::kPeriodUs);
      host_.skipped_periods += behind;
      kick += behind;
    }
  }
  world_.advance_to(static_cast<uint64_t>(kick) * qr::kPeriodUs);
  sample_ = to_sensor_sample(world_.sample());
  return kick;
}

void SimBoard::use_sensor_drivers() {
  sensor_drivers_ = true;
  i2c_.attach(mpu6050_);
  i2c_.attach(ms5611_);
  world_.use_chips(mpu6050_, ms5611_);
}

bool SimBoard::serial_read(uint8_t& byte) { return to_qr_.receive(world_.now_us() * 1000, byte); }

uint32_t SimBoard::cycles() const {
  return static_cast<uint32_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
          .count());
}

void SimBoard::set_engines(qr::EngineCommand engines) {
  engines_ = engines;
  if (!dshot_) {
    world_.plant().set_engines({engines.value[0], engines.value[1], engines.value[2], engines.value[3]});
    return;
  }
  // What a DShot board does with the engine values: a frame per ESC; what the ESCs make of them
  // drives the plant.
  std::array<uint16_t, 4> run{};
  for (size_t i = 0; i < 4; ++i) {
    uint16_t frame = sequencers_[i].next_frame(engines.value[i], drivers::DshotLine::bidirectional, false);
    ++dshot_frames_;
    if (corrupt_every_ != 0 && dshot_frames_ % corrupt_every_ == 0)
      frame ^= static_cast<uint16_t>(1u << (dshot_frames_ % 16));
    run[i] = escs_[i].receive(frame);
    // An ESC set to spin direction 2 turns its motor, and the rotor on it, the other way.
    if (escs_[i].reversed() != esc_reversed_[i]) {
      esc_reversed_[i] = escs_[i].reversed();
      world_.plant().set_output_reversed(static_cast<int>(i), esc_reversed_[i]);
    }
  }
  world_.plant().set_engines(run);
  answered_ = true;
}

bool SimBoard::radio_read(uint8_t& byte) {
  if (radio_.empty()) return false;
  byte = radio_.front();
  radio_.pop_front();
  return true;
}

bool SimBoard::esc_answers(qr::EscAnswers& answers) {
  if (!dshot_ || !answered_) return false;
  answered_ = false;
  const auto& speed = world_.plant().state().rotor_speed;
  for (size_t i = 0; i < 4; ++i) answers.raw[i] = SimEsc::answer(speed[i], pole_pairs_);
  answers.fresh = 0xF;
  return true;
}

bool SimBoard::esc_command(uint8_t command, uint8_t engines) {
  if (!dshot_) return false;
  bool all = true;
  for (size_t i = 0; i < 4; ++i) {
    if ((engines >> i & 1u) != 0) all = sequencers_[i].request(command, engines_.value[i]) && all;
  }
  return all;
}

bool SimBoard::pc_next_sent_at_us(uint64_t& us) const {
  uint64_t ns = 0;
  if (!to_pc_.next_sent_at(ns)) return false;
  us = ns / 1000;
  return true;
}

void SimBoard::follow_wall_clock() {
  real_time_ = true;
  wall_start_ = std::chrono::steady_clock::now();
  sim_at_wall_start_us_ = world_.now_us();
}

uint64_t SimBoard::wall_us() const {
  return static_cast<uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - wall_start_).count());
}

}  // namespace qrsim
