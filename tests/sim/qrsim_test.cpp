// qrsim --serve as the console sees it: a pseudo terminal (or stdin/stdout) carrying the wire
// protocol in real time. Each test runs qrsim for a few seconds of wall time.
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
#include <string>
#include <utility>
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
// calibration after `ask_after_s`; collects what comes back.
Heard converse(int to_qr, int from_qr, double seconds, double ask_after_s = 0) {
  Heard heard;
  wire::FrameParser parser(wire::Listen::qr_to_pc);
  const auto write_frame = [&](const wire::FrameBytes& f) {
    ASSERT_EQ(write(to_qr, f.bytes, f.size), static_cast<ssize_t>(f.size));
  };
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  const auto ask = Clock::now() + std::chrono::duration<double>(ask_after_s);
  bool asked = false;
  auto next_control = Clock::now();
  while (Clock::now() < end) {
    if (!asked && Clock::now() >= ask) {
      write_frame(wire::encode(wire::ModeChange{5, wire::Mode::calibration}));
      asked = true;
    }
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

// The child qrsim with its line on a pipe pair: (to it, from it).
pid_t serve_on_pipes(std::vector<const char*> args, int& to_qr, int& from_qr) {
  int to_child[2], from_child[2];
  if (pipe(to_child) != 0 || pipe(from_child) != 0) return -1;
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(to_child[0], STDIN_FILENO);
    dup2(from_child[1], STDOUT_FILENO);
    close(to_child[1]);
    close(from_child[0]);
    args.insert(args.begin(), "qrsim");
    args.push_back(nullptr);
    execv(QRSIM_PATH, const_cast<char* const*>(args.data()));
    _exit(127);
  }
  close(to_child[0]);
  close(from_child[1]);
  to_qr = to_child[1];
  from_qr = from_child[0];
  return pid;
}

// A served qrsim on pipes, talked to as converse() does; what it said and how it ended (-1: it
// could not be started, or did not exit).
struct Served {
  Heard heard;
  int exit_status = -1;
};
Served serve_and_converse(std::vector<const char*> args, double seconds, double ask_after_s = 0) {
  Served out;
  int to_qr = -1, from_qr = -1;
  const pid_t pid = serve_on_pipes(std::move(args), to_qr, from_qr);
  if (pid <= 0) return out;
  out.heard = converse(to_qr, from_qr, seconds, ask_after_s);
  close(to_qr);
  close(from_qr);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) out.exit_status = WEXITSTATUS(status);
  return out;
}

// Serve mode through the sensor drivers (--sensors drivers; direct is its default): asked at once,
// before the IMU streams, the QR refuses calibration (safety.md rule 20: why serve's default is
// direct); asked at 0.5 s (it streams from about 0.28 s), it calibrates.
TEST(Qrsim, ServesThroughTheSensorDriversWhenAsked) {
  const Served refused = serve_and_converse({"--serve", "--stdio", "--sensors", "drivers", "--seconds", "1"}, 0.8);
  EXPECT_GT(refused.heard.attitude_frames, 0);  // it was there, and refused
  EXPECT_FALSE(refused.heard.mode_change_acked);
  EXPECT_EQ(refused.heard.text.find("mode: calibration\n"), std::string::npos) << refused.heard.text;

  const Served asked = serve_and_converse({"--serve", "--stdio", "--sensors", "drivers", "--seconds", "3"}, 2.0, 0.5);
  EXPECT_EQ(asked.exit_status, 0);
  expect_a_live_qr(asked.heard, 2.0);
}

TEST(Qrsim, ServesStdio) {
  const Served served = serve_and_converse({"--serve", "--stdio", "--seconds", "3"}, 2.0);
  EXPECT_EQ(served.exit_status, 0);
  expect_a_live_qr(served.heard, 2.0);
}

