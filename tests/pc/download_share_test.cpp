// A log download beside a plot stream (issue 36, docs/protocol.md section 13.6): while a download
// runs the console lowers the plot's stream to a tenth of the line and restores it after.
//
// The StreamSession's rule on its own, and then the whole console (its model, pc/core) against
// the firmware's host build on the simulator's 115200-baud line, in simulated time: the same log
// downloaded on a quiet line and beside `phi phi_sp` at 1000 Hz (6000 of the line's 11520 B/s);
// the second keeps at least 80 % of the first's rate, brings the same files, and the stream is
// back at its rate afterwards.
#include <gtest/gtest.h>

#include <stdint.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/sample_packing.hpp>
#include <pc/core/console.hpp>
#include <pc/core/stream_session.hpp>
#include <qr/boards/sim/sim_qr.hpp>

#include "console_bench.hpp"
#include "observable_table_feed.hpp"

namespace {

using qrterm::StreamSession;

// --- the rule: the StreamSession with a download running

struct PlotStream : ::testing::Test {
  std::vector<std::string> notes;
  StreamSession session{
      StreamSession::Hooks{[this](qrterm::Severity, const std::string& t) { notes.push_back(t); }, {}, {}}};
  qrterm::LinkSession link{0, 1};

  PlotStream() { qrterm::send_observable_table(session); }

  // Ticks and acks until no request goes out: the dividers asked for, in order.
  std::vector<uint16_t> settle() {
    std::vector<uint16_t> dividers;
    for (int i = 0; i < 10; ++i) {
      session.tick(link, 0);
      wire::FrameParser parser{wire::Listen::pc_to_qr};
      bool asked = false;
      for (uint8_t b : link.output()) {
        parser.push(b, [&](const wire::Frame& f) {
          wire::StreamRequest r;
          if (f.type == wire::MessageType::stream_request && wire::decode(f, r)) {
            dividers.push_back(r.divider);
            asked = true;
          }
        });
      }
      link.output().clear();
      if (!asked) break;
      session.on_answer(wire::MessageType::stream_request, wire::NackReason::none, 50);
    }
    return dividers;
  }

  // The pilot's selection at the plot's fastest rate, streaming.
  void pick_at_1000_hz(const std::string& names) {
    session.pick(names);
    for (int i = 0; i < 3; ++i) session.faster();  // 200 -> 500 -> 1000 Hz
    ASSERT_EQ(settle(), std::vector<uint16_t>{1});
    ASSERT_EQ(session.state(), "streaming");
  }
};

TEST_F(PlotStream, ADownloadLowersItToATenthOfTheLineAndItsEndRestoresIt) {
  pick_at_1000_hz("phi phi_sp");
  session.download_running(true);
  // 2 observables: 100 Hz is 600 B/s, 200 Hz would be 1200 of the 1152 allowed.
  EXPECT_EQ(settle(), std::vector<uint16_t>{10});
  EXPECT_TRUE(session.lowered());
  EXPECT_EQ(session.state(), "streaming at 100 Hz during the download");
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes.back(),
            "the plot's stream lowered to 100 Hz during the log download (1000 Hz would slow it; back after)");

  // The samples of the lowered stream are 10 ms apart on the plot, not 1 ms.
  wire::SamplePacker packer;
  packer.start(0, 2);
  for (int s = 0; s < 2; ++s) {
    const int16_t values[2] = {static_cast<int16_t>(s * 100), 0};
    wire::ObservableSamples frame;
    if (packer.add(values, frame)) session.on(frame, 2.0);
  }
  const auto& points = session.plot().traces()[0].points;
  ASSERT_EQ(points.size(), 2u);
  EXPECT_NEAR(points[1].t_s - points[0].t_s, 0.010, 1e-12);

  session.download_running(false);
  EXPECT_EQ(settle(), std::vector<uint16_t>{1}) << "the pilot's rate again";
  EXPECT_FALSE(session.lowered());
  EXPECT_EQ(session.state(), "streaming");
  EXPECT_EQ(notes.back(), "log download over: the plot's stream back to 1000 Hz");
}

