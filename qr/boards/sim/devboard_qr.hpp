// The cross-compiled firmware (qr.elf on the emulated devboard) flying in the simulated world, in
// lock-step over the sensor link (common/sensor_link.hpp, docs/devboard.md). Per control period:
// the plant runs to the kick and is sampled (SimBoard::wait_kick, as for the host build); the
// ground line's bytes that have reached the QR by then go down its UART; the sensors frame goes
// down the link, stamped with the simulated time and counting those bytes; the board answers with
// its engines and the count of bytes it wrote to its UART, which are read and put on the line to
// the pilot in that tick. Nothing waits on a wall clock, so a flight is the same on any host.
// With the sensor drivers (SimBoard::use_sensor_drivers) the kick carries no sample: the board's
// drivers read the sim board's chips over the link (common/sensor_link.hpp, I2cBeginFrame).
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include <common/frame_parser.hpp>
#include <common/sensor_link.hpp>
#include <qr/boards/sim/devboard_process.hpp>
#include <qr/boards/sim/flying_qr.hpp>

namespace qrsim {

// The scheduler's statistics of one row (a task, or the whole tick), in RV32 instructions, as the
// board last reported them (a row a tick, common/sensor_link.hpp).
struct InstructionStats {
  bool reported = false;
  uint32_t runs = 0, max = 0, overruns = 0;
  uint64_t sum = 0;
  double mean() const { return runs == 0 ? 0.0 : static_cast<double>(sum) / runs; }
};

class DevboardQr final : public FlyingQr {
 public:
  // Starts QEMU with `elf` and waits for the board's first frame; error() says why it did not.
  // core_mhz > 0: a core of that speed, whose ticks can run past their period (DevboardProcess).
  DevboardQr(const sim::VehicleParams& vehicle, const sim::WorldConfig& config, const std::string& elf,
             uint32_t core_mhz = 0);

  sim::World& world() override { return world_; }
  SimBoard& board() override { return board_; }
  bool tick() override;
  FirmwareView view() const override { return view_; }
  const wire::ParameterValues& parameters() const override { return parameters_; }
  const char* firmware() const override { return "rv32"; }
  // As the board last reported them in its engines frame.
  std::optional<qr::SensorCounts> sensor_counts() const override {
    if (!board_.sensor_drivers()) return std::nullopt;
    return sensor_counts_;
  }
  std::string error() const override { return error_; }

  // Rows 0 .. task count - 1: the task table's; the last: the whole tick.
  const std::vector<InstructionStats>& instructions() const { return instructions_; }
  // Bytes the board wrote to its UART that the simulated line refused: 0 when its paced
  // transmitter keeps the line's pace, as it should.
  uint64_t ground_bytes_refused() const { return ground_refused_; }
  uint32_t core_mhz() const { return core_mhz_; }  // 0: time stands still while a tick runs

 private:
  bool await_engines(uint32_t kick, simlink::EngineFrame& out);
  // The sensors' bus on the link (SimBoard::use_sensor_drivers): the board's transfers onto the
  // sim board's bus, their ends back before the kick that collects them.
  void begin_transfer(const simlink::I2cBeginFrame& frame);
  bool send_transfer_ends();
  bool send_kick();
  template <class Msg>
  bool send(const Msg& message);
  void fail(const std::string& why);
  // What the firmware will make of the pilot's bytes: its parameter table, its sticks.
  void follow_pilot(uint8_t byte);
  // The values the firmware reports, the ones it writes itself among them (a gyro scale measured).
  void follow_qr(uint8_t byte);

  sim::World world_;
  SimBoard board_;
  DevboardProcess process_;
  simlink::LinkParser from_board_{simlink::LinkEnd::simulator};
  wire::FrameParser pilot_frames_{wire::Listen::pc_to_qr};
  wire::FrameParser qr_frames_{wire::Listen::qr_to_pc};
  wire::ParameterValues parameters_;
  FirmwareView view_;
  std::vector<InstructionStats> instructions_;
  uint32_t kick_ = 0;
  qr::SensorCounts sensor_counts_;
  std::vector<uint8_t> refused_;  // channels whose transfer the sim board's bus refused
  uint32_t ground_to_qr_ = 0;     // bytes put on the board's UART so far
  uint32_t ground_from_qr_ = 0;   // bytes the board wrote to it so far
  uint64_t ground_refused_ = 0;
  uint32_t late_kicks_ = 0;  // real time only: periods the round trip ran past
  uint32_t core_mhz_ = 0;
  std::string error_;
  bool stopped_ = false;
};

}  // namespace qrsim
