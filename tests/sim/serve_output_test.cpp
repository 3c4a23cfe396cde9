// Serve mode's way out to the console (qr/sim_runner/serve_output.hpp): whole frames, written
// without waiting; into a pty nobody reads, the oldest whole frames are dropped and counted, and
// what the reader gets at last is whole frames only.
#include <fcntl.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <vector>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <qr/sim_runner/serve_output.hpp>

namespace {

// A raw pty: the master is serve mode's end (non-blocking), the slave the console's.
struct Pty {
  int master = -1, slave = -1;
  Pty() {
    master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) return;
    slave = open(ptsname(master), O_RDWR | O_NOCTTY | O_NONBLOCK);
    termios t{};
    tcgetattr(slave, &t);
    cfmakeraw(&t);
    tcsetattr(slave, TCSANOW, &t);
    fcntl(master, F_SETFL, O_NONBLOCK);
  }
  ~Pty() {
    close(slave);
    close(master);
  }
};

// Frame n of a numbered sequence: telemetry_link with frames_ok = n (12 bytes).
wire::FrameBytes numbered(uint16_t n) { return wire::encode(wire::TelemetryLink{n, 0, 0, 0, 0}); }

void put(qrsim::ServeOutput& out, const wire::FrameBytes& f) {
  for (uint8_t i = 0; i < f.size; ++i) out.put(f.bytes[i]);
}

// What the console reads: the numbers of the frames, through one parser however the reads fall.
struct Console {
  std::vector<uint16_t> numbers;
  wire::FrameParser parser{wire::Listen::qr_to_pc};

  void read_all(int fd) {
    uint8_t buffer[4096];
    for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) {
      for (ssize_t i = 0; i < n; ++i) {
        parser.push(buffer[i], [&](const wire::Frame& frame) {
          wire::TelemetryLink link;
          if (wire::decode(frame, link)) numbers.push_back(link.frames_ok);
        });
      }
    }
  }
};

TEST(ServeOutput, WholeFramesGoOutInOrder) {
  Pty pty;
  ASSERT_GE(pty.slave, 0);
  qrsim::ServeOutput out;
  const wire::FrameBytes first = numbered(1);
  for (uint8_t i = 0; i + 1 < first.size; ++i) out.put(first.bytes[i]);
  out.write_to(pty.master);
  EXPECT_EQ(out.frames_written(), 0u) << "a frame goes out whole, not as it trickles in";
  out.put(first.bytes[first.size - 1]);
  put(out, numbered(2));
  out.write_to(pty.master);
  EXPECT_EQ(out.frames_written(), 2u);
  EXPECT_EQ(out.queued_bytes(), 0u);
  Console console;
  console.read_all(pty.slave);
  EXPECT_EQ(console.numbers, (std::vector<uint16_t>{1, 2}));
  EXPECT_EQ(out.frames_dropped(), 0u);
}

// Nobody reads: the pty fills (some 17 kB), the writes never wait, the queue stays within its
// bound by dropping the oldest whole frames, counted. When the console reads at last it finds
// whole frames only (whatever part of a frame a full pty took, the rest followed before anything
// else), the oldest first, then the newest; none is damaged or cut.
TEST(ServeOutput, AFullPtyDropsTheOldestWholeFrames) {
  Pty pty;
  ASSERT_GE(pty.slave, 0);
  qrsim::ServeOutput out;
  constexpr uint16_t kFrames = 6000;  // 72 kB, about four times what the pty holds
  for (uint16_t n = 0; n < kFrames; ++n) {
    put(out, numbered(n));
    out.write_to(pty.master);
    ASSERT_LE(out.queued_bytes(), qrsim::ServeOutput::kQueueBytes);
  }
  EXPECT_GT(out.frames_dropped(), 3000u);
  EXPECT_EQ(out.frames_written() + out.frames_dropped() + out.queued_bytes() / 12, kFrames);
  EXPECT_EQ(out.bytes_dropped(), out.frames_dropped() * 12);
  // The console reads everything, the queue follows as the pty takes it.
  Console console;
  for (int round = 0; round < 100 && (out.queued_bytes() > 0 || round == 0); ++round) {
    console.read_all(pty.slave);
    out.write_to(pty.master);
  }
  console.read_all(pty.slave);
  const wire::LinkCounters& counters = console.parser.counters();
  const std::vector<uint16_t>& numbers = console.numbers;
  EXPECT_EQ(counters.bytes_skipped, 0u) << "half a frame reached the console";
  EXPECT_EQ(counters.check_failures, 0u);
  EXPECT_EQ(numbers.size(), out.frames_written());
  ASSERT_FALSE(numbers.empty());
  EXPECT_EQ(numbers.front(), 0u) << "the pty's own frames are the oldest";
  EXPECT_EQ(numbers.back(), kFrames - 1) << "the newest frame is kept";
  // In order; the gaps (one, or a few as the kernel moves the pty's bytes on in its own time) are
  // the frames dropped.
  uint64_t missing = 0;
  for (size_t i = 1; i < numbers.size(); ++i) {
    ASSERT_GT(numbers[i], numbers[i - 1]);
    missing += numbers[i] - numbers[i - 1] - 1u;
  }
  EXPECT_EQ(missing, out.frames_dropped());
}

// A byte that starts no frame the QR sends (a damaged stream) goes out alone: it is not held back
// waiting for a frame, and 'M' with a type only the PC sends is no frame.
TEST(ServeOutput, BytesThatStartNoFrameGoAlone) {
  Pty pty;
  ASSERT_GE(pty.slave, 0);
  qrsim::ServeOutput out;
  out.put(0x00);
  out.put(wire::kStartByte);
  out.put(wire::type_byte(wire::MessageType::control));
  out.write_to(pty.master);
  EXPECT_EQ(out.frames_written(), 3u);
  uint8_t buffer[8] = {};
  EXPECT_EQ(read(pty.slave, buffer, sizeof buffer), 3);
}

}  // namespace
