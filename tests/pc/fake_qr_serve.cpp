// fake-qr --serve [--chatty] [--table] [--devboard [--core-mhz N]] [--truth-fd N]: the FakeQr on a
// pty, announcing it the way the simulator does ("qrsim: serial on /dev/pts/N" as the first line of
// output), so qrterm --sim can fly it in the tmux tests without the firmware. Real time; ends after
// the console's exit handshake or when the console closes the line. --chatty: a debug text line
// every 10 ms, so the console's log scrolls and every screen it draws is a big one. --table: the
// observable table for the plot's names (and so the plot's streams, made-up values: stream_wave in
// fake_qr.hpp). --devboard: task figures, and once a second on the truth
// channel (--truth-fd, which qrterm passes) the line qrsim --serve --devboard sends about the
// devboard, with --core-mhz N as its clock (docs/simulator.md section 5).
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "fake_qr.hpp"

namespace {

uint32_t now_ms() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<uint32_t>(static_cast<uint64_t>(ts.tv_sec) * 1000u + static_cast<uint64_t>(ts.tv_nsec) / 1000000u);
}

}  // namespace

int main(int argc, char** argv) {
  bool serve = false;
  bool chatty = false;
  bool table = false;
  bool devboard = false;
  unsigned core_mhz = 0;
  int truth_fd = -1;
  for (int i = 1; i < argc; ++i) {
    serve = serve || std::strcmp(argv[i], "--serve") == 0;
    chatty = chatty || std::strcmp(argv[i], "--chatty") == 0;
    table = table || std::strcmp(argv[i], "--table") == 0;
    devboard = devboard || std::strcmp(argv[i], "--devboard") == 0;
    if (i + 1 < argc && std::strcmp(argv[i], "--core-mhz") == 0)
      core_mhz = static_cast<unsigned>(std::atoi(argv[i + 1]));
    if (i + 1 < argc && std::strcmp(argv[i], "--truth-fd") == 0) truth_fd = std::atoi(argv[i + 1]);
  }
  if (!serve) {
    std::fprintf(stderr, "usage: fake-qr --serve [--chatty] [--table] [--devboard [--core-mhz N]] [--truth-fd N]\n");
    return 2;
  }
  const int master = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) {
    std::perror("fake-qr: pty");
    return 1;
  }
  // Raw from the start: an echoing line discipline would hand our own telemetry back to us.
  termios tio{};
  tcgetattr(master, &tio);
  cfmakeraw(&tio);
  tcsetattr(master, TCSANOW, &tio);
  std::printf("qrsim: serial on %s\n", ptsname(master));
  std::fflush(stdout);

  qrterm_test::FakeQr qr(now_ms());
  qr.observable_table = table;
  const uint32_t started = now_ms();
  uint32_t next_devboard = started + 1000;
  if (devboard) {
    // A few tasks' figures in instructions, as the devboard's would be.
    qr.tasks = {{0, 1210, 3400, 0}, {1, 402, 410, 0}, {8, 212, 530, 0}, {10, 655, 1710, 0}};
  }
  bool console_seen = false;
  uint32_t exited_at = 0;
  uint32_t next_chatter = now_ms();
  unsigned chatter = 0;
  uint8_t buffer[512];
  for (;;) {
    pollfd fd{master, POLLIN, 0};
    poll(&fd, 1, 5);
    const uint32_t now = now_ms();
    const ssize_t n = read(master, buffer, sizeof buffer);
    if (n > 0) {
      console_seen = true;
      qr.receive(buffer, static_cast<size_t>(n), now);
    } else if (n < 0 && errno == EIO) {
      // No console on the other end: not yet (wait) or not any more (done).
      if (console_seen) return 0;
      usleep(10000);
      continue;
    }
    qr.tick(now);
    if (devboard && truth_fd >= 0 && now - next_devboard < 0x80000000u) {
      next_devboard += 1000;
      const unsigned seconds = (now - started) / 1000;
      char line[128];
      const int length = std::snprintf(
          line, sizeof line, "devboard t=%u.000 core_mhz=%u tick_instr_mean=2738 tick_instr_max=8012 ticks=%u\n",
          seconds, core_mhz, seconds * 1000);
      if (write(truth_fd, line, static_cast<size_t>(length)) < 0 && errno != EAGAIN) truth_fd = -1;
    }
    if (chatty && now - next_chatter < 0x80000000u) {
      next_chatter = now + 10;
      char line[48];
      std::snprintf(line, sizeof line, "chatter %u, filling the screen\n", chatter++);
      qr.say(line);
    }
    std::vector<uint8_t> out = qr.take_output();
    if (!out.empty() && write(master, out.data(), out.size()) < 0 && errno != EAGAIN) return 1;
    if (qr.exited && exited_at == 0) exited_at = now;
    if (exited_at != 0 && now - exited_at > 200) return 0;
  }
}
