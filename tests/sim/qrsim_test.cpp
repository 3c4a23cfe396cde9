// qrsim --serve as the console sees it: a pseudo terminal (or stdin/stdout) carrying the wire
// protocol in real time. Each test runs qrsim for a few seconds of wall time.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>

namespace {

using Clock = std::chrono::steady_clock;

struct Heard {
  int attitude_frames = 0;
  bool mode_change_acked = false;
  std::string text;
};

// Talks to the QR on (in_fd, out_fd) for `seconds`: control at 50 Hz, one request for
// calibration; collects what comes back.
Heard converse(int to_qr, int from_qr, double seconds) {
  Heard heard;
  wire::FrameParser parser(wire::Listen::qr_to_pc);
  const auto write_frame = [&](const wire::FrameBytes& f) {
    ASSERT_EQ(write(to_qr, f.bytes, f.size), static_cast<ssize_t>(f.size));
  };
  write_frame(wire::encode(wire::ModeChange{5, wire::Mode::calibration}));
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  auto next_control = Clock::now();
  while (Clock::now() < end) {
    if (Clock::now() >= next_control) {
      write_frame(wire::encode(wire::Control{}));
      next_control += std::chrono::milliseconds(20);
    }
    pollfd p{from_qr, POLLIN, 0};
    if (poll(&p, 1, 5) <= 0) continue;
    uint8_t buffer[512];
    const ssize_t n = read(from_qr, buffer, sizeof buffer);
    if (n <= 0) break;
    for (ssize_t i = 0; i < n; ++i) {
      parser.push(buffer[i], [&](const wire::Frame& frame) {
        struct Handler {
          Heard& h;
          void operator()(const wire::TelemetryAttitude&) { ++h.attitude_frames; }
          void operator()(const wire::Ack& a) {
            if (a.type == wire::MessageType::mode_change && a.seq == 5) h.mode_change_acked = true;
          }
          void operator()(const wire::DebugText& t) { h.text.append(t.text, t.length()); }
        } handler{heard};
        wire::dispatch(frame, handler);
      });
    }
  }
  return heard;
}

void expect_a_live_qr(const Heard& heard, double seconds) {
  EXPECT_TRUE(heard.mode_change_acked);
  // Telemetry at the default 50 Hz, for most of the time talked.
  EXPECT_GT(heard.attitude_frames, static_cast<int>(50 * seconds * 0.6));
  EXPECT_NE(heard.text.find("mode: calibration\n"), std::string::npos) << heard.text;
  EXPECT_NE(heard.text.find("mode: safe\n"), std::string::npos) << heard.text;  // calibration done
}

TEST(Qrsim, ServesAPseudoTerminalLikeTheHardware) {
  FILE* out = popen(QRSIM_PATH " --serve --seconds 4", "r");
  ASSERT_NE(out, nullptr);
  char line[256] = {};
  ASSERT_NE(std::fgets(line, sizeof line, out), nullptr);
  const std::string first = line;
  const std::string prefix = "qrsim: serial on ";
  ASSERT_EQ(first.rfind(prefix, 0), 0u) << first;
  const std::string path = first.substr(prefix.size(), first.size() - prefix.size() - 1);
  const int fd = open(path.c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0) << path;
  const Heard heard = converse(fd, fd, 2.0);
  close(fd);
  EXPECT_EQ(pclose(out), 0);
  expect_a_live_qr(heard, 2.0);
}

TEST(Qrsim, ServesStdio) {
  int to_child[2], from_child[2];
  ASSERT_EQ(pipe(to_child), 0);
  ASSERT_EQ(pipe(from_child), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(to_child[0], STDIN_FILENO);
    dup2(from_child[1], STDOUT_FILENO);
    close(to_child[1]);
    close(from_child[0]);
    execl(QRSIM_PATH, "qrsim", "--serve", "--stdio", "--seconds", "3", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(to_child[0]);
  close(from_child[1]);
  const Heard heard = converse(to_child[1], from_child[0], 2.0);
  close(to_child[1]);
  close(from_child[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  expect_a_live_qr(heard, 2.0);
}

}  // namespace