TEST_F(PlotStream, EachSelectionIsLoweredToItsOwnFastestRateThatFits) {
  // One observable: 4 samples a frame, 200 Hz is 600 B/s (500 Hz, 1500).
  pick_at_1000_hz("phi");
  session.download_running(true);
  EXPECT_EQ(settle(), std::vector<uint16_t>{5});
  session.download_running(false);
  EXPECT_EQ(settle(), std::vector<uint16_t>{1});
  // Four: a sample a frame, 50 Hz is 600 B/s (100 Hz, 1200).
  session.pick("theta psi p");
  EXPECT_EQ(settle(), std::vector<uint16_t>{1});
  session.download_running(true);
  EXPECT_EQ(settle(), std::vector<uint16_t>{20});
  // The pilot slows it during the download: the slower of the two.
  for (int i = 0; i < 6; ++i) session.slower();  // 1000 -> 10 Hz
  EXPECT_EQ(settle(), std::vector<uint16_t>{100});
  EXPECT_FALSE(session.lowered());
}

TEST_F(PlotStream, ASelectionThatFitsIsLeftAloneAndNothingIsSaid) {
  session.pick("phi phi_sp");                    // 200 Hz: 1200 B/s
  for (int i = 0; i < 2; ++i) session.slower();  // 50 Hz: 300 B/s
  ASSERT_EQ(settle(), std::vector<uint16_t>{20});
  notes.clear();
  session.download_running(true);
  EXPECT_TRUE(settle().empty());
  session.download_running(false);
  EXPECT_TRUE(settle().empty());
  EXPECT_TRUE(notes.empty());
}

TEST_F(PlotStream, AutotunesIdentificationKeepsEverySample) {
  session.carry({static_cast<uint8_t>(wire::ObservableId::p), static_cast<uint8_t>(wire::ObservableId::roll_moment)});
  ASSERT_EQ(settle(), std::vector<uint16_t>{1});
  session.download_running(true);
  EXPECT_TRUE(settle().empty());
  EXPECT_FALSE(session.lowered());
}

// --- the whole console against the firmware on the simulated line

// The console's clock when the simulated QR starts.
constexpr uint32_t kStartMs = 5000;

// qrterm's model on one end of the simulated QR's serial line and the host firmware on the other,
// a control period (1 ms) a step: the QR's tick, what has arrived to the console, the console's
// tick, and its bytes onto the line towards the QR.
struct ConsoleOnTheLine {
  ConsoleOnTheLine()
      : qr(qrsim::make_qr(sim::default_vehicle(), sim::WorldConfig{.seed = 1})), console(log, files(), setup(), now()) {
  }

  uint32_t now() const { return kStartMs + static_cast<uint32_t>(qr->world.now_us() / 1000); }

  void run(uint32_t ms) {
    std::vector<uint8_t> down;
    for (uint32_t i = 0; i < ms; ++i) {
      qr->tick();
      down.clear();
      for (uint8_t byte = 0; qr->board.pc_receive(byte);) down.push_back(byte);
      console.receive(down.data(), down.size(), now());
      console.tick(now());
      for (uint8_t byte : console.output()) qr->board.pc_send(byte);
      console.output().clear();
    }
  }

  template <class Condition>
  bool run_until(Condition condition, uint32_t limit_ms) {
    for (uint32_t i = 0; i < limit_ms; ++i) {
      if (condition()) return true;
      run(1);
    }
    return condition();
  }

  void keys(const std::string& typed) {
    for (char c : typed) console.key(static_cast<qrterm::Key>(c), now());
  }

  // The plot's samples per second over `ms` of the line.
  double samples_per_s(uint32_t ms) {
    const uint32_t before = console.streams().samples_received();
    run(ms);
    return (console.streams().samples_received() - before) * 1000.0 / ms;
  }

  static qrterm::Console::Setup setup() {
    qrterm::Console::Setup s;
    s.params.set(static_cast<uint8_t>(wire::ParamId::log_divider), 1);  // a line every control period
    return s;
  }
  qrterm::ConsoleFiles files() {
    qrterm::ConsoleFiles f;
    f.open = [this](const std::string& name) -> std::unique_ptr<std::ostream> {
      return std::make_unique<qrterm_test::CapturedFile>(written[name]);
    };
    f.rename = [this](const std::string& from, const std::string& to) {
      written[to] = written[from];
      written.erase(from);
      return true;
    };
    return f;
  }

