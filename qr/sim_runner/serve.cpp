#include <qr/sim_runner/serve.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <qr/boards/sim/devboard_qr.hpp>
#include <qr/boards/sim/flying_qr.hpp>
#include <qr/sim_runner/serve_clock.hpp>
#include <qr/sim_runner/serve_output.hpp>
#include <qr/sim_runner/serve_radio.hpp>
#include <qr/sim_runner/serve_reports.hpp>
#include <qr/sim_runner/truth_channel.hpp>

namespace qrsim {
namespace {

// SIGINT and SIGTERM end serve mode within a second, whatever it is doing. The handlers are
// installed without SA_RESTART, so a call that blocks (a write to a full stderr pipe, a sleep)
// returns at once and every loop here sees g_stop within a control period. Not every wait is
// serve mode's own (the devboard's round trip waits up to 10 s for a hung QEMU), so the first
// signal also arms a backstop: if the process is still there kBackstopNs later, it ends with the
// same clean status. QEMU goes with it (it dies with its parent, devboard_process.cpp).
volatile sig_atomic_t g_stop = 0;
volatile sig_atomic_t g_backstop_armed = 0;
timer_t g_backstop{};
constexpr long kBackstopNs = 500000000;

void on_backstop(int) { _exit(0); }

void on_stop_signal(int) {
  if (g_stop == 0 && g_backstop_armed != 0) {
    itimerspec when{};
    when.it_value.tv_nsec = kBackstopNs;
    timer_settime(g_backstop, 0, &when, nullptr);  // async-signal-safe
  }
  g_stop = 1;
}

void catch_stop_signals() {
  struct sigaction action {};
  sigemptyset(&action.sa_mask);
  action.sa_handler = on_backstop;
  sigaction(SIGALRM, &action, nullptr);
  sigevent event{};
  event.sigev_notify = SIGEV_SIGNAL;
  event.sigev_signo = SIGALRM;
  g_backstop_armed = timer_create(CLOCK_MONOTONIC, &event, &g_backstop) == 0 ? 1 : 0;
  action.sa_handler = on_stop_signal;
  action.sa_flags = 0;  // no SA_RESTART: a blocked call returns EINTR
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  signal(SIGPIPE, SIG_IGN);
}

uint64_t wall_now_us() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<uint64_t>(now.tv_sec) * 1000000u + static_cast<uint64_t>(now.tv_nsec) / 1000u;
}

// Sleeps until the monotonic clock reads `wall_us`; false when a signal asked to stop meanwhile.
bool sleep_until(uint64_t wall_us) {
  const timespec until{static_cast<time_t>(wall_us / 1000000u), static_cast<long>(wall_us % 1000000u) * 1000};
  while (g_stop == 0) {
    if (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &until, nullptr) != EINTR) break;
  }
  return g_stop == 0;
}

// The master side of a fresh pseudo terminal, in raw mode; prints the slave's path. The slave is
// opened once here and kept open, so the master never sees a hang-up between console sessions
// and the line discipline is raw (no echo, no CR/LF mangling) before any console opens it.
bool open_pty(int& master, int& slave_keep) {
  master = posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) return false;
  const char* name = ptsname(master);
  if (name == nullptr) return false;
  slave_keep = open(name, O_RDWR | O_NOCTTY);
  if (slave_keep < 0) return false;
  termios t{};
  if (tcgetattr(slave_keep, &t) != 0) return false;
  cfmakeraw(&t);
  cfsetispeed(&t, B115200);
  cfsetospeed(&t, B115200);
  if (tcsetattr(slave_keep, TCSANOW, &t) != 0) return false;
  std::printf("qrsim: serial on %s\n", name);
  std::fflush(stdout);
  return true;
}

void set_nonblocking(int fd) { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK); }

// Bytes the QR has sent that have arrived at the console's end go out on the pty, as far as the
// pty takes them now (serve_output.hpp).
void forward_to_console(SimBoard& board, ServeOutput& out, int out_fd) {
  uint8_t byte = 0;
  while (board.pc_receive(byte)) out.put(byte);
  out.write_to(out_fd);
}

