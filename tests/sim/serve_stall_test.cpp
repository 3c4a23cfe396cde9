// qrsim --serve against a host and a console that do not keep up (issue 30): the simulator stopped
// for 2 s in flight (SIGSTOP, as a loaded host or a debugger stops it), a console that opens the
// pty and never reads, and SIGTERM or SIGINT while the pty is full. Real time: each test runs
// qrsim for a few seconds of wall time, on its pty, with its side channel and its stderr.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>

namespace {

using Clock = std::chrono::steady_clock;

// qrsim --serve --status --truth-fd 3 with a console on its pty: control frames at 50 Hz (while
// `heartbeat`), the QR's frames read while `reading`; truth lines and stderr lines collected.
class ServedPty {
 public:
  ServedPty() {
    int out[2], err[2], side[2];
    if (pipe2(out, O_CLOEXEC) != 0 || pipe2(err, O_CLOEXEC) != 0 ||
        socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, side) != 0)
      return;
    pid_ = fork();
    if (pid_ == 0) {
      // Standard output and error first: a pipe's end may be descriptor 3. dup2 clears
      // close-on-exec on the copy, except onto itself.
      dup2(out[1], STDOUT_FILENO);
      dup2(err[1], STDERR_FILENO);
      if (side[1] == 3) fcntl(3, F_SETFD, 0);
      else dup2(side[1], 3);
      const int null = open("/dev/null", O_RDONLY);
      dup2(null, STDIN_FILENO);
      execl(QRSIM_PATH, "qrsim", "--serve", "--status", "--truth-fd", "3", "--seconds", "60",
            static_cast<char*>(nullptr));
      _exit(127);
    }
    close(out[1]);
    close(err[1]);
    close(side[1]);
    out_ = out[0];
    err_ = err[0];
    side_ = side[0];
    fcntl(err_, F_SETFL, O_NONBLOCK);
    fcntl(side_, F_SETFL, O_NONBLOCK);
    // The first line names the pty.
    std::string line;
    for (char c = 0; line.size() < 200;) {
      pollfd p{out_, POLLIN, 0};
      if (poll(&p, 1, 5000) <= 0 || read(out_, &c, 1) != 1 || c == '\n') break;
      line += c;
    }
    const std::string prefix = "qrsim: serial on ";
    if (line.rfind(prefix, 0) != 0) return;
    pty_ = open(line.substr(prefix.size()).c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  }
  ~ServedPty() {
    if (pid_ > 0 && !ended_) {
      kill(pid_, SIGKILL);  // not SIGTERM: a test may have left it stopped, or broken
      waitpid(pid_, nullptr, 0);
    }
    for (int fd : {out_, err_, side_, pty_})
      if (fd >= 0) close(fd);
  }
  bool started() const { return pid_ > 0 && pty_ >= 0; }
  pid_t pid() const { return pid_; }

  wire::Control sticks;
  bool heartbeat = true;
  bool reading = true;

  void send(const wire::FrameBytes& f) {
    // The pty holds some 17 kB: a console's frames fit even while qrsim does not read.
    ASSERT_EQ(write(pty_, f.bytes, f.size), static_cast<ssize_t>(f.size));
  }

