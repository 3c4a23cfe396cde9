// A 10,000-line log downloaded from the firmware over a line that loses 5 % of the frames, flips
// bits at 1e-4 and duplicates some: every line arrives whole, exactly once, in order.
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
constexpr size_t kLineBytes = RecordLog<wire::SensorLogRecord>::kRecordBytes + RecordLog<Record>::kRecordBytes;

TEST(LogDownload, TenThousandLinesOverALossyLineArriveWholeOnceAndInOrder) {
  fake::FakeBoard board;
  std::vector<uint8_t> memory(kLines * kLineBytes);
  Firmware flight{LogArea{memory.data(), memory.size()}};
  Scheduler<fake::FakeBoard, Firmware> scheduler{board, flight};
  const auto feed = [&](const wire::FrameBytes& f) { board.rx.insert(board.rx.end(), f.bytes, f.bytes + f.size); };

  // Fill the log on a clean line: a line every tick until it is full.
  feed(wire::encode(wire::ParamSet{1, static_cast<uint8_t>(wire::ParamId::log_divider), 1}));
  feed(wire::encode(wire::LogStart{2, wire::kLogTelemetry}));
  for (uint32_t i = 0; i < kLines + 200u; ++i) scheduler.tick();
  feed(wire::encode(wire::LogStop{3}));
  for (int i = 0; i < 10; ++i) scheduler.tick();
  ASSERT_EQ(flight.log().status().telemetry_lines, kLines);
  board.tx.clear();

  // Now the faulty line, both ways.
  wire_test::ChannelFaults faults;
  faults.bit_error_rate = 1e-4;
  faults.frame_loss = 0.05;
  faults.duplicate = 0.01;
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
    if (downloader.next_request(now_ms, first, count)) {
      up.send(requests.submit(wire::LogDownload{0, wire::LogKind::telemetry, first, count}, now_ms));
    }
    wire::ResendEvent event;
    while (requests.poll(now_ms, event)) {
      if (event.kind == wire::ResendEvent::Kind::resend) up.send(event.frame);
      if (event.kind == wire::ResendEvent::Kind::gave_up) ++gave_up;
    }
    for (uint8_t b : up.deliver()) board.rx.push_back(b);
    for (; ticked_us + kPeriodUs <= uint64_t{now_ms} * 1000u; ticked_us += kPeriodUs) scheduler.tick();
    for (uint8_t b : board.tx) {
      qr_out.push(b, [&](const wire::Frame& f) { down.send(wire::make_frame(f.type, f.payload, f.length)); });
    }
    board.tx.clear();
    Console console{requests, downloader, lines, deliveries, now_ms};
    for (uint8_t b : down.deliver()) {
      pc_in.push(b, [&](const wire::Frame& f) {
        down.accepted(f);
        wire::dispatch(f, console);
      });
    }
  }

  ASSERT_TRUE(downloader.done()) << downloader.received() << " of " << kLines << " lines after " << now_ms << " ms";
  for (uint16_t line = 0; line < kLines; ++line) {
    ASSERT_EQ(deliveries[line], 1) << "line " << line;
    ASSERT_EQ(lines[line].line, line);
    ASSERT_EQ(lines[line].phi, 123) << "line " << line << " is not the record that was logged";
    if (line > 0) ASSERT_EQ(lines[line].time_us - lines[line - 1].time_us, kPeriodUs) << "line " << line;
  }
  EXPECT_EQ(gave_up, 0u);
  down.finish();
  EXPECT_EQ(down.accepted_false(), 0u);
  std::printf(
      "{\"lines\":%u,\"rerequests\":%u,\"frames_sent\":%llu,\"frames_dropped\":%llu,\"frames_corrupted\":%llu,"
      "\"corrupt_accepted\":%llu,\"sim_seconds\":%.1f}\n",
      downloader.received(), downloader.rerequests(), static_cast<unsigned long long>(down.frames_sent()),
      static_cast<unsigned long long>(down.frames_dropped()), static_cast<unsigned long long>(down.frames_corrupted()),
      static_cast<unsigned long long>(down.accepted_false()), now_ms / 1000.0);
}

}  // namespace
}  // namespace qr