// The firmware stops as soon as its last bytes (the exit's ack) are in the board's transmit
// buffer, up to 32 bytes or 3 ms before they are through the line. The line runs on until they
// are, and a pty stays open a little longer (`linger`): its hang-up would discard what the
// console has not read yet, and the console would see LINK LOST and an unconfirmed exit.
void let_the_line_finish(FlyingQr& qr, ServeOutput& out, int out_fd, bool linger) {
  constexpr int kMaxPeriods = 100;     // 32 bytes take 3 periods; this bounds a stuck reader
  constexpr int kLingerPeriods = 200;  // for the console to read the last bytes
  for (int i = 0; i < kMaxPeriods && (qr.board().pc_bytes_pending() || out.queued_bytes() > 0) && g_stop == 0; ++i) {
    qr.world().advance_to(qr.world().now_us() + qr::kPeriodUs);
    forward_to_console(qr.board(), out, out_fd);
    if (!qr.board().pc_bytes_pending()) {
      out.finish();
      out.write_to(out_fd);
    }
    usleep(qr::kPeriodUs);
  }
  for (int i = 0; linger && i < kLingerPeriods && g_stop == 0; ++i) usleep(qr::kPeriodUs);
}

// The side channel (--truth-fd): command lines in, truth lines and error lines out. Writes never
// block the flight: a line the reader has no room for is dropped.
class TruthChannel {
 public:
  explicit TruthChannel(int fd) : fd_(fd) {
    if (fd_ >= 0) set_nonblocking(fd_);
  }
  bool open() const { return fd_ >= 0; }

  void send(const std::string& line) {
    if (fd_ < 0) return;
    const ssize_t n = write(fd_, line.data(), line.size());
    if (n < 0 && errno != EAGAIN && errno != EINTR) fd_ = -1;  // the reader has gone
  }

  // Reads what has arrived; a push found starts now (the latest push replaces the one acting), a
  // reset sets the vehicle down upright at once and a turn starts a hand turning it (both refused
  // while an engine runs: a hand in the rotors).
  // The radio's switches move the serve-mode radio's (`radio`, null without --rc crsf).
  void poll_commands(FlyingQr& qr, ServeRadio* radio, sim::Vec3& torque, uint64_t& until_us) {
    if (fd_ < 0) return;
    char buffer[256];
    for (;;) {
      const ssize_t n = read(fd_, buffer, sizeof buffer);
      if (n == 0) {
        fd_ = -1;
        return;
      }
      if (n < 0) return;  // EAGAIN: nothing more now
      for (ssize_t i = 0; i < n; ++i) {
        if (buffer[i] != '\n') {
          if (pending_.size() < 200) pending_ += buffer[i];
          continue;
        }
        TruthCommand command;
        std::string error;
        if (!parse_truth_command(pending_, command, error)) {
          send("error " + error + "\n");
        } else if (command.kind == TruthCommand::Kind::radio_arm || command.kind == TruthCommand::Kind::radio_off) {
          move_switches(command, qr.world().now_us(), radio);
        } else if (command.kind == TruthCommand::Kind::push) {
          torque = command.torque;
          until_us = qr.world().now_us() + static_cast<uint64_t>(std::llround(command.seconds * 1e6));
          send("ok push\n");
        } else if (command.kind == TruthCommand::Kind::turn) {
          const std::string refused = qr.world().start_hand_turn(command.turn);
          send(refused.empty() ? "ok turn\n" : "error turn: " + refused + "\n");
        } else if (command.kind == TruthCommand::Kind::tilt) {
          const std::string refused = qr.world().start_hand_tilt(command.tilt);
          send(refused.empty() ? "ok tilt\n" : "error tilt: " + refused + "\n");
        } else if (!qr.board().engines().all_zero()) {
          send("error reset: the engines are running (safe first)\n");
        } else if (qr.world().held()) {
          send("error reset: " + qr.world().hand_refused() + "\n");
        } else {
          qr.world().plant().set_state(reset_state(qr.world().plant().state()));
          send("ok reset\n");
        }
        pending_.clear();
      }
    }
  }

 private:
  void move_switches(const TruthCommand& command, uint64_t now_us, ServeRadio* radio) {
    if (radio == nullptr) return send("error radio: this simulator has no radio (qrsim --serve --rc crsf)\n");
    if (command.kind == TruthCommand::Kind::radio_off) {
      radio->transmitter().disarm();
      return send("ok radio off\n");
    }
    radio->transmitter().arm(command.mode, now_us);
    send(std::string("ok radio arm ") + wire::mode_key(command.mode) + "\n");
  }

  int fd_;
  std::string pending_;
};

