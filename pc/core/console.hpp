// The console's logic, without a screen: keys and joystick in, requests and control out through
// the LinkSession, what comes back into the TelemetryModel and the ConsoleLog. The ncurses Cockpit
// draws from it and the main loop feeds it; tests drive it with a scripted clock against a fake QR.
//
// The Console itself only routes: each job is a part of its own (docs/console.md, "How it is
// built and tested"), and the Console hands it what comes in and the time:
//   keys and joystick      PilotInput (ESC's pairing, the joystick's presence), ScreenState
//                          (screens, help, prompt, the plot and parameter screens' keys)
//   asking the QR          PilotRequests (modes, abort, control), ParameterSync, StreamSession,
//                          LogDownloader, ExitHandshake
//   what the QR reports    TelemetryModel, qr_reports (notices), DescentWatch, BatteryGauge, the
//                          Receiver below
//   the log folder         Recordings (rx.hex, telemetry.csv; files for the others)
//   the simulator          SimulatorControls (truth channel), radio_pilot (the radio as the pilot)
//   before the first flight OrientationCheck (is the IMU mounted as the QR takes it?)
//   the motor test         MotorBench (its screen's steps, the truth of which rotor turned)
//   autotune               AutotuneSession (records the identification, proposes gains)
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <common/messages.hpp>
#include <common/parameter_table.hpp>
#include <pc/core/autotune_session.hpp>
#include <pc/core/battery_gauge.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/debug_text.hpp>
#include <pc/core/descent_warning.hpp>
#include <pc/core/exit_handshake.hpp>
#include <pc/core/key.hpp>
#include <pc/core/link_session.hpp>
#include <pc/core/log_downloader.hpp>
#include <pc/core/motor_bench.hpp>
#include <pc/core/orientation_check.hpp>
#include <pc/core/parameter_editor.hpp>
#include <pc/core/parameter_sync.hpp>
#include <pc/core/pilot_controls.hpp>
#include <pc/core/pilot_input.hpp>
#include <pc/core/pilot_requests.hpp>
#include <pc/core/recordings.hpp>
#include <pc/core/screen_state.hpp>
#include <pc/core/simulator_controls.hpp>
#include <pc/core/stream_session.hpp>
#include <pc/core/telemetry_model.hpp>

namespace qrterm {

// The QR's control rate until it says its own (docs/architecture.md: 1 kHz by default).
inline constexpr uint32_t kDefaultControlHz = 1000;

class Console {
 public:
  struct Setup {
    wire::ParameterValues params;    // sent to the QR whenever the link comes up
    bool joystick = false;           // a joystick is part of the cockpit
    uint8_t first_seq = 0;           // of every request type (docs/protocol.md section 6)
    bool simulator = false;          // the console started qrsim and has its truth channel
    bool devboard = false;           // and it flies the devboard (qrsim --devboard), not the host build
    std::string params_file;         // where `params` came from: the parameter screen's "file" column
    bool params_file_exists = true;  // false: there was no such file, `params` are the defaults
    size_t rx_hex_part_bytes = kRxHexPartBytes;
    int battery_cells = 0;  // the pack's LiPo cells (--cells); 0: counted at connection
  };

  Console(ConsoleLog& log, ConsoleFiles files, const Setup& setup, uint32_t now_ms);

  // --- what comes in
  void key(Key key, uint32_t now_ms);
  void act(Action action, uint32_t now_ms);
  void joystick_moved(const Sticks& sticks, bool position_known, uint32_t now_ms);
  void joystick_fire(uint32_t now_ms);  // the abort button
  void joystick_lost(uint32_t now_ms);
  void joystick_back(uint32_t now_ms);
  void receive(const uint8_t* data, size_t count, uint32_t now_ms);
  void line_closed(const std::string& why, uint32_t now_ms);
  // x, a second ESC, a signal. A second call while waiting for the QR quits without waiting.
  void request_exit(uint32_t now_ms);
  // Timers: control at 50 Hz, resends, parameter upload, link state, log download, exit wait.
  void tick(uint32_t now_ms);
  // A message from elsewhere in the program (the simulator's output, the main loop).
  void note(Severity severity, const std::string& text);
  // A line from the simulator's truth channel (docs/simulator.md): a truth line is kept for the
  // screen and drawn under the plot's estimate, an error line goes to the log.
  void truth_line(const std::string& line);
  // Command lines for the truth channel (a push), taken once; the main loop writes them.
  std::vector<std::string> take_sim_commands() { return simulator_.take_commands(); }

  // --- what goes out
  std::vector<uint8_t>& output() { return link_.output(); }
  bool finished() const { return exit_.done(); }
  bool exit_confirmed() const { return exit_.confirmed(); }

