// The console's download logic (common/log_downloader.hpp) on its own: the log is streamed once,
// lost parts are asked for by part while the stream goes on, parts of a line not yet whole are
// kept, whatever is still missing is asked for again once the line is quiet, and, told the
// parser's damage, no part is kept that a lost byte may have spliced.
#include <gtest/gtest.h>

#include <vector>

#include <common/log_downloader.hpp>
#include <common/messages.hpp>

#include "golden_frames.hpp"

namespace {

using Record = wire::SensorLogRecord;  // 5 parts a line
using Downloader = wire::LogDownloader<Record, 1024>;

Record line_record(uint16_t line) {
  Record r;
  r.line = line;
  r.time_us = 1000u * line;
  r.battery_mv = 11850;
  return r;
}

struct Download {
  Downloader downloader;
  std::vector<uint16_t> handed_on;

  explicit Download(uint16_t lines) { downloader.begin(lines); }
  void part(uint16_t line, uint8_t part, uint32_t now_ms) {
    downloader.on_part(wire::make_log_part(line_record(line), part), now_ms,
                       [&](const Record& r) { handed_on.push_back(r.line); });
  }
  void line(uint16_t line, uint32_t now_ms, int skip_part = -1) {
    for (uint8_t p = 0; p < Record::kParts; ++p) {
      if (p != skip_part) part(line, p, now_ms);
    }
  }
  // The (line, part) pairs a log_resend names.
  static std::vector<std::pair<uint16_t, uint8_t>> named(const wire::LogResend& r) {
    std::vector<std::pair<uint16_t, uint8_t>> out;
    for (size_t bit = 0; bit < wire::kLogResendMaskBytes * 8; ++bit) {
      if (r.wants(bit))
        out.emplace_back(static_cast<uint16_t>(r.first_line + bit / Record::kParts),
                         static_cast<uint8_t>(bit % Record::kParts));
    }
    return out;
  }
};

TEST(LogDownloader, StreamsTheLogOnceFromTheStart) {
  Download d(100);
  uint16_t first = 9, count = 9;
  ASSERT_TRUE(d.downloader.next_download(0, first, count));
  EXPECT_EQ(first, 0);
  EXPECT_EQ(count, 0) << "to the end";
  EXPECT_FALSE(d.downloader.next_download(1000, first, count)) << "once";
}

TEST(LogDownloader, AsksForALostPartAsSoonAsTheStreamHasPassedItsLine) {
  Download d(100);
  uint16_t first = 0, count = 0;
  d.downloader.next_download(0, first, count);
  d.line(0, 1);
  d.line(1, 2, /*skip_part=*/3);
  wire::LogResend r;
  EXPECT_FALSE(d.downloader.next_resend(3, r)) << "line 1 may still be on its way";
  d.line(2, 4, /*skip_part=*/0);  // line 2 is the newest: it may still be coming
  ASSERT_TRUE(d.downloader.next_resend(5, r));
  EXPECT_EQ(r.log, wire::LogKind::sensor);
  const auto parts = Download::named(r);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0], (std::pair<uint16_t, uint8_t>{1, 3})) << "the one part, not the line";
  EXPECT_FALSE(d.downloader.next_resend(8, r)) << "asked once";
  d.part(1, 3, 9);
  EXPECT_EQ(d.handed_on, (std::vector<uint16_t>{0, 1})) << "kept parts and the one resent make line 1";
}

TEST(LogDownloader, HandsEachLineOnOnceWhateverComesTwice) {
  Download d(10);
  d.line(4, 1);
  d.line(4, 2);
  d.part(4, 2, 3);
  EXPECT_EQ(d.handed_on, (std::vector<uint16_t>{4}));
  d.line(10, 4);  // no such line
  EXPECT_EQ(d.handed_on.size(), 1u);
  EXPECT_EQ(d.downloader.received(), 1u);
}

