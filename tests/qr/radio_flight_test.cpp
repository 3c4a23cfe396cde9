// The radio as the pilot, end to end on the fake board: CRSF frames on the receiver's line, the
// PC's frames on the serial line, the flight's answers (docs/safety.md rule 17), and the ESCs'
// eRPM answers into telemetry.
#include <gtest/gtest.h>

#include <vector>

#include <common/drivers/crsf.hpp>
#include <common/drivers/erpm.hpp>
#include <common/drivers/rc_sticks.hpp>
#include <common/messages.hpp>
#include <common/observable_table.hpp>
#include <qr/core/observable_readers.hpp>

#include "fake_flight.hpp"

namespace qr {
namespace {

using test::Firmware;

struct RadioFlightTest : test::FakeFlight<> {
  wire::Control pc_sticks;
  drivers::CrsfChannels radio;  // what the transmitter sends; AETR, arm on channel 5, mode on 6
  bool radio_on = true;
  bool pc_on = true;

  RadioFlightTest() {
    for (uint16_t& v : radio.value) v = drivers::kCrsfChannelMid;
    radio.value[2] = drivers::kCrsfChannelMin;  // lift low
    radio.value[4] = drivers::kCrsfChannelMin;  // arm switch off
    radio.value[5] = drivers::kCrsfChannelMin;  // mode switch low: manual
  }

