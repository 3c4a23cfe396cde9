// The QR's flight software as one scheduler context: the link (frames in, acks and telemetry
// out), the safety machine, and the signal chain, run as the task table says (flight_tasks.hpp).
//
// Data flows one way through a tick: bytes and the sensor sample come in, the link applies the
// pilot's messages, the chain turns the sample into engine wishes, the safety machine has the
// last word on the engines, and telemetry and the logs report what happened.
//
// The jobs around the tick each have a unit of their own: the link task (flight_link.hpp),
// applying requests (flight_requests.hpp), composing telemetry (flight_telemetry.hpp),
// assembling log lines (flight_log_lines.hpp) and the LED map (led_map.hpp). `Chain` is the
// signal chain, any type that satisfies SignalChain (signal_chain.hpp): FixedChain in flight, a
// scripted one in tests.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/byte_ring.hpp>
#include <common/drivers/erpm.hpp>
#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/parameter_table.hpp>
#include <common/request_dedup.hpp>
#include <qr/core/board.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/esc_direction.hpp>
#include <qr/core/flight_log.hpp>
#include <qr/core/flight_tasks.hpp>
#include <qr/core/flight_telemetry.hpp>
#include <qr/core/led_map.hpp>
#include <qr/core/lost_model_beacon.hpp>
#include <qr/core/observable_streams.hpp>
#include <qr/core/radio_receiver.hpp>
#include <qr/core/safety.hpp>
#include <qr/core/scheduler.hpp>
#include <qr/core/sensor_fault_report.hpp>
#include <qr/core/signal_chain.hpp>
#include <qr/core/task.hpp>
#include <qr/core/transmit_queue.hpp>

namespace qr {

template <SignalChain Chain>
class Flight {
 public:
  using ChainType = Chain;
  static constexpr uint8_t kTaskCount = kFlightTaskCount;
  static const Task<Flight> (&kTasks)[kFlightTaskCount];

  // `log_memory`: where the loggers keep their lines (none: logging is refused).
  explicit Flight(LogArea log_memory = {}) {
    log_.attach(log_memory);
    apply_parameters();
  }