  // --- what the screen shows
  // The descent warning (descent_warning.hpp) while it stands and the link is up: the descent
  // speed now, m/s, down.
  std::optional<double> sinking_m_s() const;
  // The QR is in panic: the sticks do nothing, so the warning asks for no lift.
  bool sinking_in_panic() const { return qrterm::sinking_in_panic(telemetry_); }
  uint32_t now_ms() const { return now_ms_; }
  uint32_t uptime_ms() const { return now_ms_ - start_ms_; }
  LinkState link_state() const { return link_.state(now_ms_); }
  const LinkSession& link() const { return link_; }
  const TelemetryModel& telemetry() const { return telemetry_; }
  // The battery's charge and time left against the QR's panic threshold (the console's
  // battery_panic_mv); empty before the first telemetry_system report.
  std::optional<BatteryReading> battery() const;
  const PilotControls& controls() const { return controls_; }
  const wire::Control& last_control() const { return requests_.last_control(); }
  const wire::ParameterValues& params() const { return parameters_.wanted(); }
  std::optional<int32_t> reported(wire::ParamId id) const { return parameters_.reported(id); }
  JoystickState joystick_state() const { return input_.joystick(); }
  bool joystick_position_known() const { return input_.position_known(); }
  bool help_visible() const { return screens_.help_visible(); }
  Screen screen() const { return screens_.screen(); }
  const std::optional<Prompt>& prompt() const { return screens_.prompt(); }
  const StreamSession& streams() const { return streams_; }
  const ParameterEditor& parameter_editor() const { return editor_; }
  const ParameterSync& parameter_sync() const { return parameters_; }
  const AutotuneSession& autotune() const { return autotune_; }
  const MotorBench& motor_bench() const { return bench_; }
  const OrientationCheck& orientation_check() const { return check_; }
  const std::string& params_file() const { return params_file_; }  // the parameter file the console keeps
  uint32_t telemetry_hz() const;
  uint32_t log_divider() const;  // the parameter the console holds
  uint32_t control_hz() const;
  // "truth roll +1.2 pitch -0.5 yaw +10.0 height 1.50 m", or empty: no simulator or no line yet.
  const std::string& truth() const { return simulator_.truth(); }
  // The console started the simulator: the QR's CPU load, loop time and deadline misses are the
  // host's scheduling of a simulated board there, not figures of a flight computer.
  bool flying_simulator() const { return simulator_.present(); }
  // What the QR's CPU figures are (task_figures.hpp), and the devboard's own from the simulator.
  FiguresFrom figures_from() const {
    if (!simulator_.present()) return FiguresFrom::board;
    return devboard_ || simulator_.devboard() ? FiguresFrom::simulator_devboard : FiguresFrom::simulator_host;
  }
  const std::optional<DevboardFigures>& devboard() const { return simulator_.devboard(); }
  // The simulator's clock on the console's (ms to add to a QR time); empty without truth lines.
  std::optional<int64_t> sim_clock_offset_ms() const { return simulator_.clock_offset_ms(); }
  bool exiting() const { return !exit_.running(); }
  std::string download_status() const { return downloader_.status(now_ms_); }
  size_t parameters_to_send() const { return parameters_.to_send(); }
  const ConsoleLog& log() const { return log_; }
  // Frames with a good check whose fields were out of range, and frames of types the console has
  // no use for.
  uint32_t invalid_frames() const { return invalid_frames_; }
  uint32_t unhandled_frames() const { return unhandled_frames_; }

 private:
  void route_key(Key key, uint32_t now_ms);
  struct Receiver;
  friend struct Receiver;

  using Note = std::function<void(Severity, const std::string&)>;
  // For the parts that tell the pilot something: into the log, at the console's time.
  Note note_hook();
  void set_time(uint32_t now_ms);
  void abort(const std::string& why);
  void print_tasks();
  void on_frame(const wire::Frame& frame);
  // An ack (reason none) or a nack, already matched against the request it answers.
  void on_answer(wire::MessageType type, wire::NackReason reason, const Answer& answer);
  void on_gave_up(const wire::ResendEvent& event);
  void on_attitude(const wire::TelemetryAttitude& attitude);
  void on_rates(const wire::TelemetryRates& rates);
  // The orientation check's key: its screen, in safe with the link up.
  void open_orientation_check();
  // The orientation check's verdict: imu_orientation sent and written into the parameter file.
  std::string set_imu_orientation(int orientation);
  void on_height(const wire::TelemetryHeight& height);
  void on_system(const wire::TelemetrySystem& system);
  void on_log_status(const wire::LogStatus& status);
  void on_link_state(LinkState state);
  void open_motor_test();
  void start_logs();

  ConsoleLog& log_;
  Recordings recordings_;
  uint32_t start_ms_;
  uint32_t now_ms_;
  LinkSession link_;
  LinkState link_state_ = LinkState::waiting;
  std::string closed_because_;  // why the line closed, as first said
  TelemetryModel telemetry_;
  BatteryGauge battery_;
  DebugTextAssembler debug_text_;
  PilotControls controls_;
  ParameterSync parameters_;
  LogDownloader downloader_;
  std::optional<uint32_t> log_restart_asked_ms_;  // when s warned that a start drops the QR's lines
  PilotInput input_;
  SimulatorControls simulator_;
  ExitHandshake exit_;
  DescentWatch descent_;
  uint32_t invalid_frames_ = 0;
  uint32_t unhandled_frames_ = 0;
  std::set<uint8_t> unhandled_types_;
  StreamSession streams_;
  AutotuneSession autotune_;
  ParameterEditor editor_;
  std::string params_file_;  // the parameter file the console keeps (--params)
  bool devboard_;            // the simulator flies the devboard (Setup::devboard)
  OrientationCheck check_;
  ScreenState screens_;
  PilotRequests requests_;
  MotorBench bench_;
};

}  // namespace qrterm
