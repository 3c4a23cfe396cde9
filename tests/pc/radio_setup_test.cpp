// The radio screen's model (pc/core/radio_setup.hpp): the channel map from the parameters, the
// switches and the sticks' ends as the firmware reads them (common/drivers/rc_sticks.hpp), and the
// four streams that bring the sixteen channels while the screen is open (stream_session.hpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <common/drivers/rc_sticks.hpp>
#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/sample_packing.hpp>
#include <pc/core/radio_setup.hpp>
#include <pc/core/stream_session.hpp>

#include "observable_table_feed.hpp"

namespace qrterm {
namespace {

using drivers::kCrsfChannelMax;
using drivers::kCrsfChannelMid;
using drivers::kCrsfChannelMin;

TEST(RadioSetup, TheParametersNameEachControlsChannel) {
  wire::ParameterValues params;  // AETR, arm 5, mode 6
  EXPECT_EQ(channel_roles(0, params), "roll");
  EXPECT_EQ(channel_roles(2, params), "lift");
  EXPECT_EQ(channel_roles(5, params), "mode");
  EXPECT_EQ(channel_roles(6, params), "") << "channel 7: read by nobody";
  params.set(static_cast<uint8_t>(wire::ParamId::rc_arm_channel), 3);
  params.set(static_cast<uint8_t>(wire::ParamId::rc_mode_channel), 16);
  EXPECT_EQ(channel_roles(2, params), "lift+arm") << "two controls on one channel: said, not hidden";
  EXPECT_EQ(channel_roles(15, params), "mode");
  EXPECT_EQ(role_channel(RcRole::mode, params), 15);
}

TEST(RadioSetup, MicrosecondsAsReceiversConvertThem) {
  EXPECT_EQ(crsf_us(kCrsfChannelMin), 988);
  EXPECT_EQ(crsf_us(kCrsfChannelMid), 1500);
  EXPECT_EQ(crsf_us(kCrsfChannelMax), 2012);
}

// Every value a channel can hold reads on the screen as the firmware reads it: the arm switch on
// exactly where rc_sticks says arm, the mode switch's mode the one the QR would arm.
TEST(RadioSetup, TheSwitchesReadAsTheFirmwareReadsThem) {
  const drivers::RcChannelMap map;
  for (uint16_t v = 0; v < 2048; ++v) {
    drivers::CrsfChannels c;
    c.value[map.arm] = v;
    c.value[map.mode] = v;
    const drivers::RcSticks s = drivers::rc_sticks(c, map);
    ASSERT_EQ(arm_switch_text(v).rfind("ON (high)", 0) == 0, s.arm) << v;
    ASSERT_EQ(read_switch(v).position, s.mode_position) << v;
    ASSERT_EQ(mode_switch_text(v).substr(mode_switch_text(v).find(": ") + 2),
              wire::mode_name(wire::mode_at_switch(s.mode_position)))
        << v;
  }
  EXPECT_EQ(arm_switch_text(kCrsfChannelMin), "off (low)");
  EXPECT_EQ(arm_switch_text(kCrsfChannelMid), "off (centre)");
  EXPECT_EQ(arm_switch_text(kCrsfChannelMax), "ON (high)");
  EXPECT_EQ(mode_switch_text(kCrsfChannelMin), "low: manual");
  EXPECT_EQ(mode_switch_text(kCrsfChannelMid), "centre: yaw control");
  EXPECT_EQ(mode_switch_text(kCrsfChannelMax), "high: full control");
}

TEST(RadioSetup, AStickReachesAnEndWhereTheFirmwareReadsFullDeflection) {
  const auto roll = [](uint16_t low, uint16_t high) { return stick_ends(RcRole::roll, low, high); };
  EXPECT_STREQ(stick_ends_text(roll(kCrsfChannelMid, kCrsfChannelMid)), "no end yet");
  EXPECT_STREQ(stick_ends_text(roll(kCrsfChannelMid, kCrsfChannelMax)), "no low end");
  EXPECT_STREQ(stick_ends_text(roll(kCrsfChannelMin, kCrsfChannelMid)), "no high end");
  EXPECT_STREQ(stick_ends_text(roll(kCrsfChannelMin, kCrsfChannelMax)), "both ends");
  // A transmitter's travel set short: 94 % of full is no end, 95 % is.
  EXPECT_FALSE(roll(drivers::rc_channel_of_stick(-940), kCrsfChannelMax).low_reached);
  EXPECT_TRUE(roll(drivers::rc_channel_of_stick(-950), kCrsfChannelMax).low_reached);
  EXPECT_EQ(roll(drivers::rc_channel_of_stick(-940), kCrsfChannelMax).low_permille, -940);
  // The lift's low end is 0 exactly: leaving safe needs it.
  const auto lift = [](uint16_t low, uint16_t high) { return stick_ends(RcRole::lift, low, high); };
  EXPECT_TRUE(lift(drivers::rc_channel_of_lift(0), kCrsfChannelMax).low_reached);
  EXPECT_FALSE(lift(drivers::rc_channel_of_lift(1), kCrsfChannelMax).low_reached);
  EXPECT_TRUE(lift(kCrsfChannelMin, drivers::rc_channel_of_lift(950)).high_reached);
  EXPECT_FALSE(lift(kCrsfChannelMin, drivers::rc_channel_of_lift(949)).high_reached);
}

TEST(RadioSetup, TheEndsAreTheLowestAndHighestSinceTheScreenOpened) {
  RadioSetup radio;
  EXPECT_FALSE(radio.heard());
  radio.on_channel(0, 0);
  EXPECT_FALSE(radio.heard()) << "0: the QR has had no RC frame";
  EXPECT_FALSE(radio.value(0));
  for (const uint16_t v : {uint16_t{992}, uint16_t{1500}, uint16_t{400}, uint16_t{1100}}) radio.on_channel(0, v);
  EXPECT_TRUE(radio.heard());
  EXPECT_EQ(radio.value(0), 1100);
  EXPECT_EQ(radio.lowest(0), 400);
  EXPECT_EQ(radio.highest(0), 1500);
  EXPECT_FALSE(radio.value(1));
  radio.restart_ends();
  EXPECT_EQ(radio.value(0), 1100) << "the value stays";
  EXPECT_EQ(radio.lowest(0), 1100);
  EXPECT_EQ(radio.highest(0), 1100);
  radio.start();
  EXPECT_FALSE(radio.heard());
  EXPECT_FALSE(radio.value(0));
}

// --- the streams: four of four channels while the screen is open, the plot's back after.

// The stream requests the session put on the line since the last call.
std::vector<wire::StreamRequest> requests_sent(LinkSession& link) {
  std::vector<wire::StreamRequest> out;
  wire::FrameParser parser{wire::Listen::pc_to_qr};
  for (uint8_t b : link.output()) {
    parser.push(b, [&](const wire::Frame& f) {
      wire::StreamRequest r;
      if (f.type == wire::MessageType::stream_request && wire::decode(f, r)) out.push_back(r);
    });
  }
  link.output().clear();
  return out;
}

struct RadioStreams : ::testing::Test {
  std::vector<std::string> notes;
  StreamSession session{StreamSession::Hooks{[this](Severity, const std::string& t) { notes.push_back(t); }, {}, {}}};
  LinkSession link{0, 1};