  // ---- the scheduler's side (SchedulerContext, scheduler.hpp) ----
  // The distinct task sets (modes that run the same rows share one: kCompiledSets).
  static constexpr uint8_t kSetCount = kCompiledSetCount;
  static constexpr Task<Flight> task(uint8_t id) { return flight_tasks<Flight>()[id]; }
  static constexpr TaskSet task_set(uint8_t set) { return kCompiledSets[set]; }
  uint8_t current_set() const {
    struct SetOfMode {
      uint8_t set[kModeCount];
    };
    constexpr SetOfMode table = [] {
      SetOfMode t{};
      for (uint8_t m = 0; m < kModeCount; ++m) t.set[m] = compiled_set_of<Flight>(m);
      return t;
    }();
    return table.set[index(safety_.mode())];
  }
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
  // Bytes the board's serial receiver had no room for (boards that count them), since start.
  void serial_overruns(uint32_t count) { rx_overruns_ = count; }
  uint32_t rx_overruns() const { return rx_overruns_; }
  // The radio receiver's line (boards with one, RadioBoard).
  uint32_t radio_space() const { return static_cast<uint32_t>(radio_rx_.space()); }
  void radio_receive(uint8_t byte) { radio_rx_.push(byte); }
  // Bidirectional DShot ESCs' answers (boards with them, EscAnswerBoard): the engines' RPM for
  // telemetry. A garbled answer keeps the engine's last reading.
  void esc_answers(const EscAnswers& answers) {
    const uint8_t pole_pairs = static_cast<uint8_t>(params_.get(wire::ParamId::motor_poles) / 2);
    for (int i = 0; i < 4; ++i) {
      if ((answers.fresh & (1u << i)) == 0) continue;
      const drivers::ErpmReading r = drivers::decode_erpm_answer(answers.raw[i]);
      if (r.valid) rpm_[i] = wire::saturate_u16(drivers::rpm_of_period(r.period_us, pole_pairs));
    }
    rpm_heard_ = true;
  }
  // A DShot command for the ESCs this tick, command 0 for none (boards whose ESCs take them,
  // EscCommandBoard; docs/safety.md rule 18): an ESC's direction the pilot set on the bench
  // (esc_direction.hpp), to its engine; else the lost-model beacon (lost_model_beacon.hpp), to all.
  EscCommand esc_command_due() {
    if (esc_direction_.pending()) {
      const EscCommand due = esc_direction_.due(safety_.mode(), engines_, tick_us_);
      if (!esc_direction_.pending()) say_esc_direction(false);  // dropped: out of safe, or an engine turned
      return due;
    }
    const uint32_t timeout_us = static_cast<uint32_t>(params_.get(wire::ParamId::link_timeout_ms)) * 1000u;
    const uint8_t beacon = lost_model_beacon(safety_.mode(), engines_, tick_us_, situation().last_frame_us, timeout_us,
                                             kPeriodUs);
    return {beacon, kEveryEngine};
  }
  // Whether the board took the command due: a direction goes on to its save, and the pilot is told
  // how it ended.
  void esc_command_sent(bool taken) {
    bool saved = false;
    if (esc_direction_.pending() && esc_direction_.sent(taken, tick_us_, saved)) say_esc_direction(saved);
  }
  bool tx_peek(uint8_t& byte) const { return tx_.peek(byte); }
  void tx_pop() { tx_.pop(); }
  EngineCommand engines() const { return engines_; }
  uint8_t leds() const { return led_pattern(safety_.mode(), safety_.battery_warning()); }
  // Stops once the exit has been carried out and its last bytes are out.
  bool running() const { return !(safety_.stopped() && tx_.empty()); }
  void account(const TickReport& report, const SchedulerStats<kTaskCount>& stats) {
    last_busy_us_ = report.busy_us;
    telemetry_.note_tick(report);
    task_stats_ = &stats;
  }

  // ---- the tasks (rows of kFlightTaskTable) ----
  void run_link();
  void run_filter() { chain_.filter(sample_); }
  void run_calibration() {
    if (chain_.calibrate()) {
      if (const chain::GyroTurnsResult* turns = chain_.take_gyro_turns()) take_gyro_turns(*turns);
      say_calibration_verdict();
      safety_.calibration_finished();
    }
  }
  void run_mixer() { wanted_ = chain_.mix(); }
  // The manual set's mixer: the sticks, open loop, whatever the sources (a transition out of
  // manual takes its sources before this tick's set, which has no loops, is done).
  void run_manual_mixer() { wanted_ = chain_.mix(chain::kOpenLoop); }
  void run_safety();
  // The panic's entry action: a landing starts the chain's descent (the row's sources, a
  // landing's); the cut flies the loops as they were and leaves the engines to the safety machine.
  void enter_panic() {
    if (safety_.landing()) {
      chain_.start_descent(safety_.flying_lift());
    } else {
      chain_.fly(sources::kCut);
    }
  }
  void run_telemetry() {
    telemetry_.period(*this, [this](const wire::FrameBytes& f) { send(f); });
  }
  void run_logger();
  void run_stream();
  // The rates that are parameters, as dividers of the control rate.
  uint16_t telemetry_divider() const {
    return divider_for(static_cast<uint32_t>(params_.get(wire::ParamId::telemetry_rate_hz)));
  }
  uint16_t log_divider() const { return static_cast<uint16_t>(params_.get(wire::ParamId::log_divider)); }

