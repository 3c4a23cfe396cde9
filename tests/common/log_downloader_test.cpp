// The console's side of a log download (common/log_downloader.hpp): parts kept across passes, and,
// told the parser's damage, no part kept that a lost byte may have spliced.
#include <gtest/gtest.h>

#include <vector>

#include <common/log_downloader.hpp>
#include <common/messages.hpp>

#include "golden_frames.hpp"

using namespace wire;

namespace {

using Downloader = LogDownloader<SensorLogRecord, 1024>;

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

}  // namespace

TEST(LogDownloader, ALinesPartsAreKeptAcrossPasses) {
  Downloader d;
  Lines lines;
  d.begin(1);
  const SensorLogRecord sent = line(0);
  // First pass: every part but the last; second pass: only the last.
  for (uint8_t p = 0; p + 1 < SensorLogRecord::kParts; ++p) d.on_part(make_log_part(sent, p), 0, lines);
  EXPECT_TRUE(lines.got.empty());
  d.on_part(make_log_part(sent, SensorLogRecord::kParts - 1), 300, lines);
  ASSERT_EQ(lines.got.size(), 1u);
  EXPECT_TRUE(same(lines.got[0], sent));
  EXPECT_TRUE(d.done());
}

TEST(LogDownloader, APartNextToDamageIsNotKept) {
  Downloader d;
  Lines lines;
  d.begin(1);
  const SensorLogRecord sent = line(0);
  uint32_t damage = 0;
  const auto frame = [&](const SensorLogPart& part) {
    d.frame_accepted(damage, lines);
    d.on_part(part, 0, lines);
  };
  d.frame_accepted(damage, lines);  // a frame before the download: the receiver counts from here
  for (uint8_t p = 0; p + 1 < SensorLogRecord::kParts; ++p) frame(make_log_part(sent, p));
  // The last part comes spliced: a lost byte shifted its data, and the check happened to pass.
  SensorLogPart spliced = make_log_part(sent, SensorLogRecord::kParts - 1);
  spliced.data[0] ^= 0x5A;
  frame(spliced);
  damage += 3;  // what the splice left of the next frame was skipped
  d.frame_accepted(damage, lines);
  EXPECT_TRUE(lines.got.empty()) << "a part followed by damage must not complete a line";
  // The next pass brings the part whole, with clean frames either side.
  frame(make_log_part(sent, SensorLogRecord::kParts - 1));
  EXPECT_TRUE(lines.got.empty()) << "kept only once the frame after it shows no damage";
  d.frame_accepted(damage, lines);
  ASSERT_EQ(lines.got.size(), 1u);
  EXPECT_TRUE(same(lines.got[0], sent));
}

TEST(LogDownloader, APartAfterDamageIsNotKept) {
  Downloader d;
  Lines lines;
  d.begin(1);
  const SensorLogRecord sent = line(0);
  uint32_t damage = 0;
  d.frame_accepted(damage, lines);
  for (uint8_t p = 0; p < SensorLogRecord::kParts; ++p) {
    if (p == 2) damage += 1;  // bytes skipped just before part 2
    d.frame_accepted(damage, lines);
    d.on_part(make_log_part(sent, p), 0, lines);
  }
  d.frame_accepted(damage, lines);
  EXPECT_TRUE(lines.got.empty()) << "part 2 came right after damage: asked for again";
  EXPECT_FALSE(d.done());
}
