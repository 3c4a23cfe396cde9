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
#include <string>

#include <qr/boards/sim/devboard_qr.hpp>
#include <qr/boards/sim/flying_qr.hpp>
#include <qr/sim_runner/serve_clock.hpp>
#include <qr/sim_runner/serve_output.hpp>
#include <qr/sim_runner/serve_radio.hpp>
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

// What the console's log gets to know (qrterm logs qrsim's stderr lines as "sim: ..."): a host
// that stalled the world, and frames dropped because nobody read the line. At most a line a
// second of each, so a host that stalls often, or a console that never reads, cannot flood it.
class ServeReports {
 public:
  static constexpr uint64_t kQuietUs = 1000000;

  void paused(uint64_t pause_us, uint64_t sim_us) {
    if (pauses_ == 0) since_sim_us_ = sim_us;
    ++pauses_;
    paused_us_ += pause_us;
    longest_us_ = pause_us > longest_us_ ? pause_us : longest_us_;
  }

  // Once a control period: says what is due. `wall_us` for the stalls' rate, `sim_us` for the
  // drops' (a line read again is one that has dropped nothing for a second of the world's time).
  void step(const ServeOutput& out, uint64_t wall_us, uint64_t sim_us) {
    if (pauses_ > 0 && (!stall_said_ || wall_us - stall_said_us_ >= kQuietUs)) {
      if (pauses_ == 1) {
        std::fprintf(stderr,
                     "qrsim: the host stalled for %.2f s at t=%.3f s: the world paused there and went on "
                     "(simulated time skips nothing; the console's bytes reach the QR in order)\n",
                     static_cast<double>(paused_us_) * 1e-6, static_cast<double>(since_sim_us_) * 1e-6);
      } else {
        std::fprintf(stderr,
                     "qrsim: the host stalled %llu times since t=%.3f s: the world paused %.2f s in all, the longest "
                     "%.2f s\n",
                     static_cast<unsigned long long>(pauses_), static_cast<double>(since_sim_us_) * 1e-6,
                     static_cast<double>(paused_us_) * 1e-6, static_cast<double>(longest_us_) * 1e-6);
      }
      stall_said_ = true;
      stall_said_us_ = wall_us;
      pauses_ = paused_us_ = longest_us_ = 0;
    }
    const uint64_t dropped = out.frames_dropped();
    if (dropped > frames_seen_) {
      if (!dropping_) {
        std::fprintf(stderr,
                     "qrsim: the console does not read the serial line: the QR's oldest frames are dropped, "
                     "whole, and the world flies on\n");
        dropping_ = true;
        episode_frames_ = frames_seen_;
        episode_bytes_ = bytes_seen_;
      }
      frames_seen_ = dropped;
      bytes_seen_ = out.bytes_dropped();
      last_drop_sim_us_ = sim_us;
    } else if (dropping_ && sim_us - last_drop_sim_us_ >= kQuietUs) {
      std::fprintf(stderr,
                   "qrsim: the console reads the serial line again: %llu frames (%llu bytes) dropped meanwhile\n",
                   static_cast<unsigned long long>(frames_seen_ - episode_frames_),
                   static_cast<unsigned long long>(bytes_seen_ - episode_bytes_));
      dropping_ = false;
    }
  }

  void finish(const ServeOutput& out) const {
    if (out.frames_dropped() == 0) return;
    std::fprintf(
        stderr, "qrsim: %llu of the QR's frames (%llu bytes) dropped in all while nobody read the serial line\n",
        static_cast<unsigned long long>(out.frames_dropped()), static_cast<unsigned long long>(out.bytes_dropped()));
  }

 private:
  uint64_t pauses_ = 0, paused_us_ = 0, longest_us_ = 0, since_sim_us_ = 0;
  bool stall_said_ = false;
  uint64_t stall_said_us_ = 0;
  bool dropping_ = false;
  uint64_t frames_seen_ = 0, bytes_seen_ = 0, episode_frames_ = 0, episode_bytes_ = 0, last_drop_sim_us_ = 0;
};

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
        } else if (!qr.board().engines().all_zero()) {
          send("error reset: the engines are running (safe first)\n");
        } else if (qr.world().held()) {
          send("error reset: a turn is under way\n");
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

}  // namespace