  RadioStreams() {
    send_observable_table(session);
    session.tick(link, 0);
    link.output().clear();
  }
  // Ticks and acks until no request goes out; the requests in order.
  std::vector<wire::StreamRequest> settle() {
    std::vector<wire::StreamRequest> all;
    for (int i = 0; i < 10; ++i) {
      session.tick(link, 0);
      const std::vector<wire::StreamRequest> sent = requests_sent(link);
      if (sent.empty()) break;
      all.insert(all.end(), sent.begin(), sent.end());
      session.on_answer(wire::MessageType::stream_request, wire::NackReason::none, 50);
    }
    return all;
  }
};

TEST_F(RadioStreams, TheScreenTakesTheFourStreamsAndGivesThePlotItsStreamBack) {
  session.pick("phi");
  ASSERT_EQ(settle().size(), 1u);
  ASSERT_EQ(session.state(), "streaming");

  session.open_radio();
  EXPECT_FALSE(session.radio_streaming());
  const std::vector<wire::StreamRequest> asked = settle();
  ASSERT_EQ(asked.size(), 4u) << "one request at a time, each answered";
  for (uint8_t s = 0; s < 4; ++s) {
    EXPECT_EQ(asked[s].stream, s);
    EXPECT_EQ(asked[s].divider, 40) << "25 Hz at 1 kHz";
    for (uint8_t i = 0; i < 4; ++i) EXPECT_EQ(asked[s].id[i], wire::kFirstRcChannelObservable + 4 * s + i);
  }
  EXPECT_EQ(session.radio_state(), "16 channels at 25 Hz");
  EXPECT_TRUE(session.radio_streaming());

  // Stream 2 carries channels 9..12, in CRSF units as the QR sent them.
  wire::SamplePacker packer;
  packer.start(2, 4);
  const int16_t values[4] = {172, 992, 1811, static_cast<int16_t>(1500)};
  wire::ObservableSamples frame;
  ASSERT_TRUE(packer.add(values, frame));
  session.on(frame, 1.0);
  EXPECT_EQ(session.radio().value(8), 172);
  EXPECT_EQ(session.radio().value(10), 1811);
  EXPECT_EQ(session.radio().value(11), 1500);
  EXPECT_FALSE(session.radio().value(0));
  // Stream 0 is the radio's now: its samples are channels 1..4, not the plot's phi.
  packer.start(0, 4);
  ASSERT_TRUE(packer.add(values, frame));
  session.on(frame, 1.0);
  EXPECT_EQ(session.radio().value(0), 172);
  EXPECT_EQ(session.radio().value(3), 1500);
  EXPECT_TRUE(session.plot().traces()[0].points.empty());

  session.close_radio();
  const std::vector<wire::StreamRequest> back = settle();
  ASSERT_EQ(back.size(), 4u);
  EXPECT_EQ(back[0].stream, 0);
  EXPECT_EQ(back[0].id[0], static_cast<uint8_t>(wire::ObservableId::phi)) << "the plot's selection again";
  for (uint8_t s = 1; s < 4; ++s) {
    EXPECT_EQ(back[s].stream, s);
    EXPECT_EQ(back[s].divider, 0) << "the others stop";
  }
  EXPECT_EQ(session.state(), "streaming");
}

TEST_F(RadioStreams, ARefusalIsSaidAndNotAskedAgain) {
  session.open_radio();
  session.tick(link, 0);
  ASSERT_EQ(requests_sent(link).size(), 1u);
  session.on_answer(wire::MessageType::stream_request, wire::NackReason::over_budget, 100);
  EXPECT_EQ(session.radio_state(), "refused: over_budget");
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes.back().rfind("QR refused the radio's channels: ", 0), 0u) << notes.back();
  session.tick(link, 0);
  const std::vector<wire::StreamRequest> next = requests_sent(link);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_EQ(next[0].stream, 1) << "stream 0 is not asked again; the next is";
}

TEST_F(RadioStreams, AnUnansweredRequestWaitsForAChange) {
  session.open_radio();
  session.tick(link, 0);
  ASSERT_EQ(requests_sent(link).size(), 1u);
  session.stream_unanswered();
  session.tick(link, 0);
  EXPECT_TRUE(requests_sent(link).empty()) << "no request every tick to a QR that does not answer";
  session.close_radio();
  session.tick(link, 0);
  EXPECT_EQ(requests_sent(link).size(), 1u) << "what the streams should carry changed: asked";
}

}  // namespace
}  // namespace qrterm
