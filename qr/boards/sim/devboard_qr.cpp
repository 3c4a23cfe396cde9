#include <qr/boards/sim/devboard_qr.hpp>

#include <common/messages.hpp>
#include <common/task_names.hpp>

namespace qrsim {
namespace {

// Long enough for QEMU to start and for any tick; a board that does not answer in this time has
// stopped or hung.
constexpr int kAnswerTimeoutMs = 10000;

}  // namespace

DevboardQr::DevboardQr(const sim::VehicleParams& vehicle, const sim::WorldConfig& config, const std::string& elf,
                       uint32_t core_mhz)
    : world_(vehicle, config), board_(world_), instructions_(wire::kTaskCount + 1u), core_mhz_(core_mhz) {
  if (!process_.start(elf, core_mhz, error_)) return;
  // The board's engines frame for kick 0 says its UART is ready: from now on every ground byte
  // is counted (one sent before could be lost in its FIFO reset).
  simlink::EngineFrame ready;
  if (!await_engines(0, ready)) return;
}

void DevboardQr::fail(const std::string& why) {
  if (error_.empty()) error_ = why;
  stopped_ = true;
}

bool DevboardQr::await_engines(uint32_t kick, simlink::EngineFrame& out) {
  uint8_t buffer[512];
  for (;;) {
    bool got = false;
    const long n = read_some(process_.link(), buffer, sizeof buffer, kAnswerTimeoutMs);
    if (n == 0) {
      fail("the devboard did not answer kick " + std::to_string(kick) + " within 10 s");
      return false;
    }
    if (n < 0) {
      // The firmware ended (an exit request) or QEMU died: the end of the flight, unless it died.
      stopped_ = true;
      return false;
    }
    for (long i = 0; i < n; ++i) {
      from_board_.push(buffer[i], [&](const simlink::LinkFrame& frame) {
        simlink::EngineFrame engines;
        simlink::I2cBeginFrame transfer;
        if (frame.decode(engines) && engines.kick == kick) {
          out = engines;
          got = true;
        } else if (frame.decode(transfer)) {
          begin_transfer(transfer);
        }
      });
    }
    // Lock-step: nothing follows the answer until the next sensors frame, so it is the last of
    // what was read.
    if (got) return true;
  }
}

// A transfer the board's driver began during the tick: on the sim board's bus now, in the
// simulated instant the tick runs in, as the host build's driver begins it (sim_i2c_bus.hpp).
void DevboardQr::begin_transfer(const simlink::I2cBeginFrame& f) {
  drivers::I2cTransfer t;
  t.address = f.address;
  for (uint8_t i = 0; i < drivers::kI2cMaxWrite; ++i) t.write[i] = f.write[i];
  t.write_count = f.write_count;
  t.read_count = f.read_count;
  if (board_.i2c().begin(f.channel, t)) return;
  // Refused (a channel still busy, which the board's own book would have refused first): the
  // board is told at the next kick, so its channel is not held for ever.
  refused_.push_back(f.channel);
}

// Before a kick: the end of every transfer the wire has finished by now, so that the board's
// drivers collect in this tick what the host build's would. In channel order, which is the order
// they were begun, as the board's bus expects (LinkI2cBus::done): a tick's transfers all end within
// its period (532.5 us at most of 1000), and the sensor stage begins the IMU's (channel 0) first.
bool DevboardQr::send_transfer_ends() {
  for (uint8_t channel = 0; channel < SimI2cBus::kChannels; ++channel) {
    drivers::I2cReply reply;
    const drivers::I2cResult result = board_.i2c().poll(channel, reply);
    if (result == drivers::I2cResult::pending || result == drivers::I2cResult::idle) continue;
    simlink::I2cDoneFrame done;
    done.channel = channel;
    done.result = static_cast<uint8_t>(result);
    done.count = reply.count;
    for (uint8_t i = 0; i < drivers::kI2cMaxRead; ++i) done.data[i] = reply.data[i];
    if (!send(done)) return false;
  }
  for (const uint8_t channel : refused_) {
    simlink::I2cDoneFrame done;
    done.channel = channel;
    done.result = static_cast<uint8_t>(drivers::I2cResult::idle);
    if (!send(done)) return false;
  }
  refused_.clear();
  return true;
}

// The kick: the sensors frame, after the ends of the transfers the board's drivers will collect
// (with the sensor drivers), or with the plant's sample.
bool DevboardQr::send_kick() {
  const qr::SensorSample sample = board_.read_sensors();
  simlink::SensorFrame sensors;
  sensors.kick = kick_;
  sensors.time_us = board_.now_us();
  sensors.battery_mv = sample.battery_mv;
  sensors.ground_bytes = ground_to_qr_;
  if (board_.sensor_drivers()) {
    sensors.sensors_on_i2c = 1;
    if (!send_transfer_ends()) return false;
  } else {
    for (int axis = 0; axis < 3; ++axis) {
      sensors.gyro[axis] = sample.gyro[axis];
      sensors.accel[axis] = sample.accel[axis];
    }
    sensors.pressure_pa = sample.pressure_pa;
  }
  return send(sensors);
}

template <class Msg>
bool DevboardQr::send(const Msg& message) {
  const simlink::LinkFrameBytes frame = simlink::encode(message);
  if (write_all(process_.link(), frame.bytes, frame.size)) return true;
  stopped_ = true;  // the firmware has ended
  return false;
}

void DevboardQr::follow_pilot(uint8_t byte) {
  pilot_frames_.push(byte, [&](const wire::Frame& frame) {
    wire::ParamSet set;
    wire::Control control;
    if (wire::decode(frame, set)) parameters_.set(set.id, set.value);
    if (wire::decode(frame, control))
      view_.controls = qr::ControlInput{control.lift, control.roll, control.pitch, control.yaw};
  });
}

void DevboardQr::follow_qr(uint8_t byte) {
  qr_frames_.push(byte, [&](const wire::Frame& frame) {
    wire::ParamReport report;
    if (wire::decode(frame, report)) parameters_.set(report.id, report.value);
  });
}

bool DevboardQr::tick() {
  if (stopped_) return false;
  const uint32_t seen = kick_;
  kick_ = board_.wait_kick(kick_);
  // In real time (serve mode) a round trip that ran past its period makes the next kick a later
  // one: the periods in between are deadline misses, as on the host build's sim board.
  late_kicks_ += kick_ - seen - 1;

  // The pilot's bytes that have reached the QR by this kick, down its UART first.
  std::vector<uint8_t> down;
  uint8_t byte = 0;
  while (board_.serial_read(byte)) {
    down.push_back(byte);
    follow_pilot(byte);
  }
  ground_to_qr_ += static_cast<uint32_t>(down.size());
  if (!down.empty() && !write_all(process_.ground(), down.data(), down.size())) {
    fail("the devboard's UART closed: " + process_.log());
    return false;
  }

  simlink::EngineFrame answer;
  if (!send_kick() || !await_engines(kick_, answer)) return false;

  // What the board wrote to its UART during the tick: on the line to the pilot from this tick on.
  uint32_t owed = answer.ground_bytes - ground_from_qr_;
  uint8_t up[256];
  while (owed > 0) {
    const long n = read_some(process_.ground(), up, owed < sizeof up ? owed : sizeof up, kAnswerTimeoutMs);
    if (n <= 0) {
      fail("the devboard's UART fell silent with bytes owed: " + process_.log());
      return false;
    }
    for (long i = 0; i < n; ++i) {
      follow_qr(up[i]);
      if (!board_.serial_write(up[i])) ++ground_refused_;
    }
    owed -= static_cast<uint32_t>(n);
  }
  ground_from_qr_ = answer.ground_bytes;

  qr::EngineCommand engines;
  for (int i = 0; i < 4; ++i) engines.value[i] = answer.engines[i];
  board_.set_engines(engines);
  view_.mode = answer.mode;
  view_.flying = (answer.flags & wire::kFlagFlying) != 0;
  view_.roll_e4 = answer.angles_e4[simlink::EngineFrame::roll_estimate];
  view_.pitch_e4 = answer.angles_e4[simlink::EngineFrame::pitch_estimate];
  view_.roll_setpoint_e4 = answer.angles_e4[simlink::EngineFrame::roll_setpoint];
  view_.pitch_setpoint_e4 = answer.angles_e4[simlink::EngineFrame::pitch_setpoint];
  view_.yaw_rate_setpoint_e3 = answer.yaw_rate_setpoint_e3;
  view_.deadline_misses = answer.deadline_misses + late_kicks_;
  sensor_counts_.healthy = answer.sensors_healthy;
  for (int i = 0; i < qr::SensorCounts::kCounts; ++i) sensor_counts_.value[i] = answer.sensor_counts[i];
  if (answer.stats_row < instructions_.size()) {
    InstructionStats& s = instructions_[answer.stats_row];
    s.reported = true;
    s.runs = answer.stats[simlink::EngineFrame::count];
    s.max = answer.stats[simlink::EngineFrame::max];
    s.overruns = answer.stats[simlink::EngineFrame::overruns];
    s.sum = answer.stats[simlink::EngineFrame::sum_low] |
            (static_cast<uint64_t>(answer.stats[simlink::EngineFrame::sum_high]) << 32);
  }
  return true;
}

}  // namespace qrsim
