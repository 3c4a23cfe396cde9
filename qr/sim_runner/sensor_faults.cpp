#include <qr/sim_runner/sensor_faults.hpp>

#include <cmath>
#include <cstdio>

namespace qrsim {
namespace {

// `imu selftest bad`: the gyroscope's x axis responds at half its trim, a change of -50 % where
// 14 % is allowed (a damaged drive of one axis).
void break_self_test(sim::Mpu6050Faults& mpu) { mpu.gyro_self_test_scale = {0.5, 1, 1}; }

}  // namespace

bool is_sensor_fault(Action action) {
  switch (action) {
    case Action::nack:
    case Action::sda_stuck:
    case Action::imu_identity:
    case Action::prom_bad:
    case Action::baro_slow:
    case Action::fifo_overflow:
    case Action::imu_self_test: return true;
    default: return false;
  }
}

std::string inject_sensor_fault(const Event& e, SimBoard& board, uint64_t now_us) {
  char note[200];
  if (!board.sensor_drivers()) {
    std::snprintf(note, sizeof note,
                  "at %g s: a sensor fault with the sensors off the bus (--sensors direct): no effect", e.at_s);
    return note;
  }
  const uint64_t until_us = std::isinf(e.duration_s) ? SimI2cBus::kForever
                                                     : now_us + static_cast<uint64_t>(std::llround(e.duration_s * 1e6));
  switch (e.action) {
    case Action::nack: board.i2c().nack_address(static_cast<uint8_t>(e.value), now_us, until_us); break;
    case Action::sda_stuck: board.i2c().stick_sda(now_us, until_us); break;
    case Action::fifo_overflow:
      // The driver reads the 14 data bytes in one burst and never enables the FIFO
      // (common/drivers/mpu6050.hpp): there is nothing to overflow, and the model says so.
      if (!board.mpu6050_chip().overflow_fifo()) {
        std::snprintf(note, sizeof note,
                      "at %g s: imu fifo overflow: the FIFO is not enabled (the driver reads the burst): nothing "
                      "overflowed",
                      e.at_s);
        return note;
      }
      break;
    default: break;  // the chips' own: apply_chip_faults, every tick
  }
  return {};
}

void apply_chip_faults(const ScenarioScript& script, double since, SimBoard& board) {
  sim::Mpu6050Faults mpu;
  sim::Ms5611Faults baro;
  bool any = false;
  for (const Event& e : script.events) {
    if (e.at_s > since + 1e-9) break;  // in time order
    switch (e.action) {
      case Action::imu_identity:
        mpu.who_am_i = static_cast<uint8_t>(e.value);
        any = true;
        break;
      case Action::prom_bad:
        baro.bad_prom_crc = true;
        any = true;
        break;
      case Action::imu_self_test:
        break_self_test(mpu);
        any = true;
        break;
      case Action::baro_slow:
        if (since < e.at_s + e.duration_s) baro.slow_conversion_s += e.value * 1e-3;
        any = true;
        break;
      default: break;
    }
  }
  if (!any) return;
  board.mpu6050_chip().set_faults(mpu);
  board.ms5611_chip().set_faults(baro);
}

void apply_power_up_faults(const ScenarioScript& script, SimBoard& board) {
  for (const Event& e : script.events) {
    if (e.action != Action::imu_self_test) continue;
    sim::Mpu6050Faults mpu;
    break_self_test(mpu);
    board.mpu6050_chip().set_faults(mpu);
  }
}

}  // namespace qrsim
