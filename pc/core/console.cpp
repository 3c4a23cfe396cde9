#include <pc/core/console.hpp>

#include <pc/core/gain_steps.hpp>
#include <pc/core/key_map.hpp>
#include <pc/core/log_room.hpp>
#include <pc/core/mode_names.hpp>
#include <pc/core/param_file.hpp>
#include <pc/core/qr_reports.hpp>
#include <pc/core/request_texts.hpp>
#include <pc/core/task_figures.hpp>

namespace qrterm {
namespace {

struct ModeKey {
  Action action;
  wire::Mode mode;
};

constexpr ModeKey kModeKeys[] = {
    {Action::mode_safe, wire::Mode::safe},
    {Action::mode_panic, wire::Mode::panic},
    {Action::mode_manual, wire::Mode::manual},
    {Action::mode_calibration, wire::Mode::calibration},
    {Action::mode_yaw_control, wire::Mode::yaw_control},
    {Action::mode_full_control, wire::Mode::full_control},
    {Action::mode_acro, wire::Mode::acro},
    {Action::mode_autotune, wire::Mode::autotune},
};

}  // namespace

// Every message from the QR, decoded, lands in one of these.
struct Console::Receiver {
  Console& console;

  void operator()(const wire::Ack& ack) {
    console.on_answer(ack.type, wire::NackReason::none, console.link_.answer(ack, console.now_ms_));
  }
  void operator()(const wire::Nack& nack) {
    console.on_answer(nack.type, nack.reason, console.link_.answer(nack, console.now_ms_));
  }
  void operator()(const wire::ParamReport& report) { console.parameters_.on_report(report); }
  void operator()(const wire::DebugText& text) {
    for (std::string& line : console.debug_text_.add(text)) console.note(Severity::qr, line);
  }
  void operator()(const wire::TelemetryAttitude& m) { console.on_attitude(m); }
  void operator()(const wire::TelemetryRates& m) { console.on_rates(m); }
  void operator()(const wire::TelemetryEngines& m) { console.telemetry_.on(m); }
  void operator()(const wire::TelemetrySetpoints& m) { console.telemetry_.on(m); }
  void operator()(const wire::TelemetrySystem& m) { console.on_system(m); }
  void operator()(const wire::TelemetryLink& m) { console.telemetry_.on(m); }
  void operator()(const wire::TelemetryTask& m) { console.telemetry_.on(m); }
  void operator()(const wire::LogStatus& m) { console.on_log_status(m); }
  void operator()(const wire::TelemetryHeight& m) { console.on_height(m); }
  void operator()(const wire::TelemetryRadio& m) { console.telemetry_.on(m); }
  void operator()(const wire::TelemetryRpm& m) { console.telemetry_.on(m); }
  void operator()(const wire::SensorLogPart& part) { console.downloader_.on_part(part, console.now_ms_); }
  void operator()(const wire::TelemetryLogPart& part) { console.downloader_.on_part(part, console.now_ms_); }
  void operator()(const wire::ObservableInfo& m) { console.streams_.on(m); }
  void operator()(const wire::ObservableText& m) { console.streams_.on(m); }
  void operator()(const wire::ObservableSamples& m) { console.streams_.on(m, console.uptime_ms() / 1000.0); }
};

Console::Console(ConsoleLog& log, ConsoleFiles files, const Setup& setup, uint32_t now_ms)
    : log_(log), recordings_(std::move(files), setup.rx_hex_part_bytes, note_hook()), start_ms_(now_ms),
      now_ms_(now_ms), link_(now_ms, setup.first_seq), battery_(setup.battery_cells),
      parameters_(setup.params, note_hook()),
      downloader_(LogDownloader::Hooks{
          [this](const wire::LogDownload& request) { link_.request(request, now_ms_); },
          [this](const wire::LogResend& request) { link_.request(request, now_ms_); },
          [this] { return link_.pending(wire::MessageType::log_resend); }, note_hook(),
          [this](const std::string& name) { return recordings_.open(name); },
          [this](const std::string& from, const std::string& to) { return recordings_.rename(from, to); }}),
      input_(setup.joystick), simulator_(setup.simulator, note_hook()), exit_(note_hook()),
      streams_(StreamSession::Hooks{
          note_hook(), [this](const std::string& name) { return recordings_.open(name); },
          [this](const std::vector<uint8_t>& ids, uint32_t index, const std::vector<double>& values) {
            autotune_.on_carried(ids, index, values);
          }}),
      autotune_(note_hook()), editor_(setup.params, setup.params_file, setup.params_file_exists),
      params_file_(setup.params_file), devboard_(setup.devboard),
      check_(OrientationCheck::Hooks{
          note_hook(),
          [this] {
            // What the QR reports, unless a change is on its way to it.
            const wire::ParamId id = wire::ParamId::imu_orientation;
            const int32_t wanted = parameters_.wanted().get(id);
            return static_cast<int>(parameters_.pending(id) ? wanted : parameters_.reported(id).value_or(wanted));
          },
          [this](size_t axis) { return simulator_.hand_tilt(axis); },
          [this](int orientation) { return set_imu_orientation(orientation); }}),
      screens_(streams_, editor_, parameters_, check_, autotune_, note_hook()),
      requests_(link_, telemetry_, controls_, input_, simulator_, note_hook()),
      bench_(MotorBench::Hooks{
          [this](uint8_t engine, uint16_t level) { return requests_.motor_test(engine, level, now_ms_); },
          [this] { requests_.mode(wire::Mode::safe, now_ms_); },
          [this](uint8_t engine, uint8_t direction) {
            link_.request(wire::EscDirection{0, engine, direction}, now_ms_);
          },
          [this] { return telemetry_.rpm.has_value(); }, [this] { screens_.show(Screen::cockpit); }, note_hook()}) {}

void Console::set_time(uint32_t now_ms) { now_ms_ = now_ms; }

Console::Note Console::note_hook() {
  return [this](Severity severity, const std::string& text) { note(severity, text); };
}

void Console::note(Severity severity, const std::string& text) { log_.add(now_ms_ - start_ms_, severity, text); }

void Console::truth_line(const std::string& line) {
  if (const std::optional<PlotModel::TrueState> truth = simulator_.on_line(line, now_ms_)) {
    streams_.plot().add_truth(uptime_ms() / 1000.0, *truth);
    if (simulator_.rotors()) bench_.rotors(*simulator_.rotors());
  }
}

uint32_t Console::log_divider() const {
  return static_cast<uint32_t>(parameters_.wanted().get(wire::ParamId::log_divider));
}

uint32_t Console::control_hz() const {
  // The QR says its rate with the observable table; before that, the default rate.
  const uint16_t said = streams_.catalog().control_hz();
  return said != 0 ? said : kDefaultControlHz;
}

uint32_t Console::telemetry_hz() const {
  return static_cast<uint32_t>(parameters_.wanted().get(wire::ParamId::telemetry_rate_hz));
}

void Console::key(Key key, uint32_t now_ms) {
  // A key that stepped no gain ends a burst of steps: its log line comes before the key's own.
  const size_t steps_before = parameters_.steps_taken();
  route_key(key, now_ms);
  if (parameters_.steps_taken() == steps_before) parameters_.end_steps();
}

void Console::route_key(Key key, uint32_t now_ms) {
  set_time(now_ms);
  // The motor test's screen takes every key but the abort and exit keys, which act as anywhere
  // (and end a test at the QR too): a key meant for the cockpit must stop an engine, not fly.
  if (screens_.screen() == Screen::motor_test && key != kKeyEscape && key != kKeyInterrupt) {
    return bench_.key(key, now_ms);
  }
  const ScreenState::Taken taken = screens_.key(key, uptime_ms() / 1000.0);
  if (taken == ScreenState::Taken::by_screen) input_.screen_key();
  if (taken != ScreenState::Taken::no) return;
  const CockpitKey pressed = input_.cockpit_key(key);
  if (pressed.action != Action::help) screens_.close_help();
  if (pressed.second_escape) {
    request_exit(now_ms);
  } else if (pressed.action == Action::none) {
    note(Severity::warning, "key " + key_name(key) + " does nothing (h: help)");
  } else {
    act(pressed.action, now_ms);
  }
}

void Console::act(Action action, uint32_t now_ms) {
  set_time(now_ms);
  if (action == Action::abort) return abort("ESC");
  if (action == Action::help) return screens_.toggle_help();
  // While exiting only an abort is still obeyed: the QR is on its way to safe already.
  if (!exit_.running()) return;
  if (action == Action::exit) return request_exit(now_ms);
  if (controls_.apply(action)) return;
  if (const GainStep* step = find_gain_step(action)) return parameters_.step(*step);
  if (simulator_.act(action)) return;
  for (const ModeKey& mode_key : kModeKeys) {
    if (mode_key.action == action) return requests_.mode(mode_key.mode, now_ms_);
  }
  switch (action) {
    case Action::height_hold: return requests_.toggle_height_hold(now_ms_);
    case Action::log_start: return start_logs();
    case Action::log_stop: link_.request(wire::LogStop{}, now_ms_); break;
    case Action::log_download:
      downloader_.start(telemetry_.log_status, now_ms_);
      streams_.download_running(downloader_.active());
      break;
    case Action::params_read: parameters_.read_back(link_, now_ms_); break;
    case Action::tasks_print: print_tasks(); break;
    case Action::motor_test: open_motor_test(); break;
    case Action::orientation_check: open_orientation_check(); break;
    case Action::lift_hover: {
      const Notice said = lift_to_hover(controls_, telemetry_.height ? telemetry_.height->hover_lift : 0);
      note(said.severity, said.text);
      break;
    }
    default: break;
  }
}

// A start empties the QR's log: one that holds lines is started only by a second s within
// kLogRestartConfirmMs (a log now lasts minutes, and one s too many lost it).
void Console::start_logs() {
  const std::string drops = telemetry_.log_status
                                ? log_restart_warning(*telemetry_.log_status, log_divider(), control_hz())
                                : "";
  const bool confirmed = log_restart_asked_ms_ && now_ms_ - *log_restart_asked_ms_ <= kLogRestartConfirmMs;
  if (!drops.empty() && !confirmed) {
    log_restart_asked_ms_ = now_ms_;
    return note(Severity::warning, drops);
  }
  log_restart_asked_ms_.reset();
  link_.request(wire::LogStart{0, wire::kLogSensor | wire::kLogTelemetry}, now_ms_);
  if (telemetry_.log_status)
    note(Severity::info, "QR log: " + log_room_text(*telemetry_.log_status, log_divider(), control_hz()));
}

// The bench is for a QR in safe, on a live link: there is nothing to test otherwise, and a key
// that opened it in flight would leave the pilot on a screen that takes every key.
void Console::open_motor_test() {
  if (link_state_ != LinkState::up || !telemetry_.attitude || telemetry_.attitude->mode != wire::Mode::safe) {
    return note(Severity::warning, "the motor test opens in safe only, with the link up (0: safe)");
  }
  screens_.show(Screen::motor_test);
  bench_.open();
}

void Console::abort(const std::string& why) { requests_.abort(why, link_state_ == LinkState::closed, now_ms_); }

void Console::print_tasks() {
  if (telemetry_.tasks.empty()) return note(Severity::warning, "no task figures from the QR yet");
  for (const std::string& line : task_figure_lines(telemetry_.tasks, figures_from(), devboard(), control_hz()))
    note(Severity::info, line);
}

void Console::joystick_moved(const Sticks& sticks, bool position_known, uint32_t now_ms) {
  set_time(now_ms);
  controls_.set_joystick(sticks);
  input_.joystick_moved(position_known);
}

void Console::joystick_fire(uint32_t now_ms) {
  set_time(now_ms);
  abort("joystick fire button");
}

void Console::joystick_lost(uint32_t now_ms) {
  set_time(now_ms);
  if (!input_.joystick_lost()) return;
  controls_.set_joystick(Sticks{});
  const bool may_fly = !telemetry_.attitude || (telemetry_.attitude->mode != wire::Mode::safe);
  if (may_fly) {
    abort("joystick lost");
  } else {
    note(Severity::warning, "joystick lost: flight modes refused until it is back");
  }
}

void Console::joystick_back(uint32_t now_ms) {
  set_time(now_ms);
  if (!input_.joystick_back()) return;
  note(Severity::info, "joystick back: centre it and close the throttle before flying");
}

void Console::receive(const uint8_t* data, size_t count, uint32_t now_ms) {
  set_time(now_ms);
  recordings_.received(now_ms_ - start_ms_, data, count);
  link_.receive(data, count, now_ms, [this](const wire::Frame& frame) { on_frame(frame); });
}

void Console::on_frame(const wire::Frame& frame) {
  // Before the frame is handled: a log part is kept only when no damage surrounds it.
  const wire::LinkCounters& seen = link_.counters();
  downloader_.frame_accepted(seen.bytes_skipped + seen.check_failures, now_ms_);
  Receiver receiver{*this};
  const wire::DispatchResult result = wire::dispatch(frame, receiver);
  if (result == wire::DispatchResult::invalid_payload) ++invalid_frames_;
  if (result != wire::DispatchResult::not_handled) return;
  // A message of the wire this console has no use for: a newer firmware, or a gap here.
  ++unhandled_frames_;
  const uint8_t type = static_cast<uint8_t>(frame.type);
  if (!unhandled_types_.insert(type).second) return;
  note(Severity::warning,
       std::string("the QR sends ") + wire::message_name(frame.type) + ", which this console ignores");
}

void Console::on_attitude(const wire::TelemetryAttitude& attitude) {
  const std::optional<wire::TelemetryAttitude> before = telemetry_.attitude;
  telemetry_.on(attitude);
  bench_.mode(attitude.mode);
  check_.on_mode(attitude.mode);
  autotune_.on_attitude(attitude, telemetry_hz(), control_hz(), parameters_.wanted(), now_ms_);
  for (const Notice& notice : attitude_notices(before, attitude, requests_.panic_asked_by(now_ms_)))
    note(notice.severity, notice.text);
  recordings_.telemetry_row(now_ms_ - start_ms_, telemetry_, requests_.last_control());
}

void Console::on_rates(const wire::TelemetryRates& rates) {
  telemetry_.on(rates);
  check_.on_rates(rates, telemetry_hz());
}

void Console::open_orientation_check() {
  if (link_state_ != LinkState::up || !telemetry_.attitude || telemetry_.attitude->mode != wire::Mode::safe) {
    return note(Severity::warning, "the orientation check runs in safe with the link up: 0 first");
  }
  screens_.show_orientation_check();
  note(Severity::info,
       std::string("orientation check: imu_orientation ") + std::to_string(check_.in_force()) +
           " in force; Enter starts each step" +
           (simulator_.present() ? " (the simulator's hand tilts the QR)" : ", then move the QR by hand"));
}

std::string Console::set_imu_orientation(int orientation) {
  const wire::ParamId id = wire::ParamId::imu_orientation;
  if (parameters_.set(id, orientation) != wire::NackReason::none)
    return "imu_orientation " + std::to_string(orientation) + " refused";
  const std::string failed = write_param_to_file(params_file_, id, orientation);
  if (!failed.empty()) return "imu_orientation = " + std::to_string(orientation) + " sent, but not kept: " + failed;
  editor_.file_written(params_file_, id, orientation);
  return "";
}

void Console::on_height(const wire::TelemetryHeight& height) {
  telemetry_.on(height);
  const std::string warning = descent_.on_height(height, telemetry_, simulator_.present(), now_ms_);
  if (!warning.empty()) note(Severity::error, warning);
}

void Console::on_system(const wire::TelemetrySystem& system) {
  telemetry_.on(system);
  const wire::ParameterValues& p = parameters_.wanted();
  const wire::TelemetryEngines engines = telemetry_.engines.value_or(wire::TelemetryEngines{});
  battery_.on_report(system.battery_mv, engines.engine, static_cast<uint16_t>(p.get(wire::ParamId::battery_sag_mv)),
                     uptime_ms() / 1000.0);
  const std::string warning = battery_.notice(static_cast<uint16_t>(p.get(wire::ParamId::battery_panic_mv)));
  if (!warning.empty()) note(Severity::warning, warning);
}

std::optional<BatteryReading> Console::battery() const {
  return battery_.reading(static_cast<uint16_t>(parameters_.wanted().get(wire::ParamId::battery_panic_mv)));
}

std::optional<double> Console::sinking_m_s() const {
  if (link_state_ != LinkState::up) return std::nullopt;
  return descent_.speed_m_s();
}

void Console::on_log_status(const wire::LogStatus& status) {
  const std::optional<wire::LogStatus> before = telemetry_.log_status;
  telemetry_.on(status);
  for (const Notice& notice : log_status_notices(before, status, log_divider(), control_hz())) {
    note(notice.severity, notice.text);
  }
}

void Console::on_answer(wire::MessageType type, wire::NackReason reason, const Answer& answer) {
  // A stale or unexpected answer (to a replaced request, or a repeat of one already taken) says
  // nothing about what is in force now.
  if (answer.match != wire::AnswerMatch::matched) return;
  const bool refused = reason != wire::NackReason::none;
  if (type == wire::MessageType::exit) return exit_.on_answer(reason);
  if (type == wire::MessageType::log_download) {
    if (refused) downloader_.on_nack(reason);
    return;  // accepted: the parts say the rest
  }
  // Refused (the QR's queue of parts to resend was full): the parts are asked for again later.
  if (type == wire::MessageType::log_resend) return;
  if (type == wire::MessageType::stream_request || type == wire::MessageType::observable_get) {
    return streams_.on_answer(type, reason, telemetry_hz());
  }
  if (type == wire::MessageType::mode_change) return requests_.on_mode_answer(reason);
  if (type == wire::MessageType::motor_test) return bench_.answer(reason);
  if (refused) {
    note(Severity::warning, std::string("QR refused the ") + request_what(type) + ": " + reason_text(reason));
  } else if (request_accepted(type) != nullptr) {
    note(Severity::info, request_accepted(type));
  }
}

void Console::on_gave_up(const wire::ResendEvent& event) {
  if (event.type == wire::MessageType::exit) return exit_.unanswered();
  // A log_download that went unanswered is asked for again by the downloader once the line is
  // quiet; it gives up by itself when nothing comes.
  if (event.type == wire::MessageType::log_download || event.type == wire::MessageType::log_resend) return;
  if (event.type == wire::MessageType::observable_get) return streams_.table_unanswered();
  if (event.type == wire::MessageType::motor_test) return bench_.unanswered();
  if (event.type == wire::MessageType::stream_request) streams_.stream_unanswered();
  note(Severity::error, std::string("no answer from the QR to the ") + request_what(event.type) + " request (" +
                            std::to_string(wire::kMaxSends) + " sends)");
}

void Console::on_link_state(LinkState state) {
  const LinkState before = link_state_;
  link_state_ = state;
  if (state == LinkState::up) {
    note(Severity::info, before == LinkState::lost ? "link back" : "link up");
    // The QR may have restarted with its defaults: every parameter goes up again, and the
    // observable table and the plot's stream are asked for again.
    parameters_.send_all();
    streams_.link_up();
    battery_.link_up();
  } else if (state == LinkState::lost) {
    note(Severity::error,
         "LINK LOST: no valid frame from the QR for " + std::to_string(kLinkLostAfterMs / 1000) + " s");
  }
}

void Console::line_closed(const std::string& why, uint32_t now_ms) {
  set_time(now_ms);
  if (link_state_ == LinkState::closed) {
    if (why != closed_because_) note(Severity::error, "and: " + why);  // the simulator's end after its line's
    closed_because_ = why;
    return;
  }
  link_.close();
  link_state_ = LinkState::closed;
  closed_because_ = why;
  // A QR that was flying is on its own now: tell the pilot what it does.
  const bool flying = telemetry_.attitude && wire::flies(telemetry_.attitude->mode);
  note(Severity::error, "LINK LOST: " + why +
                            (flying ? std::string("; the QR was in ") + mode_name(telemetry_.attitude->mode) +
                                          ": it panics by itself after the link timeout (safety rule 7)"
                                    : std::string()));
  exit_.line_closed();
}

void Console::request_exit(uint32_t now_ms) {
  set_time(now_ms);
  parameters_.end_steps();
  const LinkState state = link_.state(now_ms);
  if (exit_.request(state != LinkState::closed && link_.ever_up(), now_ms)) link_.request(wire::Exit{}, now_ms);
}

void Console::tick(uint32_t now_ms) {
  set_time(now_ms);
  if (exit_.done()) return;

  parameters_.settle_steps(now_ms);
  const LinkState state = link_.state(now_ms);
  if (state != link_state_) on_link_state(state);

  if (state != LinkState::closed && link_.control_due(now_ms)) requests_.send_control(now_ms);
  link_.poll(now_ms, [this](const wire::ResendEvent& event) { on_gave_up(event); });

  if (state == LinkState::up && exit_.running()) {
    parameters_.tick(link_, now_ms);
    autotune_.tick(streams_, now_ms);
    streams_.tick(link_, now_ms);
  }

  downloader_.tick(now_ms);
  // A download has the line to itself but for a lowered plot stream (docs/protocol.md section 13.6).
  streams_.download_running(downloader_.active());
  bench_.tick(now_ms);
  exit_.tick(now_ms);
}

}  // namespace qrterm