// The console's end of the QR's serial line: a pseudo terminal, or stdin and stdout.
struct ConsoleLine {
  int in_fd = STDIN_FILENO;
  int out_fd = STDOUT_FILENO;
  int slave_keep = -1;  // the pty's slave, open for as long as serve mode runs (open_pty)
};

bool open_console_line(bool stdio, ConsoleLine& line) {
  if (!stdio) {
    int master = -1;
    if (!open_pty(master, line.slave_keep)) return false;
    line.in_fd = line.out_fd = master;
  }
  // Neither way waits: a console that does not read must not stop the world (serve_output.hpp).
  set_nonblocking(line.in_fd);
  set_nonblocking(line.out_fd);
  return true;
}

// The host build, or the cross-compiled firmware on the emulated devboard; null when the devboard
// would not start (said on stderr).
std::unique_ptr<FlyingQr> make_flying_qr(const ServeOptions& options) {
  std::unique_ptr<FlyingQr> qr;
  if (options.devboard_elf.empty()) {
    qr = std::make_unique<HostQr>(options.vehicle, sim::WorldConfig{.seed = options.seed});
  } else {
    qr = std::make_unique<DevboardQr>(options.vehicle, sim::WorldConfig{.seed = options.seed}, options.devboard_elf,
                                      options.devboard_core_mhz);
    if (!qr->error().empty()) {
      std::fprintf(stderr, "qrsim: devboard: %s\n", qr->error().c_str());
      return nullptr;
    }
  }
  if (options.sensor_drivers) qr->board().use_sensor_drivers();
  // The simulated motors have the pole pairs the QR's motor_poles parameter says by default.
  if (options.dshot) qr->board().use_dshot(static_cast<uint8_t>(qr->parameters().get(wire::ParamId::motor_poles) / 2));
  return qr;
}

// One run of serve mode: the QR, the console's line, the side channel and the radio, taken a
// control period at a time on the wall clock.
class ServeSession {
 public:
  ServeSession(const ServeOptions& options, FlyingQr& qr, const ConsoleLine& line)
      : options_(options), qr_(qr), line_(line),
        stop_us_(options.seconds > 0 ? static_cast<uint64_t>(std::llround(options.seconds * 1e6)) : 0),
        truth_(options.truth_fd), devboard_(dynamic_cast<const DevboardQr*>(&qr)) {
    if (options.radio) radio_ = std::make_unique<ServeRadio>();
  }

  // Until the firmware stops, a signal asks to, or the time is up.
  void run() {
    // The kicks follow the wall clock from here (serve_clock.hpp); the board itself keeps
    // simulated time only.
    clock_.start(wall_now_us(), qr_.world().now_us());
    while (g_stop == 0 && period()) {
    }
    reports_.finish(out_);
  }

 private:
  // One kick; false when serve mode ends.
  bool period() {
    const uint64_t kick_us = qr_.board().kick_time_us(qr_.board().kicks());
    if (!sleep_until(clock_.due_us(kick_us))) return false;
    const uint64_t wall_us = wall_now_us();
    const uint64_t paused_us = clock_.begin(kick_us, wall_us);
    if (paused_us > 0) reports_.paused(paused_us, qr_.world().now_us());

    take_console_bytes();
    forward_to_console(qr_.board(), out_, line_.out_fd);
    if (truth_.open()) take_side_channel_commands();
    if (radio_) radio_->step(qr_.world().now_us(), qr_.board());
    if (!qr_.tick()) {  // the physics to the kick, then the firmware's tick
      if (!qr_.error().empty()) std::fprintf(stderr, "qrsim: devboard: %s\n", qr_.error().c_str());
      else let_the_line_finish(qr_, out_, line_.out_fd, /*linger=*/!options_.stdio);
      return false;
    }

    const uint64_t now = qr_.world().now_us();
    reports_.step(out_, wall_us, now);
    if (truth_.open() && now >= next_truth_us_) {
      next_truth_us_ = now - now % 20000 + 20000;
      truth_.send(truth_line(static_cast<double>(now) * 1e-6, qr_.world().plant()));
    }
    if (truth_.open() && devboard_ != nullptr && now >= next_devboard_us_) {
      next_devboard_us_ = now - now % 1000000 + 1000000;
      const InstructionStats& tick = devboard_->instructions().back();  // the last row: the whole tick
      if (tick.reported) {
        truth_.send(
            devboard_line(static_cast<double>(now) * 1e-6, devboard_->core_mhz(), tick.mean(), tick.max, tick.runs));
      }
    }
    if (options_.status && now >= next_status_us_) {
      next_status_us_ += 1000000;
      print_status(now);
    }
    return stop_us_ == 0 || now < stop_us_;
  }

