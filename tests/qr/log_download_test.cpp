// A 10,000-line log downloaded from the firmware at 115200 baud, over a clean line and over one
// that loses 5 % of the frames, flips bits at 1e-4 and duplicates 1 %: every line arrives whole,
// exactly once, in order, and the bad line keeps at least 70 % of the clean line's rate (the
// lost parts are asked for again by part while the stream goes on, docs/protocol.md section 8).
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include <common/frame_parser.hpp>
#include <common/log_downloader.hpp>
#include <common/messages.hpp>
#include <common/resend_queue.hpp>
#include <qr/boards/fake/fake_board.hpp>
#include <qr/core/flight.hpp>
#include <qr/core/scheduler.hpp>

#include "../common/sim_channel.hpp"
#include "scripted_chain.hpp"

namespace qr {
namespace {

using Firmware = Flight<test::ScriptedChain>;
using Record = wire::TelemetryLogRecord;

constexpr uint16_t kLines = 10000;
constexpr size_t kLineBytes = wire::wire_size<Record>();  // more than a packed line takes

struct DownloadRun {
  uint32_t ms = 0;
  uint32_t rerequests = 0;
  uint64_t frames_sent = 0, frames_dropped = 0, frames_corrupted = 0, corrupt_accepted = 0;
  double lines_per_s() const { return ms == 0 ? 0 : kLines * 1000.0 / ms; }
};

// The firmware with a full telemetry log, then the download over `faults`, both ways. The QR's
// serial port sends 11.52 bytes a millisecond (115200 baud, 8N1), as the simulator's line does.
DownloadRun download(const wire_test::ChannelFaults& faults) {
  fake::FakeBoard board;
  std::vector<uint8_t> memory(kLines * kLineBytes + FlightLog<test::ScriptedChain>::kIndexBytes);
  Firmware flight{LogArea{memory.data(), memory.size()}};
  Scheduler<fake::FakeBoard, Firmware> scheduler{board, flight};
  const auto feed = [&](const wire::FrameBytes& f) { board.rx.insert(board.rx.end(), f.bytes, f.bytes + f.size); };

  // Fill the log on a clean line: a line every tick until it has kLines.
  feed(wire::encode(wire::ParamSet{1, static_cast<uint8_t>(wire::ParamId::log_divider), 1}));
  feed(wire::encode(wire::LogStart{2, wire::kLogTelemetry}));
  for (uint32_t i = 0; i < 2u * kLines && flight.log().status().telemetry_lines < kLines; ++i) scheduler.tick();
  feed(wire::encode(wire::LogStop{3}));
  for (int i = 0; i < 10; ++i) scheduler.tick();
  EXPECT_EQ(flight.log().status().telemetry_lines, kLines);
  board.tx.clear();
  // The UART: a byte leaves every 86.8 µs; the board takes what its FIFO has room for.
  constexpr double kBytesPerMs = 115200.0 / 10 / 1000;
  board.tx_capacity = 32;  // the sim board's transmit FIFO (docs/simulator.md section 4)
  double line_budget = 0;

  wire_test::SimChannel down(faults, 11), up(faults, 12);
  wire::FrameParser qr_out{wire::Listen::qr_to_pc};  // cuts the firmware's bytes into frames
  wire::FrameParser pc_in{wire::Listen::qr_to_pc};   // the console's receiver
  wire::ResendQueue requests(100);
  wire::LogDownloader<Record> downloader;
  downloader.begin(kLines);
  std::vector<Record> lines(kLines);
  std::vector<int> deliveries(kLines, 0);
  uint32_t gave_up = 0;

  struct Console {
    wire::ResendQueue& requests;
    wire::LogDownloader<Record>& downloader;
    std::vector<Record>& lines;
    std::vector<int>& deliveries;
    uint32_t now_ms;
    void operator()(const wire::Ack& a) { requests.on_ack(a); }
    void operator()(const wire::Nack& n) { requests.on_nack(n); }
    void operator()(const wire::TelemetryLogPart& p) {
      downloader.on_part(p, now_ms, [&](const Record& r) {
        lines[r.line] = r;
        ++deliveries[r.line];
      });
    }
  };

  uint32_t now_ms = 0;
  uint64_t ticked_us = 0;  // firmware periods run so far on the download's clock
  for (; now_ms < 1200000 && !downloader.done(); ++now_ms) {
    uint16_t first = 0, count = 0;
    if (downloader.next_download(now_ms, first, count)) {
      up.send(requests.submit(wire::LogDownload{0, wire::LogKind::telemetry, first, count}, now_ms));
    }
    wire::LogResend resend;
    if (!requests.pending(wire::MessageType::log_resend) && downloader.next_resend(now_ms, resend)) {
      up.send(requests.submit(resend, now_ms));
    }
    wire::ResendEvent event;
    while (requests.poll(now_ms, event)) {
      if (event.kind == wire::ResendEvent::Kind::resend) up.send(event.frame);
      if (event.kind == wire::ResendEvent::Kind::gave_up) ++gave_up;
    }
    for (uint8_t b : up.deliver()) board.rx.push_back(b);
    for (; ticked_us + kPeriodUs <= uint64_t{now_ms} * 1000u; ticked_us += kPeriodUs) scheduler.tick();
    line_budget += kBytesPerMs;
    size_t sent = 0;
    for (; sent < board.tx.size() && line_budget >= 1; ++sent, line_budget -= 1) {
      qr_out.push(board.tx[sent],
                  [&](const wire::Frame& f) { down.send(wire::make_frame(f.type, f.payload, f.length)); });
    }
    if (sent == board.tx.size()) line_budget = 0;  // an idle line saves no time for later
    board.tx.erase(board.tx.begin(), board.tx.begin() + static_cast<std::ptrdiff_t>(sent));
    Console console{requests, downloader, lines, deliveries, now_ms};
    for (uint8_t b : down.deliver()) {
      pc_in.push(b, [&](const wire::Frame& f) {
        down.accepted(f);
        wire::dispatch(f, console);
      });
    }
  }

  EXPECT_TRUE(downloader.done()) << downloader.received() << " of " << kLines << " lines after " << now_ms << " ms";
  for (uint16_t line = 0; line < kLines; ++line) {
    EXPECT_EQ(deliveries[line], 1) << "line " << line;
    EXPECT_EQ(lines[line].line, line);
    EXPECT_EQ(lines[line].phi, 123) << "line " << line << " is not the record that was logged";
    if (line > 0) EXPECT_EQ(lines[line].time_us - lines[line - 1].time_us, kPeriodUs) << "line " << line;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_EQ(gave_up, 0u);
  down.finish();
  return DownloadRun{now_ms,
                     downloader.rerequests(),
                     down.frames_sent(),
                     down.frames_dropped(),
                     down.frames_corrupted(),
                     down.accepted_false()};
}

TEST(LogDownload, TenThousandLinesOverALossyLineArriveWholeOnceInOrderAtSeventyPercentOfTheCleanRate) {
  const DownloadRun clean = download(wire_test::ChannelFaults{});
  ASSERT_FALSE(::testing::Test::HasFailure()) << "the clean line";
  wire_test::ChannelFaults faults;
  faults.bit_error_rate = 1e-4;
  faults.frame_loss = 0.05;
  faults.duplicate = 0.01;
  const DownloadRun bad = download(faults);
  ASSERT_FALSE(::testing::Test::HasFailure()) << "the faulty line";
  EXPECT_EQ(bad.corrupt_accepted, 0u);
  const double ratio = bad.lines_per_s() / clean.lines_per_s();
  std::printf(
      "{\"lines\":%u,\"clean_lines_per_s\":%.1f,\"faulty_lines_per_s\":%.1f,\"faulty_over_clean\":%.3f,"
      "\"rerequests\":%u,\"frames_sent\":%llu,\"frames_dropped\":%llu,\"frames_corrupted\":%llu,"
      "\"corrupt_accepted\":%llu,\"sim_seconds\":%.1f,\"clean_sim_seconds\":%.1f}\n",
      kLines, clean.lines_per_s(), bad.lines_per_s(), ratio, bad.rerequests,
      static_cast<unsigned long long>(bad.frames_sent), static_cast<unsigned long long>(bad.frames_dropped),
      static_cast<unsigned long long>(bad.frames_corrupted), static_cast<unsigned long long>(bad.corrupt_accepted),
      bad.ms / 1000.0, clean.ms / 1000.0);
  EXPECT_GE(ratio, 0.70) << "the bad line's download is slower than 70 % of the clean line's";
}

}  // namespace
}  // namespace qr