// qrsim --serve with the side channel (--truth-fd) on a socket, for `seconds`: command lines in,
// the lines it answers collected.
class TruthSide {
 public:
  explicit TruthSide(const char* seconds) {
    int pair[2];
    if (socketpair(AF_UNIX, SOCK_STREAM, 0, pair) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      close(pair[0]);  // first: it may be descriptor 3
      dup2(pair[1], 3);
      const int null = open("/dev/null", O_RDWR);
      dup2(null, STDIN_FILENO);
      dup2(null, STDOUT_FILENO);
      execl(QRSIM_PATH, "qrsim", "--serve", "--stdio", "--seconds", seconds, "--truth-fd", "3",
            static_cast<char*>(nullptr));
      _exit(127);
    }
    close(pair[1]);
    fd_ = pair[0];
  }
  bool started() const { return pid_ > 0 && fd_ >= 0; }

  void send(const std::string& line) {
    ASSERT_EQ(write(fd_, line.data(), line.size()), static_cast<ssize_t>(line.size()));
  }
  // Collects lines for `seconds` of wall-clock time.
  void listen(double seconds) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < end) {
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 10) <= 0) continue;
      char buffer[1024];
      const ssize_t n = read(fd_, buffer, sizeof buffer);
      if (n <= 0) break;
      for (ssize_t i = 0; i < n; ++i) {
        if (buffer[i] == '\n') {
          lines.push_back(pending_);
          pending_.clear();
        } else {
          pending_ += buffer[i];
        }
      }
    }
  }
  std::string last_truth() const {
    for (auto it = lines.rbegin(); it != lines.rend(); ++it)
      if (it->rfind("truth t=", 0) == 0) return *it;
    return "";
  }
  // Waits for the program's end: its exit status.
  int finish() {
    close(fd_);
    int status = 0;
    waitpid(pid_, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  std::vector<std::string> lines;

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string pending_;
};

// A truth line's field ("roll", "height", ...); NaN when the line has none.
double field_of(const std::string& line, const std::string& name) {
  const size_t at = line.find(" " + name + "=");
  return at == std::string::npos ? std::nan("") : std::strtod(line.c_str() + at + name.size() + 2, nullptr);
}

// The side channel (--truth-fd): truth lines every 20 ms of simulated time, a bad command answered
// with an error line, and a push that tips the QR where it stands (roll moves by more than a degree).
TEST(Qrsim, TruthChannelReportsAndPushes) {
  TruthSide side("4");
  ASSERT_TRUE(side.started());
  side.listen(1.0);
  size_t truths = 0;
  for (const std::string& l : side.lines) truths += l.rfind("truth t=", 0) == 0 ? 1 : 0;
  EXPECT_GT(truths, 25u);  // 50 a second of simulated time, which runs at wall-clock pace
  const std::string before = side.last_truth();
  ASSERT_FALSE(before.empty());
  EXPECT_NE(before.find(" pitch="), std::string::npos) << before;
  EXPECT_NE(before.find(" height="), std::string::npos) << before;
  EXPECT_NE(before.find(" climb="), std::string::npos) << before;

  side.send("shove 1 2\n");
  side.send("push 3 0 0 0.3\n");
  double most = 0;
  const size_t from = side.lines.size();
  side.listen(1.0);
  bool error_seen = false;
  for (size_t i = from; i < side.lines.size(); ++i) {
    if (side.lines[i].rfind("error unknown command 'shove'", 0) == 0) error_seen = true;
    const double r = field_of(side.lines[i], "roll");
    if (std::isfinite(r)) most = std::max(most, std::fabs(r - field_of(before, "roll")));
  }
  EXPECT_TRUE(error_seen);
  EXPECT_GT(most, 1.0) << before << " / " << side.last_truth();
  EXPECT_EQ(side.finish(), 0);
}

// A hand turn from the side channel (the firmware in safe, engines still): answered "ok turn", a
// second one while it acts refused, the truth rolls over (half-way round it is upside down) and
// ends level where it stood.
TEST(Qrsim, TruthChannelTurnsTheVehicle) {
  TruthSide side("4");
  ASSERT_TRUE(side.started());
  side.listen(0.5);
  const std::string before = side.last_truth();
  ASSERT_FALSE(before.empty());
  side.send("turn x 1 2\n");
  side.listen(0.3);
  side.send("turn y 1 2\n");
  side.listen(2.5);
  bool accepted = false, refused = false;
  double most = 0;
  for (const std::string& l : side.lines) {
    accepted = accepted || l == "ok turn";
    refused = refused || l == "error turn: a turn is under way";
    const double r = field_of(l, "roll");
    if (std::isfinite(r)) most = std::max(most, std::fabs(r));
  }
  EXPECT_TRUE(accepted);
  EXPECT_TRUE(refused);
  EXPECT_GT(most, 170.0) << "upside down half-way round";
  const std::string after = side.last_truth();
  EXPECT_NEAR(field_of(after, "roll"), field_of(before, "roll"), 0.01) << after;
  EXPECT_NEAR(field_of(after, "pitch"), field_of(before, "pitch"), 0.01) << after;
  EXPECT_NEAR(field_of(after, "height"), field_of(before, "height"), 0.001) << after;
  EXPECT_EQ(side.finish(), 0);
}

// Everything qrsim prints for a command line (stdout and stderr together) and its exit status.
struct QrsimRun {
  std::string out;
  int status = -1;
};

QrsimRun run_qrsim(const std::string& arguments) {
  QrsimRun run;
  FILE* out = popen((std::string(QRSIM_PATH) + " " + arguments + " 2>&1").c_str(), "r");
  if (out == nullptr) return run;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, out)) > 0;) run.out.append(buffer, n);
  const int status = pclose(out);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// A scenario file that does not read names its line and points to where the format is described
