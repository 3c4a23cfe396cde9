// qrsim --serve --rc crsf as a console sees it: the console's control frames become the radio's
// sticks (CRSF at 150 Hz on the QR's receiver line), the side channel moves the radio's switches,
// and the QR flies by the radio once its pilot parameter says so (docs/safety.md rule 17). Real
// time: each test runs qrsim for some seconds of wall time.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/parameter_table.hpp>

namespace {

using Clock = std::chrono::steady_clock;

// A scripted console on qrsim's stdio line and its side channel: control frames at 50 Hz with
// `sticks`, requests written once, what the QR and the simulator say collected.
class ServedRadio {
 public:
  explicit ServedRadio(double seconds, bool radio = true) {
    int to_child[2], from_child[2], side[2];
    if (pipe(to_child) != 0 || pipe(from_child) != 0 || socketpair(AF_UNIX, SOCK_STREAM, 0, side) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      // Standard input and output first: a pipe's end may be descriptor 3.
      dup2(to_child[0], STDIN_FILENO);
      dup2(from_child[1], STDOUT_FILENO);
      close(to_child[1]);
      close(from_child[0]);
      close(side[0]);
      dup2(side[1], 3);
      const std::string s = std::to_string(seconds);
      if (radio) {
        execl(QRSIM_PATH, "qrsim", "--serve", "--stdio", "--truth-fd", "3", "--seconds", s.c_str(), "--rc", "crsf",
              static_cast<char*>(nullptr));
      } else {
        execl(QRSIM_PATH, "qrsim", "--serve", "--stdio", "--truth-fd", "3", "--seconds", s.c_str(),
              static_cast<char*>(nullptr));
      }
      _exit(127);
    }
    close(to_child[0]);
    close(from_child[1]);
    close(side[1]);
    to_qr_ = to_child[1];
    from_qr_ = from_child[0];
    side_ = side[0];
    fcntl(from_qr_, F_SETFL, O_NONBLOCK);
    fcntl(side_, F_SETFL, O_NONBLOCK);
  }
  ~ServedRadio() {
    close(to_qr_);
    close(from_qr_);
    close(side_);
    if (pid_ > 0) {
      kill(pid_, SIGTERM);  // qrsim stops at once on it
      waitpid(pid_, &status_, 0);
    }
  }
  bool started() const { return pid_ > 0; }

  wire::Control sticks;
  bool heartbeat = true;  // false: the console sends nothing (it has gone)

  void send(const wire::FrameBytes& f) { ASSERT_EQ(write(to_qr_, f.bytes, f.size), static_cast<ssize_t>(f.size)); }
  void side(const std::string& line) {
    ASSERT_EQ(write(side_, line.data(), line.size()), static_cast<ssize_t>(line.size()));
  }

  // Talks until `done` holds or `seconds` have passed; true when it held.
  bool until(const std::function<bool()>& done, double seconds) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < end) {
      if (heartbeat && Clock::now() >= next_control_) {
        send(wire::encode(sticks));
        next_control_ = Clock::now() + std::chrono::milliseconds(20);
      }
      pollfd p[2] = {{from_qr_, POLLIN, 0}, {side_, POLLIN, 0}};
      poll(p, 2, 5);
      read_qr();
      read_side();
      if (done()) return true;
    }
    return false;
  }

  wire::Mode mode = wire::Mode::safe;
  uint8_t attitude_flags = 0;
  uint8_t radio_flags = 0;
  int radio_frames = 0;
  std::string text;                     // the QR's debug text
  std::vector<std::string> side_lines;  // everything the side channel said
  double height = 0;                    // the last truth line's
  std::vector<wire::Nack> nacks;
  std::vector<wire::Ack> acks;

  bool said(const std::string& line) const {
    for (const std::string& l : side_lines)
      if (l == line) return true;
    return false;
  }
  bool acked(wire::MessageType type, uint8_t seq) const {
    for (const wire::Ack& a : acks)
      if (a.type == type && a.seq == seq) return true;
    return false;
  }

 private:
  void read_qr() {
    uint8_t buffer[512];
    for (ssize_t n; (n = read(from_qr_, buffer, sizeof buffer)) > 0;) {
      for (ssize_t i = 0; i < n; ++i) {
        parser_.push(buffer[i], [&](const wire::Frame& frame) {
          struct Handler {
            ServedRadio& c;
            void operator()(const wire::TelemetryAttitude& m) {
              c.mode = m.mode;
              c.attitude_flags = m.flags;
            }
            void operator()(const wire::TelemetryRadio& m) {
              c.radio_flags = m.flags;
              ++c.radio_frames;
            }
            void operator()(const wire::DebugText& m) { c.text.append(m.text, m.length()); }
            void operator()(const wire::Ack& m) { c.acks.push_back(m); }
            void operator()(const wire::Nack& m) { c.nacks.push_back(m); }
          } handler{*this};
          wire::dispatch(frame, handler);
        });
      }
    }
  }
  void read_side() {
    char buffer[1024];
    for (ssize_t n; (n = read(side_, buffer, sizeof buffer)) > 0;) {
      for (ssize_t i = 0; i < n; ++i) {
        if (buffer[i] != '\n') {
          pending_ += buffer[i];
          continue;
        }
        const size_t at = pending_.find(" height=");
        if (at != std::string::npos) height = std::strtod(pending_.c_str() + at + 8, nullptr);
        else side_lines.push_back(pending_);  // answers and errors (truth lines are many)
        pending_.clear();
      }
    }
  }

  pid_t pid_ = -1;
  int status_ = 0;
  int to_qr_ = -1, from_qr_ = -1, side_ = -1;
  Clock::time_point next_control_ = Clock::now();
  wire::FrameParser parser_{wire::Listen::qr_to_pc};
  std::string pending_;
};

