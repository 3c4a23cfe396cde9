#include <sim/world.hpp>

namespace sim {
namespace {

// Stream numbers: one independent generator per source of randomness.
enum Stream : uint64_t { kImuStream = 1, kVibrationStream = 2, kBatteryStream = 3, kBarometerStream = 4 };

}  // namespace

World::World(const VehicleParams& vehicle, const WorldConfig& config)
    : plant_(vehicle), vibration_(vehicle, Random(config.seed).stream(kVibrationStream)),
      imu_(vehicle, Random(config.seed).stream(kImuStream)),
      battery_sensor_(vehicle, Random(config.seed).stream(kBatteryStream)),
      barometer_(vehicle, Random(config.seed).stream(kBarometerStream)),
      step_us_(config.step_us == 0 ? 125 : config.step_us) {}

void World::advance_to(uint64_t time_us) {
  const double dt = static_cast<double>(step_us_) * 1e-6;
  while (now_us_ + step_us_ <= time_us) {
    plant_.step(dt);
    now_us_ += step_us_;
    // The barometer converts over milliseconds on its own clock, not at the kicks.
    barometer_.step(now_us_, altitude_m());
  }
}

VibrationSample World::vibration() const {
  std::array<double, kRotorCount> phase{};
  for (size_t i = 0; i < kRotorCount; ++i) phase[i] = plant_.rotor_phase(static_cast<int>(i));
  return vibration_.at(plant_.state().rotor_speed, phase, imu_.low_pass_hz());
}

SensorReading World::sample() {
  SensorReading out;
  out.imu = imu_.sample(plant_.state().rate, plant_.specific_force(), vibration());
  out.battery_mv = battery_sensor_.read_mv(plant_.battery_volts());
  out.pressure_pa = barometer_.pressure_pa();
  return out;
}

}  // namespace sim