int serve(const ServeOptions& options) {
  catch_stop_signals();
  int in_fd = STDIN_FILENO, out_fd = STDOUT_FILENO, slave_keep = -1;
  if (!options.stdio) {
    int master = -1;
    if (!open_pty(master, slave_keep)) {
      std::perror("qrsim: pseudo terminal");
      return 1;
    }
    in_fd = out_fd = master;
  }
  // Neither way waits: a console that does not read must not stop the world (serve_output.hpp).
  set_nonblocking(in_fd);
  set_nonblocking(out_fd);

  std::unique_ptr<FlyingQr> qr;
  if (options.devboard_elf.empty()) {
    qr = std::make_unique<HostQr>(options.vehicle, sim::WorldConfig{.seed = options.seed});
  } else {
    qr = std::make_unique<DevboardQr>(options.vehicle, sim::WorldConfig{.seed = options.seed}, options.devboard_elf,
                                      options.devboard_core_mhz);
    if (!qr->error().empty()) {
      std::fprintf(stderr, "qrsim: devboard: %s\n", qr->error().c_str());
      return 1;
    }
  }
  // The simulated motors have the pole pairs the QR's motor_poles parameter says by default.
  if (options.dshot) qr->board().use_dshot(static_cast<uint8_t>(qr->parameters().get(wire::ParamId::motor_poles) / 2));
  const uint64_t stop_us = options.seconds > 0 ? static_cast<uint64_t>(std::llround(options.seconds * 1e6)) : 0;
  uint64_t next_status_us = 1000000;
  uint8_t buffer[256];
  bool input_open = true;
  TruthChannel truth(options.truth_fd);
  uint64_t next_truth_us = 0;
  sim::Vec3 push_torque;
  uint64_t push_until_us = 0;
  bool pushing = false;
  std::unique_ptr<ServeRadio> radio;
  if (options.radio) radio = std::make_unique<ServeRadio>();
  ServeOutput out;
  ServeReports reports;
  // The kicks follow the wall clock from here (serve_clock.hpp); the board itself keeps
  // simulated time only.
  ServeClock clock(qr::kPeriodUs);
  clock.start(wall_now_us(), qr->world().now_us());

  while (g_stop == 0) {
    const uint64_t kick_us = qr->board().kick_time_us(qr->board().kicks());
    if (!sleep_until(clock.due_us(kick_us))) break;
    const uint64_t wall_us = wall_now_us();
    const uint64_t paused_us = clock.begin(kick_us, wall_us);
    if (paused_us > 0) reports.paused(paused_us, qr->world().now_us());

    // Bytes from the console go onto the line now; the line delivers them at 115200 baud, in order.
    while (input_open) {
      const ssize_t n = read(in_fd, buffer, sizeof buffer);
      if (n > 0) {
        for (ssize_t i = 0; i < n; ++i) {
          qr->board().pc_send(buffer[i]);
          if (radio) radio->hear(buffer[i], qr->world().now_us());
        }
      } else {
        if (n == 0 && options.stdio) input_open = false;  // stdin closed: keep flying, silent
        break;                                            // EAGAIN, or EIO: no console attached
      }
    }
    forward_to_console(qr->board(), out, out_fd);

    if (truth.open()) {
      const uint64_t before = qr->world().now_us();
      truth.poll_commands(*qr, radio.get(), push_torque, push_until_us);
      const bool push_now = before < push_until_us;
      if (push_now || pushing) qr->world().plant().set_disturbance(push_now ? push_torque : sim::Vec3{}, sim::Vec3{});
      pushing = push_now;
    }

    if (radio) radio->step(qr->world().now_us(), qr->board());
    if (!qr->tick()) {  // the physics to the kick, then the firmware's tick
      if (!qr->error().empty()) std::fprintf(stderr, "qrsim: devboard: %s\n", qr->error().c_str());
      else let_the_line_finish(*qr, out, out_fd, /*linger=*/!options.stdio);
      break;
    }

    const uint64_t now = qr->world().now_us();
    reports.step(out, wall_us, now);
    if (truth.open() && now >= next_truth_us) {
      next_truth_us = now - now % 20000 + 20000;
      truth.send(truth_line(static_cast<double>(now) * 1e-6, qr->world().plant().state()));
    }
    if (options.status && now >= next_status_us) {
      next_status_us += 1000000;
      const sim::PlantState& s = qr->world().plant().state();
      const sim::Euler e = sim::to_euler(s.attitude);
      const ServeTiming& timing = clock.timing();
      std::fprintf(stderr,
                   "qrsim: t=%.0fs mode=%u height=%.2fm roll=%.1f pitch=%.1f yaw=%.1f deg battery=%.2fV misses=%u "
                   "host: late_wakeups=%llu behind=%llu max_behind_ms=%.1f pauses=%llu paused_s=%.2f "
                   "line: frames_dropped=%llu\n",
                   static_cast<double>(now) * 1e-6, static_cast<unsigned>(qr->view().mode), -s.position.z,
                   e.roll * 57.29578, e.pitch * 57.29578, e.yaw * 57.29578, qr->world().plant().battery_volts(),
                   static_cast<unsigned>(qr->view().deadline_misses),
                   static_cast<unsigned long long>(timing.late_wakeups),
                   static_cast<unsigned long long>(timing.behind_kicks),
                   static_cast<double>(timing.max_behind_us) * 1e-3, static_cast<unsigned long long>(timing.pauses),
                   static_cast<double>(timing.paused_us) * 1e-6, static_cast<unsigned long long>(out.frames_dropped()));
      if (radio) {
        std::fprintf(stderr, "qrsim: radio %s, arm switch %s, mode switch %s, %u RC frames sent\n",
                     radio->sending(now) ? "sending" : "silent (no control frames from the console)",
                     radio->transmitter().arm_switch_on(now) ? "on" : "off",
                     wire::mode_key(radio->transmitter().mode_switch()), radio->transmitter().rc_frames());
      }
    }
    if (stop_us != 0 && now >= stop_us) break;
  }
  reports.finish(out);
  if (slave_keep >= 0) close(slave_keep);
  return 0;
}

}  // namespace qrsim