TEST(LogDownloader, OnceQuietAsksForEverythingStillMissingFromTheFirstMissingLine) {
  Download d(12);
  uint16_t first = 0, count = 0;
  d.downloader.next_download(0, first, count);
  for (uint16_t l = 0; l < 9; ++l) d.line(l, 10 + l, l == 4 ? 0 : -1);  // line 4 lost part 0; 9..11 lost whole
  wire::LogResend r;
  ASSERT_TRUE(d.downloader.next_resend(20, r));
  EXPECT_EQ(r.first_line, 4);
  EXPECT_FALSE(d.downloader.next_resend(21, r)) << "nothing else is behind the stream";
  // The resent part is lost too, and the stream has ended: after 250 ms of quiet, again, and
  // now the lines at the end as well.
  const uint32_t quiet = 20 + Downloader::kQuietMs;
  ASSERT_TRUE(d.downloader.next_resend(quiet, r));
  EXPECT_EQ(r.first_line, 4);
  auto parts = Download::named(r);
  ASSERT_EQ(parts.front(), (std::pair<uint16_t, uint8_t>{4, 0}));
  EXPECT_EQ(parts.size(), 1u + 3u * Record::kParts) << "line 4's part and every part of 9, 10, 11 (8 lines a request)";
  EXPECT_FALSE(d.downloader.next_resend(quiet + 1, r)) << "not again before it could have come";
  d.part(4, 0, quiet + 2);
  for (uint16_t l = 9; l < 12; ++l) d.line(l, quiet + 3);
  EXPECT_TRUE(d.downloader.done());
  EXPECT_EQ(d.downloader.rerequests(), 2u);
}


namespace damage {

using namespace wire;

struct Lines {
  std::vector<SensorLogRecord> got;
  void operator()(const SensorLogRecord& r) { got.push_back(r); }
};

SensorLogRecord line(uint16_t n) {
  SensorLogRecord r = wire_test::golden_sensor_record();
  r.line = n;
  r.time_us = 1000u * n;
  return r;
}

bool same(const SensorLogRecord& a, const SensorLogRecord& b) {
  for (uint8_t p = 0; p < SensorLogRecord::kParts; ++p) {
    if (!(make_log_part(a, p) == make_log_part(b, p))) return false;
  }
  return true;
}


}  // namespace damage

}  // namespace

TEST(LogDownloaderDamage, ALinesPartsAreKeptAcrossPasses) {
  Downloader d;
  damage::Lines lines;
  d.begin(1);
  const wire::SensorLogRecord sent = damage::line(0);
  // First pass: every part but the last; second pass: only the last.
  for (uint8_t p = 0; p + 1 < wire::SensorLogRecord::kParts; ++p) d.on_part(wire::make_log_part(sent, p), 0, lines);
  EXPECT_TRUE(lines.got.empty());
  d.on_part(wire::make_log_part(sent, wire::SensorLogRecord::kParts - 1), 300, lines);
  ASSERT_EQ(lines.got.size(), 1u);
  EXPECT_TRUE(damage::same(lines.got[0], sent));
  EXPECT_TRUE(d.done());
}

TEST(LogDownloaderDamage, APartNextToDamageIsNotKept) {
  Downloader d;
  damage::Lines lines;
  d.begin(1);
  const wire::SensorLogRecord sent = damage::line(0);
  uint32_t damage = 0;
  const auto frame = [&](const wire::SensorLogPart& part) {
    d.frame_accepted(damage, lines);
    d.on_part(part, 0, lines);
  };
  d.frame_accepted(damage, lines);  // a frame before the download: the receiver counts from here
  for (uint8_t p = 0; p + 1 < wire::SensorLogRecord::kParts; ++p) frame(wire::make_log_part(sent, p));
  // The last part comes spliced: a lost byte shifted its data, and the check happened to pass.
  wire::SensorLogPart spliced = wire::make_log_part(sent, wire::SensorLogRecord::kParts - 1);
  spliced.data[0] ^= 0x5A;
  frame(spliced);
  damage += 3;  // what the splice left of the next frame was skipped
  d.frame_accepted(damage, lines);
  EXPECT_TRUE(lines.got.empty()) << "a part followed by damage must not complete a line";
  // The next pass brings the part whole, with clean frames either side.
  frame(wire::make_log_part(sent, wire::SensorLogRecord::kParts - 1));
  EXPECT_TRUE(lines.got.empty()) << "kept only once the frame after it shows no damage";
  d.frame_accepted(damage, lines);
  ASSERT_EQ(lines.got.size(), 1u);
  EXPECT_TRUE(damage::same(lines.got[0], sent));
}

TEST(LogDownloaderDamage, APartAfterDamageIsNotKept) {
  Downloader d;
  damage::Lines lines;
  d.begin(1);
  const wire::SensorLogRecord sent = damage::line(0);
  uint32_t damage = 0;
  d.frame_accepted(damage, lines);
  for (uint8_t p = 0; p < wire::SensorLogRecord::kParts; ++p) {
    if (p == 2) damage += 1;  // bytes skipped just before part 2
    d.frame_accepted(damage, lines);
    d.on_part(wire::make_log_part(sent, p), 0, lines);
  }
  d.frame_accepted(damage, lines);
  EXPECT_TRUE(lines.got.empty()) << "part 2 came right after damage: asked for again";
  EXPECT_FALSE(d.done());
}