// (docs/simulator.md section 6.2), not to --help, which lists the options only; --help points
// there too.
TEST(Qrsim, BadScenarioFilePointsToTheFormatNotTheHelp) {
  const std::string path = ::testing::TempDir() + "qrsim_bad_scenario.txt";
  FILE* file = std::fopen(path.c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fputs("seconds: 3\nat 1 roll ten\nband final_mode == full\n", file);
  std::fclose(file);
  const QrsimRun bad = run_qrsim("--scenario " + path);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("qrsim_bad_scenario.txt:2: bad number 'ten'"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("docs/simulator.md section 6.2"), std::string::npos) << bad.out;
  EXPECT_EQ(bad.out.find("--help"), std::string::npos) << bad.out;
  const QrsimRun help = run_qrsim("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("docs/simulator.md section 6.2"), std::string::npos) << help.out;
}

// --param out of its range: the message says the range and the unit (max_yaw_rate_rad_s is
// written in rad/s, carried in Q10).
TEST(Qrsim, ScenarioParamOutOfRangeSaysTheRange) {
  const QrsimRun run = run_qrsim("--scenario hover --param max_yaw_rate_rad_s=9");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.out.find("parameter max_yaw_rate_rad_s: 9 is out of its range 0 .. 8 (rad/s)"), std::string::npos)
      << run.out;
}

// Without --json the notes go to stderr beside the figures, so a clamped stick is not missed.
TEST(Qrsim, ScenarioNotesGoToStderr) {
  const std::string path = ::testing::TempDir() + "qrsim_note_scenario.txt";
  FILE* file = std::fopen(path.c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fputs("seconds: 1\nat 0.5 roll 45\nband final_mode == full\n", file);
  std::fclose(file);
  // stderr alone: onto the pipe, stdout (the figures) away.
  FILE* out = popen((std::string(QRSIM_PATH) + " --scenario " + path + " 2>&1 >/dev/null").c_str(), "r");
  ASSERT_NE(out, nullptr);
  QrsimRun stderr_only;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, out)) > 0;) stderr_only.out.append(buffer, n);
  pclose(out);
  EXPECT_NE(stderr_only.out.find(
                "qrsim: note: at 0.5 s: roll 45 deg asks for more than max_tilt_mrad allows (30 deg): the set-point "
                "is 30 deg"),
            std::string::npos)
      << stderr_only.out;
}

// The number after "KEY": in `json`, searched from the first occurrence of `within` on (NaN if absent).
double json_number_after(const std::string& json, const std::string& within, const std::string& key) {
  const size_t from = json.find(within);
  if (from == std::string::npos) return std::nan("");
  const size_t at = json.find("\"" + key + "\": ", from);
  return at == std::string::npos ? std::nan("") : std::strtod(json.c_str() + at + key.size() + 4, nullptr);
}

