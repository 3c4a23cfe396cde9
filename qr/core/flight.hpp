// The QR's flight software as one scheduler context: the link (frames in, acks and telemetry
// out), the safety machine, and the signal chain, run as task sets chosen by the mode.
//
// Data flows one way through a tick: bytes and the sensor sample come in, the link applies the
// pilot's messages, the chain turns the sample into engine wishes, the safety machine has the
// last word on the engines, and telemetry reports what happened.
//
// `Chain` is the signal chain (qr/core/chain/flight_chain.hpp in flight; a scripted one in
// tests). It provides: set_parameters, set_pilot, filter, calibrate, calibrated, estimate,
// control_yaw, control_attitude, mix, mix_manual and the integer read-outs used below.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/byte_ring.hpp>
#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/parameter_table.hpp>
#include <common/request_dedup.hpp>
#include <qr/core/board.hpp>
#include <qr/core/flight_log.hpp>
#include <qr/core/flight_tasks.hpp>
#include <qr/core/rate.hpp>
#include <qr/core/safety.hpp>
#include <qr/core/scheduler.hpp>
#include <qr/core/task.hpp>

namespace qr {

template <class Chain>
class Flight {
 public:
  static constexpr uint8_t kTaskCount = kFlightTaskCount;
  static const Task<Flight> kTasks[kTaskCount];

  // `log_memory`: where the loggers keep their lines (none: logging is refused).
  explicit Flight(LogArea log_memory = {}) {
    log_.attach(log_memory);
    apply_parameters();
  }

  // ---- the scheduler's side ----
  TaskSet task_set() const { return kFlightTaskSets[index(safety_.mode())]; }
  void begin_tick(uint32_t now_us, const SensorSample& sample) {
    sub_ms_us_ += now_us - tick_us_;  // divisions by a constant: multiplies on RV32IM
    uptime_ms_ += sub_ms_us_ / 1000u;
    sub_ms_us_ %= 1000u;
    tick_us_ = now_us;
    sample_ = sample;
    wanted_ = EngineCommand{};
  }
  uint32_t rx_space() const { return static_cast<uint32_t>(rx_.space()); }
  void receive(uint8_t byte) { rx_.push(byte); }
  bool tx_peek(uint8_t& byte) const { return tx_.peek(byte); }
  void tx_pop() { tx_.drop(); }
  EngineCommand engines() const { return engines_; }
  uint8_t leds() const;
  // Stops once the exit has been carried out and its last bytes are out.
  bool running() const { return !(safety_.stopped() && tx_.empty()); }
  void account(const TickReport& report, const SchedulerStats<kTaskCount>& stats) {
    last_busy_us_ = report.busy_us;
    if (report.busy_us > loop_time_us_) loop_time_us_ = report.busy_us;
    deadline_misses_ = report.deadline_misses;
    cpu_load_permille_ = report.cpu_load_permille;
    task_stats_ = &stats;
  }

  // ---- read-outs for boards, tests and the simulator ----
  Mode mode() const { return safety_.mode(); }
  // The pilot's input as of the last control frame this tick's link task read.
  const ControlInput& controls() const { return controls_; }
  const SafetyMachine& safety() const { return safety_; }
  const Chain& chain() const { return chain_; }
  Chain& chain() { return chain_; }
  const wire::LinkCounters& link_counters() const { return parser_.counters(); }
  const wire::ParameterValues& parameters() const { return params_; }
  const FlightLog& log() const { return log_; }
  uint32_t tx_dropped_frames() const { return tx_dropped_; }

 private:
  struct RequestHandler;

  // ---- tasks ----
  void run_link();
  void run_filter() { chain_.filter(sample_); }
  void run_calibration() {
    if (chain_.calibrate()) safety_.calibration_finished();
  }
  void run_estimator() { chain_.estimate(); }
  void run_attitude_control() { chain_.control_attitude(); }
  void run_yaw_control() { chain_.control_yaw(); }
  void run_mixer() { wanted_ = chain_.mix(); }
  void run_manual_mixer() { wanted_ = chain_.mix_manual(); }
  void run_safety();
  void run_telemetry();
  void run_logger();

  void on_frame(const wire::Frame& frame);
  void apply_parameters();
  void send(const wire::FrameBytes& frame);
  void say(const char* text);
  void send_slow_group();
  uint8_t telemetry_flags() const;
  static uint16_t saturate_u16(uint32_t v) { return v > 0xFFFFu ? uint16_t{0xFFFF} : static_cast<uint16_t>(v); }
  Situation situation() const {
    Situation s;
    s.now_us = tick_us_;
    s.controls = controls_;
    s.engines = engines_;
    s.calibrated = chain_.calibrated();
    s.battery_mv = sample_.battery_mv;
    s.last_frame_us = last_frame_us_;
    s.tilt_mrad = chain_.tilt_mrad();
    return s;
  }

  // Receive side: 64 bytes hold more than two ticks of a full-speed line.
  wire::ByteRing<64> rx_;
  // Send side: a telemetry period's frames plus replies, with room to spare.
  wire::ByteRing<256> tx_;
  wire::FrameParser parser_{wire::Listen::pc_to_qr};
  wire::RequestDedup dedup_;
  wire::ParameterValues params_;
  SafetyMachine safety_{SafetyLimits{}};
  Chain chain_;

  uint32_t tick_us_ = 0;      // time of this tick
  uint32_t uptime_ms_ = 0;    // for the dedup window; wraps after 49 days
  uint32_t sub_ms_us_ = 0;
  SensorSample sample_;
  ControlInput controls_;
  EngineCommand wanted_;      // what the mixer asks for this tick
  EngineCommand engines_;     // what the engines get (after the safety machine)
  uint32_t last_frame_us_ = 0;
  uint32_t last_byte_us_ = 0;
  Mode announced_mode_ = Mode::safe;

  uint16_t telemetry_divider_ = 1;
  uint16_t telemetry_count_ = 0;
  uint8_t telemetry_seq_ = 0;
  uint8_t slow_group_ = 0;
  uint32_t loop_time_us_ = 0;     // longest tick since the last system report
  uint32_t last_busy_us_ = 0;
  uint32_t deadline_misses_ = 0;
  uint16_t cpu_load_permille_ = 0;
  uint32_t tx_dropped_ = 0;
  const SchedulerStats<kTaskCount>* task_stats_ = nullptr;  // the scheduler's, once it ran
  uint8_t stats_task_ = 0;  // whose figures the next telemetry_task carries

  FlightLog log_;
  bool log_status_owed_ = false;  // after a log request, its effect is reported at once

  // Parameter reports still owed after a param_get: table rows [report_next_, report_end_).
  uint8_t report_next_ = 0;
  uint8_t report_end_ = 0;
};

}  // namespace qr

#include <qr/core/flight_impl.hpp>