  // In this order: the console reads the QR's clock and takes the log and the files as it starts.
  std::unique_ptr<qrsim::SimQr> qr;
  qrterm::ConsoleLog log;
  std::map<std::string, std::string> written;  // the log folder's files
  qrterm::Console console;
};

// Both logs, from the key to the last file written: seconds of the line.
double download_s(ConsoleOnTheLine& line) {
  const uint32_t began = line.now();
  line.console.act(qrterm::Action::log_download, line.now());
  EXPECT_FALSE(line.console.download_status().empty());
  EXPECT_TRUE(line.run_until([&] { return line.console.download_status().empty(); }, 30000));
  return (line.now() - began) / 1000.0;
}

size_t rows(const std::string& csv) {
  size_t n = 0;
  for (char c : csv) n += c == '\n' ? 1 : 0;
  return n;
}

TEST(DownloadShare, ADownloadBesideAStreamKeepsFourFifthsOfItsRate) {
  ConsoleOnTheLine line;
  qrterm::Console& console = line.console;
  ASSERT_TRUE(line.run_until(
      [&] { return console.streams().catalog().complete() && console.parameters_to_send() == 0; }, 3000));

  // 0.4 s of both logs at a line a control period.
  console.act(qrterm::Action::log_start, line.now());
  line.run(400);
  console.act(qrterm::Action::log_stop, line.now());
  ASSERT_TRUE(line.run_until(
      [&] {
        const auto& status = console.telemetry().log_status;
        return status && status->flags == 0 && status->sensor_lines > 0;
      },
      1000));
  const wire::LogStatus status = *console.telemetry().log_status;
  const uint32_t lines = uint32_t{status.sensor_lines} + status.telemetry_lines;

  const double quiet_s = download_s(line);

  // The pilot's plot: phi and its set-point at 1000 Hz.
  line.keys("\t/phi phi_sp\r...");
  ASSERT_TRUE(line.run_until([&] { return console.streams().state() == "streaming"; }, 1000));
  const double stream_before = line.samples_per_s(300);
  ASSERT_GE(stream_before, 950) << "the stream runs at its rate before the download";

  const uint32_t samples_before = console.streams().samples_received();
  const double busy_s = download_s(line);
  const double stream_during = (console.streams().samples_received() - samples_before) / busy_s;

  // Back at the pilot's rate once the QR has the request.
  ASSERT_TRUE(line.run_until([&] { return console.streams().state() == "streaming"; }, 100));
  line.run(20);
  const double stream_after = line.samples_per_s(500);

  const double quiet = lines / quiet_s, busy = lines / busy_s;
  std::printf(
      "{\"download_share\": {\"lines\": %u, \"quiet_lines_per_s\": %.1f, \"busy_lines_per_s\": %.1f, "
      "\"ratio\": %.3f, \"stream_hz_before\": %.0f, \"stream_hz_during\": %.0f, \"stream_hz_after\": %.0f}}\n",
      lines, quiet, busy, busy / quiet, stream_before, stream_during, stream_after);
  EXPECT_GE(busy, 0.8 * quiet);
  EXPECT_TRUE(console.log().find_last("the plot's stream lowered to 100 Hz during the log download"));
  EXPECT_GT(stream_during, 80) << "the plot goes on, lowered";
  EXPECT_LT(stream_during, 110);
  EXPECT_GE(stream_after, 950) << "and is back at 1000 Hz after";

  // Nothing lost: every line of both logs, the same beside the stream as on the quiet line.
  for (const char* log : {"sensor", "telemetry"}) {
    const std::string first = line.written[std::string(log) + "_log_1.csv"];
    const std::string second = line.written[std::string(log) + "_log_2.csv"];
    EXPECT_EQ(rows(first), 1u + (log[0] == 's' ? status.sensor_lines : status.telemetry_lines)) << log;
    EXPECT_EQ(first, second) << log;
  }
}

}  // namespace
