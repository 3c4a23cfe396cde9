// Log lines in parts: split, sent, put back together; missing and repeated parts.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <common/messages.hpp>

#include "golden_frames.hpp"
#include "wire_test_support.hpp"

using namespace wire;

namespace {

template <class Record>
std::vector<LogPart<Record>> parts_over_the_wire(const Record& record) {
  std::vector<LogPart<Record>> parts;
  for (uint8_t k = 0; k < Record::kParts; ++k) {
    LogPart<Record> decoded;
    EXPECT_TRUE(decode(wire_test::frame_of(encode(make_log_part(record, k))), decoded));
    parts.push_back(decoded);
  }
  return parts;
}

}  // namespace

TEST(LogRecords, ARecordFillsItsPartsExactly) {
  EXPECT_EQ(wire_size<SensorLogRecord>(), size_t{SensorLogRecord::kParts} * kLogPartDataBytes);
  EXPECT_EQ(wire_size<TelemetryLogRecord>(), size_t{TelemetryLogRecord::kParts} * kLogPartDataBytes);
}

TEST(LogRecords, PartsInAnyOrderGiveBackTheLine) {
  const SensorLogRecord sent = wire_test::golden_sensor_record();
  std::vector<SensorLogPart> parts = parts_over_the_wire(sent);
  std::mt19937 rng(3);
  for (int round = 0; round < 20; ++round) {
    std::shuffle(parts.begin(), parts.end(), rng);
    LogLineAssembler<SensorLogRecord> assembler;
    SensorLogRecord got;
    for (size_t i = 0; i < parts.size(); ++i) {
      const auto result = assembler.add(parts[i], got);
      EXPECT_EQ(result, i + 1 == parts.size() ? LogLineAssembler<SensorLogRecord>::Result::complete
                                              : LogLineAssembler<SensorLogRecord>::Result::incomplete);
    }
    EXPECT_TRUE(got == sent);
  }
}

TEST(LogRecords, TelemetryLinesToo) {
  const TelemetryLogRecord sent = wire_test::golden_telemetry_record();
  LogLineAssembler<TelemetryLogRecord> assembler;
  TelemetryLogRecord got;
  int complete = 0;
  for (const TelemetryLogPart& p : parts_over_the_wire(sent)) {
    complete += assembler.add(p, got) == LogLineAssembler<TelemetryLogRecord>::Result::complete ? 1 : 0;
  }
  EXPECT_EQ(complete, 1);
  EXPECT_TRUE(got == sent);
}

TEST(LogRecords, ALineMissingAPartIsAbandonedWhenTheNextLineStarts) {
  SensorLogRecord line5 = wire_test::golden_sensor_record();
  line5.line = 5;
  SensorLogRecord line6 = line5;
  line6.line = 6;
  line6.time_us += 1000;
  LogLineAssembler<SensorLogRecord> assembler;
  SensorLogRecord got;
  std::vector<SensorLogPart> parts5 = parts_over_the_wire(line5);
  parts5.erase(parts5.begin() + 2);
  for (const SensorLogPart& p : parts5)
    EXPECT_EQ(assembler.add(p, got), LogLineAssembler<SensorLogRecord>::Result::incomplete);
  int complete = 0;
  for (const SensorLogPart& p : parts_over_the_wire(line6)) {
    complete += assembler.add(p, got) == LogLineAssembler<SensorLogRecord>::Result::complete ? 1 : 0;
  }
  EXPECT_EQ(complete, 1);
  EXPECT_EQ(got.line, 6);
  EXPECT_EQ(assembler.abandoned_lines(), 1u);
}

TEST(LogRecords, ARepeatedPartDoesNotCompleteALine) {
  const SensorLogRecord sent = wire_test::golden_sensor_record();
  const std::vector<SensorLogPart> parts = parts_over_the_wire(sent);
  LogLineAssembler<SensorLogRecord> assembler;
  SensorLogRecord got;
  for (int i = 0; i < 10; ++i)
    EXPECT_EQ(assembler.add(parts[0], got), LogLineAssembler<SensorLogRecord>::Result::incomplete);
}

TEST(LogRecords, ALineWithAFieldOutOfRangeIsRejected) {
  TelemetryLogRecord bad = wire_test::golden_telemetry_record();
  bad.engine[2] = 1001;
  LogLineAssembler<TelemetryLogRecord> assembler;
  TelemetryLogRecord got;
  LogLineAssembler<TelemetryLogRecord>::Result last{};
  for (const TelemetryLogPart& p : parts_over_the_wire(bad)) last = assembler.add(p, got);
  EXPECT_EQ(last, LogLineAssembler<TelemetryLogRecord>::Result::rejected);
}

TEST(LogRecords, APartNumberPastTheEndMakesAPartReceiversRefuse) {
  const SensorLogPart past_end = make_log_part(wire_test::golden_sensor_record(), SensorLogRecord::kParts);
  SensorLogPart decoded;
  EXPECT_FALSE(decode(wire_test::frame_of(encode(past_end)), decoded));
  LogLineAssembler<SensorLogRecord> assembler;
  SensorLogRecord got;
  EXPECT_EQ(assembler.add(past_end, got), LogLineAssembler<SensorLogRecord>::Result::rejected);
}