  // Bytes from the console go onto the line now; the line delivers them at 115200 baud, in order.
  void take_console_bytes() {
    uint8_t buffer[256];
    while (input_open_) {
      const ssize_t n = read(line_.in_fd, buffer, sizeof buffer);
      if (n <= 0) {
        if (n == 0 && options_.stdio) input_open_ = false;  // stdin closed: keep flying, silent
        return;                                             // EAGAIN, or EIO: no console attached
      }
      for (ssize_t i = 0; i < n; ++i) {
        qr_.board().pc_send(buffer[i]);
        if (radio_) radio_->hear(buffer[i], qr_.world().now_us());
      }
    }
  }

  // A push acts on the plant until its time is up; then the disturbance is taken off once.
  void take_side_channel_commands() {
    const uint64_t before = qr_.world().now_us();
    truth_.poll_commands(qr_, radio_.get(), push_torque_, push_until_us_);
    const bool push_now = before < push_until_us_;
    if (push_now || pushing_) qr_.world().plant().set_disturbance(push_now ? push_torque_ : sim::Vec3{}, sim::Vec3{});
    pushing_ = push_now;
  }

  // --status: the flight and the host's pace once a second of simulated time.
  void print_status(uint64_t now) {
    const sim::PlantState& s = qr_.world().plant().state();
    const sim::Euler e = sim::to_euler(s.attitude);
    const ServeTiming& timing = clock_.timing();
    std::fprintf(stderr,
                 "qrsim: t=%.0fs mode=%u height=%.2fm roll=%.1f pitch=%.1f yaw=%.1f deg battery=%.2fV misses=%u "
                 "host: late_wakeups=%llu behind=%llu max_behind_ms=%.1f pauses=%llu paused_s=%.2f "
                 "line: frames_dropped=%llu\n",
                 static_cast<double>(now) * 1e-6, static_cast<unsigned>(qr_.view().mode), -s.position.z,
                 e.roll * 57.29578, e.pitch * 57.29578, e.yaw * 57.29578, qr_.world().plant().battery_volts(),
                 static_cast<unsigned>(qr_.view().deadline_misses),
                 static_cast<unsigned long long>(timing.late_wakeups),
                 static_cast<unsigned long long>(timing.behind_kicks), static_cast<double>(timing.max_behind_us) * 1e-3,
                 static_cast<unsigned long long>(timing.pauses), static_cast<double>(timing.paused_us) * 1e-6,
                 static_cast<unsigned long long>(out_.frames_dropped()));
    if (!radio_) return;
    std::fprintf(stderr, "qrsim: radio %s, arm switch %s, mode switch %s, %u RC frames sent\n",
                 radio_->sending(now) ? "sending" : "silent (no control frames from the console)",
                 radio_->transmitter().arm_switch_on(now) ? "on" : "off",
                 wire::mode_key(radio_->transmitter().mode_switch()), radio_->transmitter().rc_frames());
  }

  const ServeOptions& options_;
  FlyingQr& qr_;
  ConsoleLine line_;
  uint64_t stop_us_;  // 0: no end but the firmware's or a signal
  TruthChannel truth_;
  std::unique_ptr<ServeRadio> radio_;  // --rc crsf
  ServeOutput out_;
  ServeReports reports_;
  ServeClock clock_{qr::kPeriodUs};
  bool input_open_ = true;
  uint64_t next_status_us_ = 1000000;
  uint64_t next_truth_us_ = 0;
  const DevboardQr* devboard_;  // null: the host build flies; else its figures once a second
  uint64_t next_devboard_us_ = 1000000;
  sim::Vec3 push_torque_;
  uint64_t push_until_us_ = 0;
  bool pushing_ = false;  // a push's disturbance is on the plant
};

}  // namespace

int serve(const ServeOptions& options) {
  catch_stop_signals();
  ConsoleLine line;
  if (!open_console_line(options.stdio, line)) {
    std::perror("qrsim: pseudo terminal");
    return 1;
  }
  const std::unique_ptr<FlyingQr> qr = make_flying_qr(options);
  if (!qr) return 1;
  ServeSession session(options, *qr, line);
  session.run();
  if (line.slave_keep >= 0) close(line.slave_keep);
  return 0;
}

}  // namespace qrsim