// qrsim --autotune (issue 34, docs/signal-chain.md "Autotune: the identification flight"): the
// identification flown on the default vehicle, each axis' fitted gain and lag within 15 % of the
// vehicle file's truth, gains that keep the design's targets on the models, and its params taken
// back unchanged by --param: the step they fly passes step-roll's bands on the truth.
TEST(Qrsim, AutotuneFitsEachAxisAndItsParamsFlyAsParams) {
  const QrsimRun tune = run_qrsim("--autotune");
  ASSERT_EQ(tune.status, 0) << tune.out;
  const size_t ratios = tune.out.find("\"model_over_truth\"");
  ASSERT_NE(ratios, std::string::npos) << tune.out;
  const std::string rest = tune.out.substr(ratios);
  for (const char* axis : {"roll", "pitch", "yaw"}) {
    EXPECT_NEAR(json_number_after(rest, std::string("\"") + axis + "\"", "gain"), 1, 0.15) << axis << ": " << rest;
    EXPECT_NEAR(json_number_after(rest, std::string("\"") + axis + "\"", "motor_tau_s"), 1, 0.15)
        << axis << ": " << rest;
  }
  EXPECT_NE(tune.out.find("\"keeps_targets\": true"), std::string::npos) << tune.out;
  const size_t params = tune.out.find("\"params\": {");
  ASSERT_NE(params, std::string::npos) << tune.out;
  const size_t open = tune.out.find('{', params), close = tune.out.find('}', open);
  std::string arguments, names;
  for (size_t at = open + 1; at < close;) {
    const size_t name_start = tune.out.find('"', at) + 1, name_end = tune.out.find('"', name_start);
    const size_t value_start = name_end + 3, value_end = std::min(tune.out.find(',', value_start), close);
    const std::string name = tune.out.substr(name_start, name_end - name_start);
    arguments += " --param " + name + "=" + tune.out.substr(value_start, value_end - value_start);
    names += name + " ";
    at = value_end + 1;
  }
  EXPECT_EQ(names, "roll_pitch_p1 roll_pitch_p2 roll_pitch_i roll_pitch_d yaw_p yaw_i ");
  const QrsimRun step = run_qrsim("--scenario step-roll --json" + arguments);
  EXPECT_EQ(step.status, 0) << arguments << "\n" << step.out;
  // Faster than the defaults' 0.25 s (docs/signal-chain.md "Defaults and why"), within the band.
  EXPECT_LT(json_number_after(step.out, "{", "rise_s"), 0.22) << step.out;
  EXPECT_LT(json_number_after(step.out, "{", "overshoot_pct"), 8) << step.out;
}

// The identification flies the host firmware over the PC link: the devboard's link carries no
// moments and the radio's pilot would move the sticks, which ends the mode.
TEST(Qrsim, AutotuneRefusesTheDevboardAndTheRadio) {
  for (const char* option : {"--rc crsf", "--devboard"}) {
    const QrsimRun run = run_qrsim(std::string("--autotune ") + option);
    EXPECT_EQ(run.status, 2) << option;
    EXPECT_NE(run.out.find("--autotune flies the host firmware from the PC link"), std::string::npos) << run.out;
  }
}

// --sensors: the host firmware reads the chips through its drivers by default (the JSON's sensor
// figures are numbers), --sensors direct gives it the plant's sample (they are null), and any
// other word is refused.
TEST(Qrsim, SensorsThroughTheDriversByDefaultOrDirect) {
  const QrsimRun drivers = run_qrsim("--scenario step-roll --json");
  EXPECT_EQ(drivers.status, 0) << drivers.out;
  EXPECT_EQ(drivers.out.find("\"imu_samples\": null"), std::string::npos) << drivers.out;
  EXPECT_NE(drivers.out.find("\"imu_faults\": 1,"), std::string::npos) << drivers.out;
  const QrsimRun direct = run_qrsim("--scenario step-roll --json --sensors direct");
  EXPECT_EQ(direct.status, 0) << direct.out;
  EXPECT_NE(direct.out.find("\"imu_samples\": null"), std::string::npos) << direct.out;
  const QrsimRun bad = run_qrsim("--scenario step-roll --sensors spi");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("--sensors is drivers or direct"), std::string::npos) << bad.out;
}

}  // namespace