  // ---- read-outs for the units around the tick, boards, tests and the simulator ----
  Mode mode() const { return safety_.mode(); }
  Pilot pilot() const { return pilot_; }
  const RadioReceiver& radio() const { return radio_; }
  // A valid RC frame within the link timeout.
  bool radio_link_up() const {
    return radio_.heard() && tick_us_ - radio_.last_rc_us() <= safety_.limits().link_timeout_us;
  }
  // The engines' RPM from their ESCs' answers; false until a board handed any.
  bool rpm(uint16_t (&out)[4]) const {
    for (int i = 0; i < 4; ++i) out[i] = rpm_[i];
    return rpm_heard_;
  }
  // The radio's channel `ch` (0..15) as last received, CRSF units; 0 before an RC frame.
  uint16_t rc_channel(uint8_t ch) const { return radio_.channel(ch); }
  // Engine i's RPM as last heard (0 until then).
  uint16_t engine_rpm(uint8_t i) const { return rpm_[i]; }
  // The pilot's input as of the last control frame this tick's link task read.
  const ControlInput& controls() const { return controls_; }
  const SensorSample& sample() const { return sample_; }
  uint32_t tick_us() const { return tick_us_; }
  uint32_t last_busy_us() const { return last_busy_us_; }
  const SafetyMachine& safety() const { return safety_; }
  const Chain& chain() const { return chain_; }
  Chain& chain() { return chain_; }
  const wire::LinkCounters& link_counters() const { return parser_.counters(); }
  const wire::ParameterValues& parameters() const { return params_; }
  const FlightLog<Chain>& log() const { return log_; }
  const FlightTelemetry& telemetry() const { return telemetry_; }
  const SchedulerStats<kTaskCount>* task_stats() const { return task_stats_; }
  uint32_t tx_dropped_frames() const { return tx_dropped_; }
  uint8_t telemetry_flags() const;

 private:
  template <class F>
  friend struct FlightRequests;

  void receive_link_bytes();
  void receive_radio_bytes();
  void on_frame(const wire::Frame& frame);
  void on_radio_sticks(const drivers::RcSticks& sticks);
  void send_download_parts();
  void send_owed_reports();
  void take_sticks();
  void take_gyro_turns(const chain::GyroTurnsResult& turns);
  // Parameter fan-out, when a parameter changes (never per tick): the safety machine's limits
  // and the chain's coefficients. The task rates that are parameters are read by the scheduler
  // through the task table.
  void apply_parameters() {
    safety_.limits() = safety_limits(params_);
    chain_.set_parameters(params_);
    radio_.set_map(params_);
    const Pilot pilot = static_cast<Pilot>(params_.get(wire::ParamId::pilot));
    if (pilot != pilot_) {
      // The old pilot's sticks are nobody's now, and the new one's arm switch must be seen off.
      pilot_ = pilot;
      controls_ = ControlInput{};
      safety_.pilot_changed();
    }
    pilot_changed_ = true;
  }
  // The one door of mode changes (issue 31). Whatever made the safety machine change the mode
  // since the last tick's door (a request, the sticks or the radio's switches read by the link,
  // a finished calibration, a watchdog) takes effect here, once: the mode's sources go to the
  // chain, and its entry action runs, told the mode the vehicle flew in before. Its one caller is
  // the link task (run_link, flight_link.hpp), after every request the tick reads (only the link's
  // sending is left) and before the chain runs, so a tick that reads a lift change already flies
  // the stick (rule 15); what the calibration or the safety task changes takes effect at the next
  // tick's door, a control period later (the safety machine's own engine limits apply at once).
  void change_modes() {
    static_assert(modes_in_order<Flight>(), "kFlightModes: row i is mode i");
    static_assert(rows_in_task_order<Flight>(), "kFlightTaskTable: row i is task i");
    static_assert(every_mode_has_a_compiled_set<Flight>(), "kCompiledSets: every mode's set is compiled");
    static_assert(sources_have_their_tasks<Flight>(), "kFlightModes: a mode's sources need their loops' tasks");
    if (safety_.take_entered() != 0) open_door();
  }
  // Out of line, as the mode's announcement is: a tick that enters a mode is rare, and the
  // link row, which asks every tick, need not save the registers it takes.
  [[gnu::noinline]] void open_door() {
    const Mode to = safety_.mode();
    const FlightMode<Flight>& row = flight_modes<Flight>()[index(to)];
    chain_.fly(row.sources);
    if (row.enter != nullptr) row.enter(*this, door_mode_);
    door_mode_ = to;
  }
  void announce_mode();
  void say_esc_direction(bool saved);
  void say_calibration_verdict();
  void report_sensor_faults();
  void say_sensor_faults();
  void send(const wire::FrameBytes& frame) {
    if (!tx_.push(frame)) ++tx_dropped_;
  }
  // An ack or nack: ahead of everything queued that is not yet on its way (transmit_queue.hpp).
  void send_answer(const wire::FrameBytes& frame) {
    if (!tx_.push_answer(frame)) ++tx_dropped_;
  }
  void say(const char* text);
  Situation situation() const {
    Situation s;
    s.now_us = tick_us_;
    s.controls = controls_;
    s.engines = engines_;
    s.calibrated = chain_.calibrated();
    s.battery_mv = sample_.battery_mv;
    // The link watchdog watches the pilot's link: the radio's RC frames when the radio flies.
    s.pilot = pilot_;
    s.last_frame_us = pilot_ == Pilot::radio ? radio_.last_rc_us() : last_frame_us_;
    s.tilt_mrad = chain_.tilt_mrad();
    s.height_valid = chain_.height_valid();
    s.height_mm = chain_.height_mm();
    s.landed = chain_.landed();
    s.imu_healthy = sample_.health.imu;
    s.barometer_healthy = sample_.health.barometer;
    s.wrong_sign = static_cast<uint8_t>(chain_.wrong_sign());
    s.identification_over = chain_.identification_over();
    return s;
  }

