// A scenario's faults on the sensors' bus and chips (docs/simulator.md section 6.2: nack, sda,
// imu, baro), played on the sim board: the wire's (a NACK burst, a stuck SDA) as time windows of
// its bus (SimI2cBus), the chips' (a wrong identity, a PROM with a bad CRC, a slow conversion, a
// FIFO overflow, a self-test response out of bounds) through their models' fault hooks. What the
// firmware does with each is docs/drivers.md section 7, "Faults".
#pragma once

#include <stdint.h>

#include <string>

#include <qr/boards/sim/sim_board.hpp>
#include <qr/sim_runner/scenario_script.hpp>

namespace qrsim {

bool is_sensor_fault(Action action);

// The event `e` (a sensor fault) at the world's `now_us`. Returns a note for the flight's notes
// when it changes nothing the file may expect it to: no bus (--sensors direct), or
// a FIFO that is not enabled.
std::string inject_sensor_fault(const Event& e, SimBoard& board, uint64_t now_us);

// The chips' faults acting at `since` (s after t0), set every tick: the last identity and the
// PROM from their events on, each slow conversion while its window lasts.
void apply_chip_faults(const ScenarioScript& script, double since, SimBoard& board);

// The faults a part has from power-up, set before the first tick: a self-test response out of
// bounds (the driver self-tests at power-up only, before any t0).
void apply_power_up_faults(const ScenarioScript& script, SimBoard& board);

}  // namespace qrsim