// The radio made the pilot in safe, and calibrated: ready for its arm switch.
void make_the_radio_the_pilot(ServedRadio& c) {
  c.send(wire::encode(wire::ParamSet{0x21, static_cast<uint8_t>(wire::ParamId::pilot), 1}));
  ASSERT_TRUE(c.until([&] { return c.acked(wire::MessageType::param_set, 0x21); }, 3.0)) << c.text;
  c.send(wire::encode(wire::ModeChange{0x22, wire::Mode::calibration}));
  ASSERT_TRUE(c.until([&] { return c.text.find("mode: calibration\n") != std::string::npos; }, 3.0)) << c.text;
  ASSERT_TRUE(
      c.until([&] { return c.mode == wire::Mode::safe && (c.attitude_flags & wire::kFlagCalibrated) != 0; }, 5.0))
      << c.text;
  ASSERT_TRUE(c.until(
      [&] {
        return (c.radio_flags & (wire::kRadioPilot | wire::kRadioLinkUp)) == (wire::kRadioPilot | wire::kRadioLinkUp);
      },
      2.0))
      << "the console's sticks reach the QR through the radio: flags " << int{c.radio_flags};
}

// Arm by the switch, fly, switch off: the console's sticks lift the QR through the radio in full
// control, and the arm switch moved to off in flight is the emergency stop.
TEST(ServeRadio, ArmsByTheSwitchFliesAndTheSwitchOffIsAPanic) {
  ServedRadio c(25);
  ASSERT_TRUE(c.started());
  make_the_radio_the_pilot(c);

  // The PC cannot arm while the radio flies.
  c.send(wire::encode(wire::ModeChange{0x23, wire::Mode::full_control}));
  ASSERT_TRUE(c.until([&] { return !c.nacks.empty(); }, 2.0));
  EXPECT_EQ(c.nacks.back().reason, wire::NackReason::radio_is_pilot);
  EXPECT_EQ(c.mode, wire::Mode::safe);

  c.side("radio arm full\n");
  ASSERT_TRUE(c.until([&] { return c.mode == wire::Mode::full_control; }, 2.0)) << c.text;
  EXPECT_TRUE(c.said("ok radio arm full"));
  EXPECT_TRUE(c.until([&] { return (c.radio_flags & wire::kRadioArmSwitch) != 0; }, 1.0))
      << "the console shows the switch";

  // The console's lift stick, through the radio: the QR climbs on the simulator's truth.
  const double ground = c.height;
  c.sticks.lift = 600;
  EXPECT_TRUE(c.until([&] { return c.height > ground + 0.3; }, 6.0)) << "height " << c.height;
  std::printf("climbed from %.3f m to %.3f m through the radio\n", ground, c.height);
  EXPECT_EQ(c.mode, wire::Mode::full_control) << c.text;

  c.side("radio off\n");
  ASSERT_TRUE(c.until([&] { return c.mode == wire::Mode::panic; }, 1.0)) << c.text;
  EXPECT_NE(c.text.find("mode: panic (arm switch off)"), std::string::npos) << c.text;
  EXPECT_TRUE(c.said("ok radio off"));
}

// The console gone (no control frames): nobody holds the transmitter's sticks, the radio goes
// silent, and the QR's watchdog on the radio's link panics the flight.
TEST(ServeRadio, TheConsoleGoneIsTheRadiosLinkLost) {
  ServedRadio c(15);
  ASSERT_TRUE(c.started());
  make_the_radio_the_pilot(c);
  c.side("radio arm manual\n");
  ASSERT_TRUE(c.until([&] { return c.mode == wire::Mode::manual; }, 2.0)) << c.text;
  c.heartbeat = false;
  EXPECT_TRUE(c.until([&] { return c.mode == wire::Mode::panic; }, 2.0)) << c.text;
  EXPECT_NE(c.text.find("mode: panic (link lost)"), std::string::npos) << c.text;
}

// The side channel names what the radio takes, and a simulator started without --rc crsf says it
// has no radio.
TEST(ServeRadio, RadioCommandsNeedARadio) {
  ServedRadio c(4, /*radio=*/false);
  ASSERT_TRUE(c.started());
  c.side("radio arm sideways\n");
  c.side("radio arm manual\n");
  EXPECT_TRUE(c.until([&] { return c.side_lines.size() >= 2; }, 2.0));
  ASSERT_EQ(c.side_lines.size(), 2u);
  EXPECT_EQ(c.side_lines[0], "error radio takes 'arm manual', 'arm yaw', 'arm full' or 'off'");
  EXPECT_EQ(c.side_lines[1], "error radio: this simulator has no radio (qrsim --serve --rc crsf)");
}

}  // namespace