  // Receive side: 64 bytes hold more than two ticks of a full-speed line.
  wire::ByteRing<64> rx_;
  uint32_t rx_overruns_ = 0;
  wire::FrameParser parser_{wire::Listen::pc_to_qr};
  // The radio's line: 64 bytes hold more than a tick's worth at 420 000 baud.
  wire::ByteRing<64> radio_rx_;
  RadioReceiver radio_;
  Pilot pilot_ = Pilot::pc;
  uint16_t rpm_[4] = {0, 0, 0, 0};
  bool rpm_heard_ = false;
  wire::RequestDedup dedup_;
  wire::ParameterValues params_;
  SafetyMachine safety_;
  EscDirection esc_direction_;  // an ESC's direction being set on the bench
  Chain chain_;
  FlightTelemetry telemetry_;

  uint32_t tick_us_ = 0;    // time of this tick
  uint32_t uptime_ms_ = 0;  // for the dedup window; wraps after 49 days
  uint32_t sub_ms_us_ = 0;
  SensorSample sample_;
  ControlInput controls_;
  bool pilot_changed_ = true;  // the chain's set-points must be made again from controls_
  EngineCommand wanted_;       // what the mixer asks for this tick
  EngineCommand engines_;      // what the engines get (after the safety machine)
  uint32_t last_frame_us_ = 0;
  uint32_t last_byte_us_ = 0;
  Mode announced_mode_ = Mode::safe;
  SensorFaultReport fault_report_;  // the sensors' faults on the debug text, rate-limited
  Mode door_mode_ = Mode::safe;     // the mode the last door opened into (change_modes)
  uint32_t last_busy_us_ = 0;
  uint32_t tx_dropped_ = 0;
  const SchedulerStats<kTaskCount>* task_stats_ = nullptr;  // the scheduler's, once it ran

  FlightLog<Chain> log_;
  bool log_status_owed_ = false;  // after a log request, its effect is reported at once

  ObservableStreams<Flight> streams_;

  // Parameter reports still owed after a param_get: table rows [report_next_, report_end_).
  uint8_t report_next_ = 0;
  uint8_t report_end_ = 0;

  // Send side: a telemetry period's frames plus replies, answers first. Last: the members the
  // tasks use stay within a load's reach of the object's start.
  TransmitQueue tx_;
};

template <SignalChain Chain>
const Task<Flight<Chain>> (&Flight<Chain>::kTasks)[kFlightTaskCount] = kFlightTaskTable<Flight<Chain>>;

}  // namespace qr

#include <qr/core/flight_impl.hpp>
#include <qr/core/flight_link.hpp>
