// The QR in the simulator: the world, the sim board, the flight firmware exactly as it runs on
// the RV32 board (qr::Flight over the fixed-point FlightChain) and its scheduler.
#pragma once

#include <memory>

#include <qr/boards/sim/sim_board.hpp>
#include <qr/core/chain/flight_chain.hpp>
#include <qr/core/flight.hpp>
#include <qr/core/scheduler.hpp>
#include <sim/world.hpp>

namespace qrsim {

using Firmware = qr::Flight<qr::FixedChain>;

struct SimQr {
  SimQr(const sim::VehicleParams& vehicle, const sim::WorldConfig& config, size_t log_bytes = SimBoard::kLogBytes)
      : world(vehicle, config), board(world, log_bytes), firmware(board.log_area()), scheduler(board, firmware) {}

  // One control period: the physics runs to the kick, then the firmware's tick.
  bool tick() { return scheduler.tick(); }

  sim::World world;
  SimBoard board;
  Firmware firmware;
  qr::Scheduler<SimBoard, Firmware> scheduler;
};

// The whole QR is a few hundred kB of buffers: keep it off the stack.
inline std::unique_ptr<SimQr> make_qr(const sim::VehicleParams& vehicle, const sim::WorldConfig& config,
                                      size_t log_bytes = SimBoard::kLogBytes) {
  return std::make_unique<SimQr>(vehicle, config, log_bytes);
}

}  // namespace qrsim
