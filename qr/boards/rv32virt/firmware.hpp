// The flight firmware on the devboard: the board, the flight context and the scheduler, run
// until the console's exit request has been carried out.
#pragma once

#include <common/task_names.hpp>
#include <qr/boards/rv32virt/fail_safe.hpp>
#include <qr/boards/rv32virt/virt_board.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/flight.hpp>
#include <qr/core/scheduler.hpp>

namespace rv32virt {

template <class Chain>
int run_firmware() {
  // Static: the flight context is large and must not live on the 8 KiB stack.
  static VirtBoard board(qr::kControlHz);
  static qr::Flight<Chain> flight(board.log_area());
  static qr::Scheduler<VirtBoard, qr::Flight<Chain>> scheduler(board, flight);
  // A fault names the task it stopped (the table's rows are wire::kTaskNames, flight_tasks.hpp).
  watch_running_task(scheduler.running_task_cell(), wire::kTaskNames, wire::kTaskCount);
  board.attach_statistics(scheduler.stats().task, qr::Flight<Chain>::kTaskCount, &scheduler.stats().tick);
  // On the sensor link every tick is answered with its engines (lock-step with the simulator).
  while (scheduler.tick()) board.answer(flight, scheduler.stats().deadline_misses, scheduler.sensor_stage());
  return 0;
}

}  // namespace rv32virt
