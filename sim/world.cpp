#include <sim/world.hpp>

#include <algorithm>
#include <cmath>
#include <variant>

namespace sim {
namespace {

// Stream numbers: one independent generator per source of randomness.
enum Stream : uint64_t { kImuStream = 1, kVibrationStream = 2, kBatteryStream = 3, kBarometerStream = 4 };

// A free-flight step is at most this share of the faster motor time constant: RK4's error on the
// lag per step is then about (h/τ)^5/120 = 8e-11 of the speed change, far below anything the
// sensors resolve (a 10 ms motor gets 250 µs steps, a 1 ms one the fine step).
constexpr double kMotorLagPerStep = 0.025;

uint32_t free_flight_step(const VehicleParams& v, const WorldConfig& config, uint32_t fine_us) {
  const double tau_s = std::min(v.motor_tau_up_s, v.motor_tau_down_s);
  uint32_t step = config.free_flight_step_us;
  while (step > fine_us && (step % fine_us != 0 || step * 1e-6 > kMotorLagPerStep * tau_s)) step -= fine_us;
  return step > fine_us ? step : fine_us;
}

}  // namespace

World::World(const VehicleParams& vehicle, const WorldConfig& config)
    : plant_(vehicle), vibration_(vehicle, Random(config.seed).stream(kVibrationStream)),
      imu_(vehicle, Random(config.seed).stream(kImuStream)),
      battery_sensor_(vehicle, Random(config.seed).stream(kBatteryStream)),
      barometer_(vehicle, Random(config.seed).stream(kBarometerStream)),
      step_us_(config.step_us == 0 ? 125 : config.step_us),
      free_flight_step_us_(free_flight_step(vehicle, config, step_us_)) {}

uint32_t World::next_step_us(uint64_t time_us) const {
  const uint32_t coarse = free_flight_step_us_;
  if (coarse == step_us_) return step_us_;
  // On the coarse grid only, so the kicks (multiples of it) still fall on step boundaries.
  if (now_us_ % coarse != 0 || now_us_ + coarse > time_us) return step_us_;
  // The barometer acts at the first fine step at or after its instant; a coarse step must end
  // exactly there or before it, so the reading is taken where the fine steps would take it.
  if (ms5611_ == nullptr && barometer_.next_event_us() <= now_us_ + coarse - step_us_) return step_us_;
  if (const std::optional<uint64_t> at = chip_pressure_instant_us(); at && *at <= now_us_ + coarse - step_us_) {
    return step_us_;
  }
  if (!plant_.clear_of_ground_for(static_cast<double>(coarse) * 1e-6)) return step_us_;
  return coarse;
}

void World::advance_to(uint64_t time_us) {
  while (now_us_ + step_us_ <= time_us) {
    const uint32_t step = next_step_us(time_us);
    plant_.step(static_cast<double>(step) * 1e-6);
    now_us_ += step;
    if (hand_) hold();
    ++steps_taken_;
    // The barometer converts over milliseconds on its own clock, not at the kicks.
    if (ms5611_ == nullptr) {
      barometer_.step(now_us_, altitude_m());
    } else {
      sense_pressure();
    }
  }
}

std::optional<uint64_t> World::chip_pressure_instant_us() const {
  if (ms5611_ == nullptr) return std::nullopt;
  const std::optional<double> at = ms5611_->next_sample_s();
  if (!at) return std::nullopt;
  return *at <= 0 ? 0 : static_cast<uint64_t>(std::ceil(*at * 1e6));
}

// The MS5611 model's conversion takes its pressure at the first step at or after its middle.
void World::sense_pressure() {
  const std::optional<uint64_t> at = chip_pressure_instant_us();
  if (!at || now_us_ < *at) return;
  const double t_s = static_cast<double>(now_us_) * 1e-6;
  ms5611_->sense(t_s, barometer_.sense_pa(now_us_, altitude_m(), ms5611_->noise_scale()),
                 barometer_.temperature_c(now_us_));
}

std::string World::hand_refused() const {
  for (const uint16_t command : plant_.engines()) {
    if (command != 0) return "the engines are running (safe first)";
  }
  if (!hand_) return "";
  return std::holds_alternative<HandTurn>(*hand_) ? "a turn is under way" : "a tilt is under way";
}

void World::take(const std::variant<HandTurn, HandTilt>& hand) {
  hand_ = hand;
  held_position_ = plant_.state().position;
  hold();
}

std::string World::start_hand_turn(const HandTurnSpec& spec) {
  std::string refused = hand_refused();
  if (refused.empty()) take(HandTurn(plant_.state().attitude, spec, now_us_));
  return refused;
}

std::string World::start_hand_tilt(const HandTiltSpec& spec) {
  std::string refused = hand_refused();
  if (refused.empty()) take(HandTilt(plant_.state().attitude, spec, now_us_));
  return refused;
}

// The rotors and the battery run on as the step made them; the pose is the hand's alone.
void World::hold() {
  PlantState s = plant_.state();
  s.position = held_position_;
  s.velocity = {};
  const bool done = std::visit(
      [&](const auto& hand) {
        s.attitude = hand.attitude(now_us_);
        s.rate = hand.rate(now_us_);
        return hand.done(now_us_);
      },
      *hand_);
  plant_.set_state(s);
  if (done) hand_.reset();
}

VibrationSample World::vibration() const {
  std::array<double, kRotorCount> phase{};
  for (size_t i = 0; i < kRotorCount; ++i) phase[i] = plant_.rotor_phase(static_cast<int>(i));
  return vibration_.at(plant_.state().rotor_speed, phase, imu_.low_pass_hz());
}

SensorReading World::sample() {
  SensorReading out;
  const Vec3 specific_force = hand_ ? held_specific_force(plant_.state().attitude, kGravity) : plant_.specific_force();
  // The IMU reads the body's motion through its mounting (the vehicle's wiring: right by default).
  const Wiring& wiring = plant_.vehicle().wiring;
  const Vec3 rate = imu_gyro_axes(wiring, plant_.state().rate);
  const Vec3 force = imu_accel_axes(wiring, specific_force);
  if (mpu_ != nullptr) {
    const ImuSense body = imu_.sense(rate, force, vibration());
    // Mounted flat, X forward: chip (x, y, z) = body (x, -y, -z).
    const ImuSense chip{{body.rate.x, -body.rate.y, -body.rate.z},
                        {body.specific_force.x, -body.specific_force.y, -body.specific_force.z}};
    mpu_->sample(static_cast<double>(now_us_) * 1e-6, chip, barometer_.temperature_c(now_us_));
  } else {
    out.imu = imu_.sample(rate, force, vibration());
    out.pressure_pa = barometer_.pressure_pa();
  }
  out.battery_mv = battery_sensor_.read_mv(plant_.battery_volts());
  return out;
}

}  // namespace sim
