// The console's record of an identification flight (pc/core/identification_recorder.hpp) and the
// proposal made from it (autotune_proposal.hpp), fed synthetic reports and stream samples.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <common/sample_packing.hpp>

#include <common/parameter_table.hpp>
#include <pc/core/autotune_proposal.hpp>
#include <pc/core/identification_recorder.hpp>
#include <pc/core/parameter_sync.hpp>
#include <pc/core/stream_session.hpp>

#include "observable_table_feed.hpp"

namespace qrterm {
namespace {

constexpr uint32_t kTelemetryHz = 50;
constexpr uint32_t kAxisTicks = 3040;  // 0.5 s of quiet and 127 bits of 20 ms at 1 kHz
constexpr uint32_t kQuietTicks = 500;

// Attitude reports at 50 Hz from `from_ms`: each a telemetry period, its tick counting.
struct Reports {
  IdentificationRecorder& recorder;
  uint8_t tick = 0;
  void at(uint32_t now_ms, wire::Mode mode) { recorder.on_mode(mode, tick++, kTelemetryHz, now_ms); }
};

// Axis `axis`'s stream from its `first`th sample (the switch's place in the quiet part), `count`
// samples: a moment and the rate of a pure gain of 0.05 rad/s^2 per thrust unit (enough to test
// the placement; the fit of a real flight is qrsim's).
void feed_axis(IdentificationRecorder& r, size_t axis, uint32_t count) {
  for (uint32_t i = 0; i < count; ++i) r.on_sample(axis, i, static_cast<double>(axis * 1000 + i), -1.0 * i);
}

TEST(AutotuneRecorder, TheStreamCarriesEachAxisFromItsQuietPart) {
  IdentificationRecorder r;
  EXPECT_FALSE(r.streamed_axis(0).has_value()) << "not recording: the plot has the stream";
  Reports reports{r};
  reports.at(1000, wire::Mode::full_control);
  EXPECT_FALSE(r.streamed_axis(1000).has_value());
  reports.at(1020, wire::Mode::autotune);
  ASSERT_EQ(r.state(), IdentificationRecorder::State::recording);
  EXPECT_EQ(r.streamed_axis(1020), 0u);
  // Pitch's pair from 100 ms into pitch's quiet part (3.04 s after the mode's first report), yaw's
  // likewise; the switch stays inside the quiet part's 500 ms.
  EXPECT_EQ(r.streamed_axis(1020 + 3040 + kSwitchIntoQuietMs - 1), 0u);
  EXPECT_EQ(r.streamed_axis(1020 + 3040 + kSwitchIntoQuietMs), 1u);
  EXPECT_EQ(r.streamed_axis(1020 + 6080 + kSwitchIntoQuietMs - 1), 1u);
  EXPECT_EQ(r.streamed_axis(1020 + 6080 + kSwitchIntoQuietMs), 2u);
  EXPECT_LT(kSwitchIntoQuietMs + 2 * 1000 / kTelemetryHz, kQuietTicks) << "room for the report's and the ack's delay";
}

TEST(AutotuneRecorder, ARunToItsEndKeepsEachAxisRecordInOrderAndCappedAtAnAxisWorth) {
  IdentificationRecorder r;
  Reports reports{r};
  reports.at(0, wire::Mode::autotune);
  // Each axis' stream started 150 samples into its quiet part and ran 150 into the next axis'.
  feed_axis(r, 0, kAxisTicks);
  feed_axis(r, 1, kAxisTicks + 200);  // the samples past an axis' worth are not its record
  feed_axis(r, 2, kAxisTicks - 150);
  for (uint32_t t = 20; t < 9120; t += 20) reports.at(t, wire::Mode::autotune);
  EXPECT_EQ(r.state(), IdentificationRecorder::State::recording);
  reports.at(9140, wire::Mode::full_control);
  ASSERT_EQ(r.state(), IdentificationRecorder::State::recorded) << r.why();
  EXPECT_EQ(r.records()[0].moment.size(), kAxisTicks);
  EXPECT_EQ(r.records()[1].moment.size(), kAxisTicks);
  EXPECT_EQ(r.records()[2].rate.size(), kAxisTicks - 150);
  EXPECT_EQ(r.records()[1].moment.front(), 1000.0);
  EXPECT_EQ(r.records()[2].moment[10], 2010.0);
  EXPECT_EQ(r.records()[0].rate[7], -7.0);
}

TEST(AutotuneRecorder, AnEarlyEndKeepsNothingAndSaysSo) {
  IdentificationRecorder r;
  Reports reports{r};
  reports.at(0, wire::Mode::autotune);
  feed_axis(r, 0, kAxisTicks);
  feed_axis(r, 1, 1000);
  // A stick moved 4.02 s in: the QR went back to full control (the tick counts past 255: wraps).
  for (uint32_t t = 20; t <= 4000; t += 20) reports.at(t, wire::Mode::autotune);
  reports.at(4020, wire::Mode::full_control);
  ASSERT_EQ(r.state(), IdentificationRecorder::State::failed);
  EXPECT_NE(r.why().find("ended after 4.02 of its 9.12 s"), std::string::npos) << r.why();
  EXPECT_TRUE(r.records()[0].moment.empty()) << "nothing kept";
  EXPECT_FALSE(r.streamed_axis(4020).has_value()) << "the plot has its stream back";
  // Still in the mode's aftermath: reports in full control start nothing.
  reports.at(4040, wire::Mode::full_control);
  EXPECT_EQ(r.state(), IdentificationRecorder::State::failed);
}

TEST(AutotuneRecorder, ALostSampleKeepsNothingAndTheNextEntryRecordsAnew) {
  IdentificationRecorder r;
  Reports reports{r};
  reports.at(0, wire::Mode::autotune);
  r.on_sample(0, 0, 1, 1);
  r.on_sample(0, 1, 1, 1);
  r.on_sample(0, 4, 1, 1);  // a frame of two samples lost (two missing)
  ASSERT_EQ(r.state(), IdentificationRecorder::State::failed);
  EXPECT_NE(r.why().find("2 samples of the roll record lost"), std::string::npos) << r.why();
  reports.at(20, wire::Mode::autotune);
  EXPECT_EQ(r.state(), IdentificationRecorder::State::failed) << "the same flight in the mode: not again";
  reports.at(40, wire::Mode::full_control);
  reports.at(60, wire::Mode::autotune);
  EXPECT_EQ(r.state(), IdentificationRecorder::State::recording) << "the next entry";
}

TEST(AutotuneRecorder, ARecordShortOfItsBitsKeepsNothing) {
  IdentificationRecorder r;
  Reports reports{r};
  reports.at(0, wire::Mode::autotune);
  feed_axis(r, 0, kAxisTicks);
  feed_axis(r, 1, kAxisTicks - kQuietTicks - 1);  // the switch came after pitch's bits began
  feed_axis(r, 2, kAxisTicks);
  for (uint32_t t = 20; t <= 9140; t += 20) reports.at(t, wire::Mode::autotune);
  reports.at(9160, wire::Mode::full_control);
  ASSERT_EQ(r.state(), IdentificationRecorder::State::failed);
  EXPECT_NE(r.why().find("pitch record holds 2539 samples"), std::string::npos) << r.why();
}

// Stream 0 carries autotune's pair at the control rate in the plot's place; its samples go to the
// carried hook numbered from the stream's start, and the plot's selection comes back after.
TEST(AutotuneStream, TheCarriedPairTakesStreamZeroAndThePlotGetsItBack) {
  struct Carried {
    std::vector<uint8_t> ids;
    uint32_t index;
    std::vector<double> values;
  };
  std::vector<Carried> carried;
  StreamSession session(
      StreamSession::Hooks{[](Severity, const std::string&) {},
                           {},
                           [&](const std::vector<uint8_t>& ids, uint32_t index, const std::vector<double>& values) {
                             carried.push_back({ids, index, values});
                           }});
  send_observable_table(session);
  session.pick("phi");
  LinkSession link(0, 1);
  session.tick(link, 0);
  session.on_answer(wire::MessageType::stream_request, wire::NackReason::none, 50);
  ASSERT_EQ(session.state(), "streaming");

  const uint8_t moment = *session.catalog().find("roll_moment");
  const uint8_t p = *session.catalog().find("p");
  session.carry({moment, p});
  session.tick(link, 10);  // asks for the pair at divider 1
  session.on_answer(wire::MessageType::stream_request, wire::NackReason::none, 50);
  EXPECT_EQ(session.state(), "carrying autotune's identification");
  wire::SamplePacker packer;
  packer.start(0, 2);
  wire::ObservableSamples frame;
  for (int s = 0; s < 6; ++s) {
    const int16_t values[2] = {static_cast<int16_t>(s * 10), static_cast<int16_t>(-s)};
    if (s == 2 || s == 3) {  // this frame is lost on the line
      packer.add(values, frame);
      continue;
    }
    if (packer.add(values, frame)) session.on(frame, 1.0);
  }
  ASSERT_EQ(carried.size(), 4u);
  EXPECT_EQ(carried[0].ids, (std::vector<uint8_t>{moment, p}));
  EXPECT_EQ(carried[1].index, 1u);
  EXPECT_EQ(carried[2].index, 4u) << "numbered by the frames' counter: two samples lost";
  EXPECT_NEAR(carried[2].values[0], 4.0, 1e-9) << "40 tenths of a thrust unit";
  EXPECT_NEAR(carried[2].values[1], -0.004, 1e-12) << "rad/s";
  EXPECT_TRUE(session.plot().traces()[0].points.empty()) << "the plot's trace waits";

  session.carry({});
  session.tick(link, 20);
  session.on_answer(wire::MessageType::stream_request, wire::NackReason::none, 50);
  EXPECT_EQ(session.state(), "streaming") << "the plot's phi asked for again";
}

TEST(AutotuneProposal, ARefusedFitIsALineNotACrash) {
  AutotuneProposal p;
  std::array<tune::AxisRecord, 3> records;
  for (tune::AxisRecord& record : records) {
    record.moment.assign(kAxisTicks, 0.0);  // no excitation
    record.rate.assign(kAxisTicks, 0.0);
  }
  p.make(records, wire::ParameterValues{}, 1000);
  ASSERT_EQ(p.standing(), AutotuneProposal::Standing::refused);
  ASSERT_EQ(p.lines().size(), 1u);
  EXPECT_NE(p.lines()[0].find("autotune refused: roll's fit"), std::string::npos) << p.lines()[0];
  ParameterSync sync(wire::ParameterValues{}, [](Severity, const std::string&) {});
  EXPECT_FALSE(p.accept(sync)) << "nothing to take";
}

// A design taken (as the fit's thread hands it over): old and new side by side, ^T makes the new
// values the console's (sent one by one), ^R the old ones again.
TEST(AutotuneProposal, TakesTheNewGainsAndGoesBack) {
  AutotuneProposal::Outcome outcome;
  outcome.design.emplace();
  outcome.design->roll_pitch = {7.25, 235.25, 85.3125, 9.05859375};
  outcome.design->yaw = {784, 1000};
  outcome.design->keeps = true;
  const wire::ParameterValues flown;  // the defaults
  AutotuneProposal p;
  p.take(outcome, flown);
  ASSERT_EQ(p.standing(), AutotuneProposal::Standing::proposed);
  ASSERT_EQ(p.changes().size(), 6u);
  EXPECT_EQ(p.changes()[0].id, wire::ParamId::roll_pitch_p1);
  EXPECT_EQ(p.changes()[0].before, flown.get(wire::ParamId::roll_pitch_p1));
  EXPECT_EQ(p.changes()[0].after, 1856) << "7.25 in 1/256";
  const std::vector<std::string> lines = p.lines();
  ASSERT_EQ(lines.size(), 8u);
  EXPECT_EQ(lines[2].substr(0, 32), "roll_pitch_p1     5.500    7.250");
  EXPECT_NE(lines[4].find("yaw_i           300.000 1000.000"), std::string::npos) << lines[4];
  EXPECT_EQ(lines.back(), "proposed: ^T sends the new gains");

  std::vector<std::string> notes;
  ParameterSync sync(flown, [&](Severity, const std::string& t) { notes.push_back(t); });
  ASSERT_TRUE(p.accept(sync));
  for (const GainChange& c : p.changes()) EXPECT_EQ(sync.wanted().get(c.id), c.after) << static_cast<int>(c.id);
  EXPECT_EQ(sync.to_send(), 6u);
  EXPECT_EQ(p.standing(), AutotuneProposal::Standing::accepted);
  ASSERT_TRUE(p.back(sync));
  for (const GainChange& c : p.changes()) EXPECT_EQ(sync.wanted().get(c.id), c.before) << static_cast<int>(c.id);
  EXPECT_EQ(p.lines().back(), "the gains before sent again: ^T takes the new ones");
}

}  // namespace
}  // namespace qrterm
