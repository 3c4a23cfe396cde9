// fake-qr --serve [--chatty]: the FakeQr on a pty, announcing it the way the simulator does
// ("qrsim: serial on /dev/pts/N" as the first line of output), so qrterm --sim can fly it in the
// tmux tests without the firmware. Real time; ends after the console's exit handshake or when the
// console closes the line. --chatty: a debug text line every 10 ms, so the console's log scrolls
// and every screen it draws is a big one.
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
  for (int i = 1; i < argc; ++i) {
    serve = serve || std::strcmp(argv[i], "--serve") == 0;
    chatty = chatty || std::strcmp(argv[i], "--chatty") == 0;
  }
  if (!serve) {
    std::fprintf(stderr, "usage: fake-qr --serve [--chatty]\n");
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
