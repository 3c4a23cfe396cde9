// The hover key (Home): the lift to the hover lift the QR learnt, in the right unit, or a clear
// message while it has learnt none. A pilot found the hover by trial (530 did not lift, 550 climbed
// and accelerated, 520 fell): the QR knows it after a few seconds of flight.
#include <gtest/gtest.h>

#include <qr/core/chain/engine_mixer.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/host/real_numbers.hpp>

#include <pc/core/key_map.hpp>
#include <pc/core/pilot_controls.hpp>

#include "console_bench.hpp"

namespace {

using qrterm::Action;
using qrterm_test::Bench;

// The QR reports its hover as FlightChain::hover_lift(): engine_of_thrust of the learnt per-engine
// hover thrust, in engine units. The console puts that number on the lift stick unconverted, which
// is right only if the lift stick that asks for a thrust is the engine command that gives it. Both
// number formats of the firmware's mixer, every lift.
template <class N>
void expect_lift_and_engine_units_agree() {
  using Mixer = qr::chain::EngineMixer<N>;
  for (uint16_t lift = 0; lift <= wire::kLiftMax; ++lift) {
    ASSERT_EQ(Mixer::engine_of_thrust(Mixer::thrust_of_lift(lift)), lift) << "lift " << lift;
  }
}

TEST(HoverKey, TheHoverLiftIsTheLiftStickThatGivesTheHoverThrust) {
  expect_lift_and_engine_units_agree<qr::chain::FixedNumbers>();
  expect_lift_and_engine_units_agree<qr::chain::DoubleNumbers>();
}

TEST(HoverKey, HomeIsTheHoverKeyBesideTheOtherLiftKeys) {
  EXPECT_EQ(qrterm::action_for(qrterm::kKeyHome), Action::lift_hover);
  EXPECT_EQ(qrterm::key_name(qrterm::kKeyHome), "Home");
}

TEST(HoverKey, TheLiftTrimMakesJoystickPlusTrimTheHover) {
  qrterm::PilotControls keys_only;
  for (int i = 0; i < 7; ++i) keys_only.apply(Action::lift_up_coarse);  // 700: climbing hard
  EXPECT_EQ(keys_only.set_lift(537), 537);
  EXPECT_EQ(keys_only.control().lift, 537);
  EXPECT_EQ(keys_only.trims().lift, 537);

  qrterm::PilotControls throttle_low;
  throttle_low.set_joystick({200, 0, 0, 0});
  EXPECT_EQ(throttle_low.set_lift(537), 537);
  EXPECT_EQ(throttle_low.trims().lift, 337) << "keys add to the stick";

  // The lift trim does not go below 0: a throttle above the hover stays where it is.
  qrterm::PilotControls throttle_high;
  throttle_high.set_joystick({650, 0, 0, 0});
  EXPECT_EQ(throttle_high.set_lift(537), 650);
  EXPECT_EQ(throttle_high.trims().lift, 0);
}

void fly_full_control(Bench& b) {
  b.connect();
  b.key('3');
  ASSERT_TRUE(b.run_until([&] { return b.qr.calibrated && b.qr.mode == wire::Mode::safe; }, 2000));
  b.key('5');
  ASSERT_TRUE(b.run_until([&] { return b.qr.mode == wire::Mode::full_control; }, 500));
}

TEST(HoverKey, WithoutALearntHoverItChangesNothingAndSaysWhy) {
  Bench b;
  fly_full_control(b);
  for (int i = 0; i < 52; ++i) b.key('a');
  b.qr.height = wire::TelemetryHeight{2000, 0, wire::kHeightValid, 0};  // a height, no hover yet
  b.run(100);
  b.key(qrterm::kKeyHome);
  b.run(100);
  EXPECT_EQ(b.qr.control.lift, 520) << "the lift stays as it was";
  EXPECT_TRUE(
      b.logged("no hover lift known yet: the QR learns it in flight, a few seconds flying slowly; lift stays 520"));
}

TEST(HoverKey, BeforeAnyHeightReportItSaysTheSame) {
  Bench b;
  fly_full_control(b);
  b.key(qrterm::kKeyHome);
  b.run(100);
  EXPECT_EQ(b.qr.control.lift, 0);
  EXPECT_TRUE(b.logged("no hover lift known yet"));
}

TEST(HoverKey, SendsTheLearntHoverLift) {
  Bench b;
  fly_full_control(b);
  for (int i = 0; i < 52; ++i) b.key('a');  // 520: the pilot's descent
  b.qr.height = wire::TelemetryHeight{12000, -3000, wire::kHeightValid, 537};
  b.run(100);
  b.key(qrterm::kKeyHome);
  b.run(100);
  EXPECT_EQ(b.qr.control.lift, 537) << "what the QR receives";
  EXPECT_EQ(b.console.controls().trims().lift, 537);
  EXPECT_TRUE(b.logged("lift 520 -> 537, the hover lift the QR learnt (more lift to stop a descent: PgUp)"));
  // The usual keys go on from the hover.
  b.key('a');
  b.run(100);
  EXPECT_EQ(b.qr.control.lift, 547);
}

TEST(HoverKey, ThrottleAboveTheHoverIsSaidNotHidden) {
  qrterm::Console::Setup setup;
  setup.joystick = true;
  Bench b(setup);
  b.console.joystick_moved({0, 0, 0, 0}, true, b.now);
  fly_full_control(b);
  b.console.joystick_moved({640, 0, 0, 0}, true, b.now);
  b.qr.height = wire::TelemetryHeight{3000, 500, wire::kHeightValid, 537};
  b.run(100);
  b.key(qrterm::kKeyHome);
  b.run(100);
  EXPECT_EQ(b.qr.control.lift, 640);
  EXPECT_TRUE(
      b.logged("the throttle alone gives lift 640, above the hover lift 537: lift trim 0; close the throttle "
               "to reach the hover"));
}

}  // namespace
