#include <qr/boards/sim/serve.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <string>

#include <qr/boards/sim/devboard_qr.hpp>
#include <qr/boards/sim/flying_qr.hpp>
#include <qr/boards/sim/serve_radio.hpp>
#include <qr/boards/sim/truth_channel.hpp>

namespace qrsim {
namespace {

volatile sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

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

// Bytes the QR has sent that have arrived at the console's end go out on the pty.
void forward_to_console(SimBoard& board, int out_fd) {
  uint8_t buffer[256];
  size_t count = 0;
  uint8_t byte = 0;
  while (count < sizeof buffer && board.pc_receive(byte)) buffer[count++] = byte;
  for (size_t done = 0; done < count;) {
    const ssize_t n = write(out_fd, buffer + done, count - done);
    if (n < 0 && errno != EAGAIN && errno != EINTR) break;  // nobody listening: the bytes are lost, as on a wire
    if (n < 0) {
      pollfd p{out_fd, POLLOUT, 0};
      poll(&p, 1, 1);
      continue;
    }
    done += static_cast<size_t>(n);
  }
}

// The firmware stops as soon as its last bytes (the exit's ack) are in the board's transmit
// buffer, up to 32 bytes or 3 ms before they are through the line. The line runs on until they
// are, and a pty stays open a little longer (`linger`): its hang-up would discard what the
// console has not read yet, and the console would see LINK LOST and an unconfirmed exit.
void let_the_line_finish(FlyingQr& qr, int out_fd, bool linger) {
  constexpr int kMaxPeriods = 100;     // 32 bytes take 3 periods; this bounds a stuck reader
  constexpr int kLingerPeriods = 200;  // for the console to read the last bytes
  for (int i = 0; i < kMaxPeriods && qr.board().pc_bytes_pending() && g_stop == 0; ++i) {
    qr.world().advance_to(qr.world().now_us() + qr::kPeriodUs);
    forward_to_console(qr.board(), out_fd);
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
  int in_fd = STDIN_FILENO, out_fd = STDOUT_FILENO, slave_keep = -1;
  if (!options.stdio) {
    int master = -1;
    if (!open_pty(master, slave_keep)) {
      std::perror("qrsim: pseudo terminal");
      return 1;
    }
    in_fd = out_fd = master;
  }
  set_nonblocking(in_fd);
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  signal(SIGPIPE, SIG_IGN);

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
  qr->board().follow_wall_clock();
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

  while (g_stop == 0) {
    // Bytes from the console go onto the line now; the line delivers them at 115200 baud.
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
    forward_to_console(qr->board(), out_fd);

    if (truth.open()) {
      const uint64_t before = qr->world().now_us();
      truth.poll_commands(*qr, radio.get(), push_torque, push_until_us);
      const bool push_now = before < push_until_us;
      if (push_now || pushing) qr->world().plant().set_disturbance(push_now ? push_torque : sim::Vec3{}, sim::Vec3{});
      pushing = push_now;
    }

    if (radio) radio->step(qr->world().now_us(), qr->board());
    if (!qr->tick()) {  // sleeps until the next kick, then runs the firmware
      if (!qr->error().empty()) std::fprintf(stderr, "qrsim: devboard: %s\n", qr->error().c_str());
      else let_the_line_finish(*qr, out_fd, /*linger=*/!options.stdio);
      break;
    }

    const uint64_t now = qr->world().now_us();
    if (truth.open() && now >= next_truth_us) {
      next_truth_us = now - now % 20000 + 20000;
      truth.send(truth_line(static_cast<double>(now) * 1e-6, qr->world().plant().state()));
    }
    if (options.status && now >= next_status_us) {
      next_status_us += 1000000;
      const sim::PlantState& s = qr->world().plant().state();
      const sim::Euler e = sim::to_euler(s.attitude);
      std::fprintf(stderr,
                   "qrsim: t=%.0fs mode=%u height=%.2fm roll=%.1f pitch=%.1f yaw=%.1f deg battery=%.2fV misses=%u "
                   "host: late_wakeups=%llu caught_up=%llu max_late_ms=%.1f skipped=%llu\n",
                   static_cast<double>(now) * 1e-6, static_cast<unsigned>(qr->view().mode), -s.position.z,
                   e.roll * 57.29578, e.pitch * 57.29578, e.yaw * 57.29578, qr->world().plant().battery_volts(),
                   static_cast<unsigned>(qr->view().deadline_misses),
                   static_cast<unsigned long long>(qr->board().host_timing().late_wakeups),
                   static_cast<unsigned long long>(qr->board().host_timing().caught_up_periods),
                   static_cast<double>(qr->board().host_timing().max_late_us) * 1e-3,
                   static_cast<unsigned long long>(qr->board().host_timing().skipped_periods));
      if (radio) {
        std::fprintf(stderr, "qrsim: radio %s, arm switch %s, mode switch %s, %u RC frames sent\n",
                     radio->sending(now) ? "sending" : "silent (no control frames from the console)",
                     radio->transmitter().arm_switch_on(now) ? "on" : "off",
                     wire::mode_key(radio->transmitter().mode_switch()), radio->transmitter().rc_frames());
      }
    }
    if (stop_us != 0 && now >= stop_us) break;
  }
  if (slave_keep >= 0) close(slave_keep);
  return 0;
}

}  // namespace qrsim