  // Talks until `done` holds or `seconds` have passed; true when it held.
  bool until(const std::function<bool()>& done, double seconds) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < end) {
      if (heartbeat && Clock::now() >= next_control_) {
        send(wire::encode(sticks));
        next_control_ = Clock::now() + std::chrono::milliseconds(20);
      }
      pollfd p[3] = {{reading ? pty_ : -1, POLLIN, 0}, {side_, POLLIN, 0}, {err_, POLLIN, 0}};
      poll(p, 3, 5);
      if (reading) read_qr();
      read_lines(side_, side_pending_, [&](const std::string& l) { truth(l); });
      read_lines(err_, err_pending_, [&](const std::string& l) { err_lines.push_back(l); });
      if (done()) return true;
    }
    return false;
  }
  void wait(double seconds) {
    until([] { return false; }, seconds);
  }

  // The program's end within `seconds`: how long it took (s), or a negative number if it did not
  // end; `status` its wait status.
  double ends_within(double seconds, int& status) {
    const auto start = Clock::now();
    while (Clock::now() - start < std::chrono::duration<double>(seconds)) {
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        ended_ = true;
        return std::chrono::duration<double>(Clock::now() - start).count();
      }
      usleep(2000);
    }
    return -1;
  }

  // What the QR said.
  wire::Mode mode = wire::Mode::safe;
  uint8_t attitude_flags = 0;
  std::string text;
  // What the simulator said: the latest truth line's time and height, and its stderr lines.
  double truth_t = -1;
  double height = 0;
  std::vector<std::string> err_lines;

  bool err_said(const std::string& part) const {
    for (const std::string& l : err_lines)
      if (l.find(part) != std::string::npos) return true;
    return false;
  }
  // The last status line's figure `name=` (frames_dropped, pauses, ...); -1 before any.
  double status_figure(const std::string& name) const {
    for (auto it = err_lines.rbegin(); it != err_lines.rend(); ++it) {
      const size_t at = it->find(" " + name + "=");
      if (it->rfind("qrsim: t=", 0) == 0 && at != std::string::npos)
        return std::strtod(it->c_str() + at + name.size() + 2, nullptr);
    }
    return -1;
  }
  std::string err_text() const {
    std::string all;
    for (const std::string& l : err_lines) all += l + "\n";
    return all;
  }

 private:
  void read_qr() {
    uint8_t buffer[512];
    for (ssize_t n; (n = read(pty_, buffer, sizeof buffer)) > 0;) {
      for (ssize_t i = 0; i < n; ++i) {
        parser_.push(buffer[i], [&](const wire::Frame& frame) {
          struct Handler {
            ServedPty& c;
            void operator()(const wire::TelemetryAttitude& m) {
              c.mode = m.mode;
              c.attitude_flags = m.flags;
            }
            void operator()(const wire::DebugText& m) { c.text.append(m.text, m.length()); }
          } handler{*this};
          wire::dispatch(frame, handler);
        });
      }
    }
  }
  static void read_lines(int fd, std::string& pending, const std::function<void(const std::string&)>& take) {
    char buffer[4096];
    for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) {
      for (ssize_t i = 0; i < n; ++i) {
        if (buffer[i] != '\n') {
          pending += buffer[i];
          continue;
        }
        take(pending);
        pending.clear();
      }
    }
  }
  void truth(const std::string& line) {
    if (line.rfind("truth t=", 0) != 0) return;
    truth_t = std::strtod(line.c_str() + 8, nullptr);
    const size_t at = line.find(" height=");
    if (at != std::string::npos) height = std::strtod(line.c_str() + at + 8, nullptr);
  }

  pid_t pid_ = -1;
  bool ended_ = false;
  int out_ = -1, err_ = -1, side_ = -1, pty_ = -1;
  Clock::time_point next_control_ = Clock::now();
  wire::FrameParser parser_{wire::Listen::qr_to_pc};
  std::string side_pending_, err_pending_;
};

// The QR calibrated, in full control, a little off the ground on the simulator's truth.
void fly(ServedPty& c) {
  c.send(wire::encode(wire::ModeChange{1, wire::Mode::calibration}));
  ASSERT_TRUE(c.until([&] { return c.text.find("mode: calibration\n") != std::string::npos; }, 3.0)) << c.text;
  ASSERT_TRUE(
      c.until([&] { return c.mode == wire::Mode::safe && (c.attitude_flags & wire::kFlagCalibrated) != 0; }, 5.0))
      << c.text;
  c.send(wire::encode(wire::ModeChange{2, wire::Mode::full_control}));
  ASSERT_TRUE(c.until([&] { return c.mode == wire::Mode::full_control; }, 2.0)) << c.text;
  c.sticks.lift = 600;
  ASSERT_TRUE(c.until([&] { return c.height > 0.3; }, 5.0)) << "height " << c.height << "\n" << c.text;
}