  void radio_frame(const drivers::CrsfFrameBytes& f) {
    board.radio.insert(board.radio.end(), f.bytes, f.bytes + f.size);
  }
  // `ms` of flight: an RC frame every 7 ms (150 Hz), the PC's control frame every 20 ms.
  void run_ms(uint32_t ms) {
    for (uint32_t t = 0; t < ms; ++t) {
      if (radio_on && t % 7 == 0) radio_frame(drivers::encode_rc_channels(radio));
      if (pc_on && t % 20 == 0) send(pc_sticks);
      pass_ms();
      receive();
    }
  }
  NackReason set_param(wire::ParamId id, int32_t value) {
    send(wire::ParamSet{++seq, static_cast<uint8_t>(id), value});
    run_ms(30);
    return last_answer(wire::MessageType::param_set);
  }
  NackReason request_mode(Mode mode) {
    send(wire::ModeChange{++seq, mode});
    run_ms(30);
    return last_answer(wire::MessageType::mode_change);
  }
  NackReason last_answer(wire::MessageType type) const {
    for (auto it = received.rbegin(); it != received.rend(); ++it) {
      wire::Nack n;
      if (it->type == wire::MessageType::nack && wire::decode(*it, n) && n.type == type) return n.reason;
      wire::Ack a;
      if (it->type == wire::MessageType::ack && wire::decode(*it, a) && a.type == type) return NackReason::none;
    }
    return NackReason::unknown_mode;  // no answer at all
  }
  void arm(bool on) { radio.value[4] = on ? drivers::kCrsfChannelMax : drivers::kCrsfChannelMin; }
  void make_radio_the_pilot() {
    run_ms(50);
    ASSERT_EQ(set_param(wire::ParamId::pilot, 1), NackReason::none);
    ASSERT_EQ(flight.pilot(), Pilot::radio);
  }
};

TEST_F(RadioFlightTest, ArmsFliesAndStopsThroughCrsfFrames) {
  make_radio_the_pilot();
  arm(true);
  run_ms(30);
  EXPECT_EQ(flight.mode(), Mode::manual);
  radio.value[2] = drivers::rc_channel_of_lift(400);
  radio.value[0] = drivers::rc_channel_of_stick(-250);
  run_ms(30);
  EXPECT_EQ(flight.controls().lift, 400u);
  EXPECT_EQ(flight.controls().roll, drivers::rc_stick(drivers::rc_channel_of_stick(-250)));
  arm(false);
  run_ms(10);
  EXPECT_EQ(flight.mode(), Mode::panic);
  EXPECT_EQ(flight.safety().panic_cause(), PanicCause::disarmed);
}

// The mode switch's positions are a column of the mode table (wire::mode_at_switch): low manual,
// centre yaw control, high full control; height hold and acro have none.
static_assert(wire::mode_at_switch(0) == Mode::manual && wire::mode_at_switch(1) == Mode::yaw_control &&
              wire::mode_at_switch(2) == Mode::full_control);
static_assert(!wire::armed_by_the_radio(Mode::height_hold) && !wire::armed_by_the_radio(Mode::acro) &&
              !wire::armed_by_the_radio(Mode::safe) && !wire::armed_by_the_radio(Mode::calibration));

// The arm switch moved on at each position of the mode switch arms that position's mode; the
// switch off is the emergency stop, and the panic ends in safe for the next position.
TEST_F(RadioFlightTest, EachPositionOfTheModeSwitchArmsItsModeOfTheModeTable) {
  make_radio_the_pilot();
  ASSERT_EQ(request_mode(Mode::calibration), NackReason::none) << "calibration stays the PC's";
  run_ms(50);
  ASSERT_TRUE(flight.chain().calibrated());
  ASSERT_EQ(flight.mode(), Mode::safe);
  constexpr uint16_t kChannel[] = {drivers::kCrsfChannelMin, drivers::kCrsfChannelMid, drivers::kCrsfChannelMax};
  for (uint8_t position = 0; position < wire::kModeSwitchPositions; ++position) {
    radio.value[5] = kChannel[position];
    arm(true);
    run_ms(30);
    EXPECT_EQ(flight.mode(), wire::mode_at_switch(position)) << "position " << int{position};
    arm(false);
    for (int i = 0; i < 1000 && flight.mode() != Mode::safe; ++i) run_ms(10);
    ASSERT_EQ(flight.mode(), Mode::safe);
  }
}

TEST_F(RadioFlightTest, ThePcsSticksAreIgnoredWhileTheRadioFlies) {
  make_radio_the_pilot();
  // The radio pauses (in safe no watchdog minds) so that no RC frame covers the PC's.
  radio_on = false;
  pc_sticks = wire::Control{300, 100, 0, 0};
  run_ms(100);
  EXPECT_EQ(flight.controls().lift, 0u);
  EXPECT_EQ(flight.controls().roll, 0);
  radio_on = true;
  EXPECT_EQ(request_mode(Mode::manual), NackReason::radio_is_pilot);
  EXPECT_EQ(flight.mode(), Mode::safe);
}

TEST_F(RadioFlightTest, ThePilotChangesInSafeOnly) {
  run_ms(50);
  ASSERT_EQ(request_mode(Mode::manual), NackReason::none);
  EXPECT_EQ(set_param(wire::ParamId::pilot, 1), NackReason::not_from_this_mode);
  EXPECT_EQ(flight.pilot(), Pilot::pc);
  EXPECT_EQ(flight.mode(), Mode::manual);
  // The value in force is no change: a console sends every parameter when it starts.
  EXPECT_EQ(set_param(wire::ParamId::pilot, 0), NackReason::none);
  EXPECT_EQ(flight.mode(), Mode::manual);
}

// How the IMU sits in the frame changes in safe only too: in flight it would turn the attitude
// under the loops (qr/core/chain/imu_mounting.hpp).
TEST_F(RadioFlightTest, TheImuOrientationChangesInSafeOnly) {
  run_ms(50);
  ASSERT_EQ(request_mode(Mode::manual), NackReason::none);
  EXPECT_EQ(set_param(wire::ParamId::imu_orientation, 1), NackReason::not_from_this_mode);
  EXPECT_EQ(set_param(wire::ParamId::imu_orientation, 0), NackReason::none) << "the value in force: no change";
  ASSERT_EQ(request_mode(Mode::safe), NackReason::none);
  run_ms(3000);
  ASSERT_EQ(flight.mode(), Mode::safe);
  EXPECT_EQ(set_param(wire::ParamId::imu_orientation, 1), NackReason::none);
}

TEST_F(RadioFlightTest, AnArmSwitchOnWhenTheRadioBecomesThePilotDoesNotArm) {
  arm(true);
  make_radio_the_pilot();
  run_ms(200);
  EXPECT_EQ(flight.mode(), Mode::safe) << "on at power-up";
  // Seen off while the radio was the pilot; the PC takes over, the switch goes on, the radio
  // becomes the pilot again within the link timeout: still no arming.
  arm(false);
  run_ms(30);
  ASSERT_EQ(set_param(wire::ParamId::pilot, 0), NackReason::none);
  arm(true);
  run_ms(10);
  ASSERT_EQ(set_param(wire::ParamId::pilot, 1), NackReason::none);
  run_ms(200);
  EXPECT_EQ(flight.mode(), Mode::safe) << "on when the radio became the pilot";
  arm(false);
  run_ms(30);
  arm(true);
  run_ms(30);
  EXPECT_EQ(flight.mode(), Mode::manual) << "moved off and on: arms";
}

// The watchdog watches the pilot's link: the PC's frames keep coming, the radio stops.
TEST_F(RadioFlightTest, TheRadioLinkIsTheWatchdogsWhenTheRadioFlies) {
  make_radio_the_pilot();
  arm(true);
  run_ms(30);
  ASSERT_EQ(flight.mode(), Mode::manual);
  radio_on = false;
  run_ms(flight.safety().limits().link_timeout_us / 1000 - 20);
  EXPECT_EQ(flight.mode(), Mode::manual);
  run_ms(40);
  EXPECT_EQ(flight.mode(), Mode::panic);
  EXPECT_EQ(flight.safety().panic_cause(), PanicCause::link_lost);
}

// Link statistics say how the link is, not that the pilot is there: they keep no flight alive.
TEST_F(RadioFlightTest, LinkStatisticsAreNotLife) {
  make_radio_the_pilot();
  arm(true);
  run_ms(30);
  ASSERT_EQ(flight.mode(), Mode::manual);
  radio_on = false;
  drivers::CrsfLinkStatistics stats;
  stats.uplink_link_quality = 100;
  for (int i = 0; i < 60; ++i) {
    radio_frame(drivers::encode_link_statistics(stats));
    run_ms(10);
  }
  EXPECT_EQ(flight.mode(), Mode::panic);
  EXPECT_EQ(flight.safety().panic_cause(), PanicCause::link_lost);
}

TEST_F(RadioFlightTest, LinkStatisticsAndThePilotGoToTelemetry) {
  make_radio_the_pilot();
  drivers::CrsfLinkStatistics stats;
  stats.uplink_rssi_ant1 = 60;
  stats.uplink_link_quality = 97;
  stats.uplink_snr = -3;
  stats.downlink_link_quality = 88;
  radio_frame(drivers::encode_link_statistics(stats));
  run_ms(400);
  const auto radio_reports = got<wire::TelemetryRadio>();
  ASSERT_FALSE(radio_reports.empty());
  const wire::TelemetryRadio& r = radio_reports.back();
  EXPECT_EQ(r.flags & wire::kRadioPilot, wire::kRadioPilot);
  EXPECT_EQ(r.flags & wire::kRadioLinkUp, wire::kRadioLinkUp);
  EXPECT_EQ(r.flags & wire::kRadioArmSwitch, 0);
  EXPECT_EQ(r.uplink_rssi, 60u);
  EXPECT_EQ(r.uplink_lq, 97u);
  EXPECT_EQ(r.uplink_snr, -3);
  EXPECT_EQ(r.downlink_lq, 88u);
}

// The radio screen's channels (docs/console.md): all sixteen as the transmitter sent them, before
// the channel map and whoever the pilot is; 0 until an RC frame came.
TEST_F(RadioFlightTest, AllSixteenChannelsReachTheirObservablesAsSent) {
  const auto rc_ch = [this](uint8_t ch) { return read_observable(flight, wire::kFirstRcChannelObservable + ch); };
  for (uint8_t ch = 0; ch < drivers::kCrsfChannelCount; ++ch) EXPECT_EQ(rc_ch(ch), 0) << "channel " << ch + 1;
  for (uint8_t ch = 0; ch < drivers::kCrsfChannelCount; ++ch)
    radio.value[ch] = static_cast<uint16_t>(drivers::kCrsfChannelMin + 100 * ch + ch);
  radio.value[15] = drivers::kCrsfChannelMax;
  run_ms(30);
  for (uint8_t ch = 0; ch < drivers::kCrsfChannelCount; ++ch)
    EXPECT_EQ(rc_ch(ch), radio.value[ch]) << "channel " << ch + 1;
  EXPECT_EQ(flight.pilot(), Pilot::pc) << "the PC flies: the channels are read all the same";
}

TEST_F(RadioFlightTest, NoRadioNoRadioTelemetry) {
  radio_on = false;
  run_ms(400);
  EXPECT_TRUE(got<wire::TelemetryRadio>().empty());
}

// Rule 18 with the radio as the pilot: the beacon is timed from the radio's link, whatever the PC
// link does. The radio silent while the PC's frames keep coming beacons; the radio alive while
// the PC is silent does not.
TEST_F(RadioFlightTest, TheBeaconListensToThePilotsLink) {
  make_radio_the_pilot();
  const uint32_t timeout_ms = static_cast<uint32_t>(wire::ParameterValues{}.get(wire::ParamId::link_timeout_ms));
  radio_on = false;
  run_ms(timeout_ms + 4500);  // past the timeout, then two beacon periods and more
  EXPECT_EQ(flight.mode(), Mode::safe);
  EXPECT_GE(board.esc_commands.size(), 2u) << "the radio is silent: the pilot is lost, the PC link does not count";
  radio_on = true;
  pc_on = false;
  run_ms(100);
  const size_t sounded = board.esc_commands.size();
  run_ms(timeout_ms + 4500);
  EXPECT_EQ(board.esc_commands.size(), sounded) << "the radio lives: no beacon, though the PC link is silent";
}

// 14-pole motors (the default): RPM = eRPM / 7. A period of 428 us is 140 186 eRPM, 20 026 RPM.
TEST_F(RadioFlightTest, EscAnswersBecomeRpmInTelemetry) {
  run_ms(50);
  EXPECT_TRUE(got<wire::TelemetryRpm>().empty()) << "no answers: no RPM frames";
  for (uint32_t& raw : board.esc.raw) raw = drivers::encode_erpm_answer(drivers::erpm_period_code(428));
  board.esc.raw[3] = drivers::encode_erpm_answer(drivers::kErpmStopped);
  board.esc.fresh = 0xF;
  run_ms(300);
  const auto rpm = got<wire::TelemetryRpm>();
  ASSERT_FALSE(rpm.empty());
  EXPECT_EQ(rpm.back().rpm[0], 20026u);
  EXPECT_EQ(rpm.back().rpm[2], 20026u);
  EXPECT_EQ(rpm.back().rpm[3], 0u);
  // A garbled answer keeps the engine's last reading.
  board.esc.raw[0] = 0;
  board.esc.fresh = 0x1;
  run_ms(300);
  EXPECT_EQ(got<wire::TelemetryRpm>().back().rpm[0], 20026u);
}

}  // namespace
}  // namespace qr
