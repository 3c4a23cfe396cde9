// What a scenario flies: the simulated world and its board, and a firmware that takes one control
// period at a time. Either the host build of the firmware in this process (HostQr, over SimQr) or
// the cross-compiled qr.elf on the emulated devboard in lock-step over the sensor link
// (DevboardQr, devboard_qr.hpp). The scorer sees the same things of both.
#pragma once

#include <stdint.h>

#include <memory>
#include <optional>
#include <string>

#include <common/parameter_table.hpp>
#include <qr/boards/sim/sim_board.hpp>
#include <qr/boards/sim/sim_qr.hpp>
#include <qr/core/flight_types.hpp>
#include <qr/core/observable_readers.hpp>
#include <qr/core/sensor_stage.hpp>
#include <sim/world.hpp>

namespace qrsim {

// What the figures read of the firmware after each tick, in the wire's integer units.
struct FirmwareView {
  uint8_t mode = 0;
  bool flying = false;                // the landed detector's verdict
  int16_t roll_e4 = 0, pitch_e4 = 0;  // estimate
  int16_t roll_setpoint_e4 = 0, pitch_setpoint_e4 = 0, yaw_rate_setpoint_e3 = 0;
  // Only the host build shows these (the devboard's frames leave them out, common/sensor_link.hpp).
  bool has_rates = false;
  int16_t yaw_e4 = 0, p_e3 = 0, q_e3 = 0, r_e3 = 0;
  int16_t moment_e1[3] = {0, 0, 0};       // roll, pitch, yaw: asked of the mixer (tenths of thrust units)
  int32_t height_mm = 0, climb_mm_s = 0;  // the height estimate
  qr::ControlInput controls;              // the sticks the tick flew with
  uint32_t deadline_misses = 0;
};

class FlyingQr {
 public:
  virtual ~FlyingQr() = default;

  virtual sim::World& world() = 0;
  virtual SimBoard& board() = 0;
  // One control period: the physics runs to the kick, then the firmware's tick. False once the
  // firmware has stopped (or the devboard failed: error()).
  virtual bool tick() = 0;
  virtual FirmwareView view() const = 0;
  // The firmware's parameter table as it is now.
  virtual const wire::ParameterValues& parameters() const = 0;
  virtual const char* firmware() const = 0;  // "host" or "rv32"
  virtual std::string error() const { return {}; }
  // The sample the firmware's last tick ran on (the board's, or the drivers' with --sensors drivers).
  virtual qr::SensorSample sensor_sample() { return board().read_sensors(); }
  // The host firmware's sensor stage (its drivers and their figures); null for the devboard's.
  virtual const qr::SensorStage<SimBoard>* sensor_stage() const { return nullptr; }
  // The sensor drivers' counts and verdicts, where the drivers run (none with the sensors direct).
  virtual std::optional<qr::SensorCounts> sensor_counts() const = 0;
};

// The host build of the firmware, in this process.
class HostQr final : public FlyingQr {
 public:
  HostQr(const sim::VehicleParams& vehicle, const sim::WorldConfig& config) : qr_(make_qr(vehicle, config)) {}

  sim::World& world() override { return qr_->world; }
  SimBoard& board() override { return qr_->board; }
  bool tick() override { return qr_->tick(); }
  FirmwareView view() const override {
    const auto& flight = qr_->firmware;
    const auto& chain = flight.chain();
    using Id = wire::ObservableId;  // the estimate, rates and set-points as a stream shows them
    FirmwareView v;
    v.mode = static_cast<uint8_t>(flight.mode());
    v.roll_e4 = qr::observe<Id::phi>(flight), v.pitch_e4 = qr::observe<Id::theta>(flight);
    v.roll_setpoint_e4 = qr::observe<Id::phi_sp>(flight), v.pitch_setpoint_e4 = qr::observe<Id::theta_sp>(flight);
    v.yaw_rate_setpoint_e3 = qr::observe<Id::r_sp>(flight);
    v.has_rates = true;
    v.yaw_e4 = qr::observe<Id::psi>(flight), v.p_e3 = qr::observe<Id::p>(flight);
    v.q_e3 = qr::observe<Id::q>(flight), v.r_e3 = qr::observe<Id::r>(flight);
    v.moment_e1[0] = qr::observe<Id::roll_moment>(flight), v.moment_e1[1] = qr::observe<Id::pitch_moment>(flight);
    v.moment_e1[2] = qr::observe<Id::yaw_moment>(flight);
    v.flying = !chain.landed();
    v.height_mm = chain.height_mm(), v.climb_mm_s = chain.climb_mm_s();
    v.controls = qr_->firmware.controls();
    v.deadline_misses = qr_->scheduler.stats().deadline_misses;
    return v;
  }
  const wire::ParameterValues& parameters() const override { return qr_->firmware.parameters(); }
  const char* firmware() const override { return "host"; }
  qr::SensorSample sensor_sample() override { return qr_->firmware.sample(); }
  const qr::SensorStage<SimBoard>* sensor_stage() const override { return &qr_->scheduler.sensor_stage(); }
  std::optional<qr::SensorCounts> sensor_counts() const override {
    if (!qr_->board.sensor_drivers()) return std::nullopt;
    return qr_->scheduler.sensor_stage().counts();
  }

 private:
  std::unique_ptr<SimQr> qr_;
};

}  // namespace qrsim
