// The log's packing (qr/core/log_pack/): every line comes back exactly as written, whatever its
// values (extremes, a wrapping clock, a model that is wrong), from any starting point, in either
// log's numbering; a full area keeps what fit and says so; the linear predictor learns a vibration.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <qr/core/log_pack/packed_log.hpp>

namespace qr::log_pack {
namespace {

// A model that predicts the filtered counts as a running average of the raw ones: right often
// enough to use the "as predicted" bit, wrong otherwise (as the chain's copy is after a parameter
// change). `take` sets it the way the chain would.
struct AverageModel {
  int32_t sum[6] = {};
  void predict(const wire::SensorLogRecord& raw, int16_t (&out)[6]) {
    for (int i = 0; i < 6; ++i) {
      const int32_t x = i < 3 ? raw.gyro[i] : raw.accel[i - 3];
      sum[i] += x - sum[i] / 8;
      out[i] = static_cast<int16_t>(sum[i] / 8);
    }
  }
};

struct Lines {
  std::vector<LogLine> lines;
  std::vector<AverageModel> models;  // what `take` set at each line
};

// Lines of a vibrating vehicle: raw axes a sine plus noise, filtered as the model says on most
// lines, the telemetry drifting; `extremes` mixes in full-scale jumps and a clock that wraps.
Lines make_lines(size_t n, uint32_t seed, bool extremes) {
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0, 40);
  Lines out;
  AverageModel model;
  uint32_t time = extremes ? 0xFFFF0000u : 1000u;
  for (size_t i = 0; i < n; ++i) {
    LogLine l;
    l.sensor.time_us = time;
    time += (extremes && i % 97 == 0) ? 12345u : 1000u;
    for (int a = 0; a < 3; ++a) {
      const double v = 1500 * std::sin(0.8 * static_cast<double>(i) + a) + noise(random);
      l.sensor.gyro[a] = static_cast<int16_t>(v / 3);
      l.sensor.accel[a] = static_cast<int16_t>(v + (a == 2 ? -8000 : 0));
      if (extremes && i % 13 == 0) l.sensor.accel[a] = (i % 26 == 0) ? INT16_MIN : INT16_MAX;
    }
    l.sensor.battery_mv = static_cast<uint16_t>(12000 + (i / 50) % 16 * 16);
    int16_t predicted[6];
    model.predict(l.sensor, predicted);
    for (int a = 0; a < 3; ++a) {
      l.sensor.gyro_filtered[a] = predicted[a];
      l.sensor.accel_filtered[a] = predicted[3 + a];
    }
    if (i % 300 == 7) l.sensor.accel_filtered[1] = static_cast<int16_t>(l.sensor.accel_filtered[1] + 3);
    l.telemetry.time_us = l.sensor.time_us;
    l.telemetry.battery_mv = l.sensor.battery_mv;
    l.telemetry.mode = static_cast<wire::Mode>(i / 1000 % 5);
    l.telemetry.phi = static_cast<int16_t>(i * 3 % 2000);
    l.telemetry.engine[2] = static_cast<uint16_t>(400 + i % 7);
    l.telemetry.cpu_load = static_cast<uint16_t>(extremes ? random() % 1001 : 100);
    out.lines.push_back(l);
    out.models.push_back(model);
  }
  return out;
}

using Log = PackedLog<AverageModel>;

// Packs `lines` into `log`; the model taken at a keyframe is the one the lines were made with.
size_t pack(Log& log, const Lines& lines) {
  size_t kept = 0;
  for (size_t i = 0; i < lines.lines.size(); ++i) {
    const size_t at = i;
    if (!log.append(lines.lines[i], [&](AverageModel& m) { m = at == 0 ? AverageModel{} : lines.models[at - 1]; }))
      break;
    ++kept;
  }
  return kept;
}

bool same_sensor(const wire::SensorLogRecord& a, const wire::SensorLogRecord& b) {
  wire::SensorLogRecord x = a, y = b;
  x.line = y.line = 0;
  return x == y;
}

// The telemetry record as the log keeps it: its time and battery are the sensor line's.
bool same_telemetry(const wire::TelemetryLogRecord& a, const wire::TelemetryLogRecord& b) {
  wire::TelemetryLogRecord x = a, y = b;
  x.line = y.line = 0;
  return x == y;
}

TEST(PackedLog, EveryLineComesBackAsWrittenFromAnyStart) {
  std::vector<uint8_t> area(400 * 1024);
  for (const bool extremes : {false, true}) {
    for (const uint16_t every : {uint16_t{1}, uint16_t{10}}) {
      Log log;
      log.attach(area.data(), area.size());
      log.clear({true, true, every});
      const Lines lines = make_lines(9000, 7, extremes);
      ASSERT_EQ(pack(log, lines), lines.lines.size());
      ASSERT_FALSE(log.full());
      EXPECT_EQ(log.telemetry_lines(), (lines.lines.size() + every - 1) / every);
      // In order, then from scattered starts (each a seek from its keyframe), backwards too.
      LogCursor<AverageModel> cursor;
      size_t wrong = 0;
      for (uint32_t i = 0; i < log.lines(); ++i) {
        ASSERT_TRUE(cursor.reach(log, i, 1));
        wrong += !same_sensor(cursor.line().sensor, lines.lines[i].sensor);
        if (i % every == 0) wrong += !same_telemetry(cursor.line().telemetry, lines.lines[i].telemetry);
      }
      for (uint32_t i : {8999u, 4096u, 4095u, 2047u, 2048u, 17u, 6000u, 0u}) {
        ASSERT_TRUE(cursor.reach(log, i, kKeyframeLines)) << i;
        wrong += !same_sensor(cursor.line().sensor, lines.lines[i].sensor);
      }
      EXPECT_EQ(wrong, 0u) << "extremes " << extremes << ", telemetry every " << every;
      EXPECT_FALSE(cursor.reach(log, log.lines(), kKeyframeLines)) << "no line past the end";
      const uint32_t t = 123;
      ASSERT_TRUE(cursor.reach(log, LogCursor<AverageModel>::index_of(log.contents(), true, t), kKeyframeLines));
      EXPECT_TRUE(same_telemetry(cursor.line().telemetry, lines.lines[t * every].telemetry));
    }
  }
}

TEST(PackedLog, AModelInStepCostsABitForTheFilteredAxes) {
  // The same lines twice: with the model the lines were made with, and with the filtered values
  // spoiled on every line; the first packs smaller by more than 6 residuals' worth.
  std::vector<uint8_t> area(200 * 1024);
  Lines right = make_lines(4000, 3, false), wrong = right;
  for (LogLine& l : wrong.lines) l.sensor.gyro_filtered[0] = static_cast<int16_t>(l.sensor.gyro_filtered[0] ^ 0x55);
  Log a, b;
  a.attach(area.data(), area.size() / 2);
  b.attach(area.data() + area.size() / 2, area.size() / 2);
  a.clear({true, false, 1});
  b.clear({true, false, 1});
  ASSERT_EQ(pack(a, right), right.lines.size());
  ASSERT_EQ(pack(b, wrong), wrong.lines.size());
  EXPECT_GT(b.bits_used(), a.bits_used() + 4 * right.lines.size());
}

TEST(PackedLog, AFullAreaKeepsWhatFitAndTakesNoMore) {
  std::vector<uint8_t> area(Log::kIndexBytes + 3000);
  Log log;
  log.attach(area.data(), area.size());
  log.clear({true, true, 10});
  const Lines lines = make_lines(2000, 5, true);
  const size_t kept = pack(log, lines);
  ASSERT_GT(kept, 10u);
  ASSERT_LT(kept, lines.lines.size());
  EXPECT_TRUE(log.full());
  EXPECT_EQ(log.lines(), kept);
  EXPECT_EQ(log.capacity_estimate(), kept);
  EXPECT_FALSE(log.append(lines.lines[0], [](AverageModel&) {})) << "full stays full";
  LogCursor<AverageModel> cursor;
  for (uint32_t i = 0; i < kept; ++i) {
    ASSERT_TRUE(cursor.reach(log, i, 1));
    EXPECT_TRUE(same_sensor(cursor.line().sensor, lines.lines[i].sensor)) << i;
  }
  log.clear({true, true, 10});
  EXPECT_FALSE(log.full()) << "a new start empties it";
}

TEST(PackedLog, AFarLineIsReachedABudgetAtATime) {
  std::vector<uint8_t> area(200 * 1024);
  Log log;
  log.attach(area.data(), area.size());
  log.clear({true, true, 10});
  ASSERT_EQ(pack(log, make_lines(3000, 1, false)), 3000u);
  LogCursor<AverageModel> cursor;
  int calls = 1;
  while (!cursor.reach(log, 2047, 8)) ++calls;
  EXPECT_EQ(calls, 256) << "2048 lines from the first keyframe, 8 a call";
  calls = 1;
  while (!cursor.reach(log, 2050, 8)) ++calls;
  EXPECT_EQ(calls, 1) << "from the keyframe at 2048: 3 lines";
}

TEST(PackedLog, ACursorSentAnywhereInAnyOrderReadsTheLinesWritten) {
  // As the parts asked for again move the repair cursor: random lines, each reached a random
  // budget at a time, a seek sometimes abandoned for another line before it arrives.
  std::vector<uint8_t> area(300 * 1024);
  Log log;
  log.attach(area.data(), area.size());
  log.clear({true, true, 10});
  const Lines lines = make_lines(7000, 11, true);
  ASSERT_EQ(pack(log, lines), lines.lines.size());
  std::mt19937 random(3);
  LogCursor<AverageModel> cursor;
  size_t wrong = 0;
  for (int n = 0; n < 3000; ++n) {
    const uint32_t index = random() % log.lines();
    const auto budget = static_cast<uint16_t>(1 + random() % 40);
    if (random() % 5 == 0) cursor.reach(log, random() % log.lines(), budget);  // abandoned midway
    while (!cursor.reach(log, index, budget)) {
    }
    wrong += !same_sensor(cursor.line().sensor, lines.lines[index].sensor);
    if (index % 10 == 0) wrong += !same_telemetry(cursor.line().telemetry, lines.lines[index].telemetry);
  }
  EXPECT_EQ(wrong, 0u);
}

TEST(LinearPredictor, LearnsAVibrationWithinABlock) {
  // Two tones of a vibration, as the rotors put them on the accelerometer: after one block the
  // prediction error is a twentieth of what the difference of two samples is. (Not zero: the fit
  // keeps a floor of 1/1024 of the power, noise it cannot model; measured 42 counts against 2,680.)
  LinearPredictor p;
  double worst_difference = 0, worst_error = 0;
  int16_t last = 0;
  for (int n = 0; n < 3 * LinearPredictor::kBlockLines; ++n) {
    const double v = 2000 * std::sin(0.81 * n) + 900 * std::sin(1.93 * n + 1) - 8000;
    const auto x = static_cast<int16_t>(std::lround(v));
    if (n >= 2 * LinearPredictor::kBlockLines) {
      worst_error = std::max(worst_error, std::abs(double(x - p.predict())));
      worst_difference = std::max(worst_difference, std::abs(double(x - last)));
    }
    p.push(x);
    last = x;
  }
  EXPECT_GT(worst_difference, 1000);
  EXPECT_LT(worst_error, worst_difference / 20);
}

TEST(RiceCode, AnyResidualRoundTripsAndSmallOnesAreShort) {
  uint8_t area[4096] = {};
  BitWriter out(area, sizeof area);
  RiceCode put;
  const int32_t values[] = {0, 1, -1, 5, -17, 300, -300, 70000, INT32_MIN, INT32_MAX, 2, 0, 0, -4};
  for (int32_t v : values) ASSERT_TRUE(put.put(out, v));
  BitReader in(area, sizeof area);
  RiceCode get;
  for (int32_t v : values) EXPECT_EQ(get.get(in), v);
  EXPECT_TRUE(in.ok());
  EXPECT_EQ(in.bit(), out.bit());

  BitWriter small(area, sizeof area);
  RiceCode quiet;
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(quiet.put(small, i % 3 - 1));
  EXPECT_LT(small.bit(), 200u * 3u) << "residuals within +-1 take under 3 bits once learnt";
}

TEST(BitStream, AReaderPastTheEndReadsZerosAndSaysSo) {
  const uint8_t area[2] = {0xFF, 0x01};
  BitReader in(area, sizeof area);
  EXPECT_EQ(in.get(9), 0x1FFu);
  EXPECT_TRUE(in.ok());
  EXPECT_EQ(in.get(8), 0u);
  EXPECT_FALSE(in.ok());
  uint8_t room[1] = {};
  BitWriter out(room, sizeof room);
  EXPECT_TRUE(out.put(0x7F, 7));
  EXPECT_FALSE(out.put(0x3, 2)) << "two bits where one is left";
  EXPECT_EQ(out.bit(), 7u);
}

}  // namespace
}  // namespace qr::log_pack