// Streams on top of the telemetry fill the line (8 kB/s of its 11.5), so a pty nobody reads is
// full within some 2.5 s, not the 9 s the telemetry alone takes.
void fill_the_line(ServedPty& c) { c.send(wire::encode(wire::StreamRequest{3, 0, 2, {0, 1, 2, 3}})); }

// A host that stops the simulator for 2 s in flight (SIGSTOP: a loaded machine, a debugger) and
// lets it go on: the world pauses, it does not skip 2 s, so the QR's link watchdog (simulated
// time) sees no gap in the console's frames and there is no panic; the stall is reported on
// stderr, which the console logs.
TEST(ServeStall, AStoppedHostPausesTheWorldWithoutALinkLoss) {
  ServedPty c;
  ASSERT_TRUE(c.started());
  fly(c);
  if (HasFatalFailure()) return;
  c.wait(0.2);
  const double t_before = c.truth_t;
  const double height_before = c.height;
  ASSERT_EQ(kill(c.pid(), SIGSTOP), 0);
  c.wait(2.0);  // the console sends its control frames on, into the pty
  const double t_stopped = c.truth_t;
  ASSERT_EQ(kill(c.pid(), SIGCONT), 0);
  ASSERT_TRUE(c.until([&] { return c.truth_t > t_stopped; }, 1.0));
  const double t_after = c.truth_t;
  c.wait(1.5);
  std::printf("truth t %.3f s before the stop, %.3f s first after it (height %.2f m); %s", t_before, t_after,
              height_before, c.err_text().c_str());
  // The world went on where it stood, not 2 s later (its own steps and the truth line's 20 ms).
  EXPECT_LT(t_after - t_stopped, 0.5) << "simulated time skipped";
  EXPECT_EQ(c.mode, wire::Mode::full_control) << c.text;
  EXPECT_EQ(c.text.find("panic"), std::string::npos) << c.text;
  EXPECT_TRUE(c.err_said("the host stalled for ")) << c.err_text();
  EXPECT_GE(c.status_figure("pauses"), 1) << c.err_text();
}

// A console that opens the pty and never reads: the world flies on at about real time (it stopped
// some 9 s after the pty filled, its writes blocked), the QR's frames dropped, counted, and said.
TEST(ServeStall, AConsoleThatNeverReadsDoesNotStopTheWorld) {
  ServedPty c;
  ASSERT_TRUE(c.started());
  c.reading = false;
  c.heartbeat = false;
  fill_the_line(c);
  // Full within some 2.5 s; frames dropped from then on.
  ASSERT_TRUE(c.until([&] { return c.err_said("does not read the serial line"); }, 6.0)) << c.err_text();
  const double t0 = c.truth_t;
  const auto wall0 = Clock::now();
  c.wait(2.0);
  const double world_s = c.truth_t - t0;
  const double wall_s = std::chrono::duration<double>(Clock::now() - wall0).count();
  std::printf("the world advanced %.2f s in %.2f s of wall time with the pty full; %s", world_s, wall_s,
              c.err_text().c_str());
  EXPECT_GT(world_s, 0.5 * wall_s) << c.err_text();
  EXPECT_GT(c.status_figure("frames_dropped"), 0) << c.err_text();
}

// SIGTERM and SIGINT with the pty full (nobody reads it): qrsim ends within 1 s, exit status 0.
void ends_on(int signal_number) {
  ServedPty c;
  ASSERT_TRUE(c.started());
  c.reading = false;
  c.heartbeat = false;
  fill_the_line(c);
  // Long enough for the pty to be full whatever the simulator says (8 kB/s into some 17 kB).
  c.wait(3.5);
  ASSERT_EQ(kill(c.pid(), signal_number), 0);
  int status = 0;
  const double took = c.ends_within(1.0, status);
  std::printf("ended %.3f s after signal %d\n", took, signal_number);
  ASSERT_GE(took, 0) << "still running 1 s after signal " << signal_number;
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(ServeStall, SigtermEndsItWithAFullPty) { ends_on(SIGTERM); }
TEST(ServeStall, SigintEndsItWithAFullPty) { ends_on(SIGINT); }

}  // namespace
