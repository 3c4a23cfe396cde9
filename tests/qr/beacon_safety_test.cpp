// The lost-model beacon (docs/safety.md rule 18, qr/core/lost_model_beacon.hpp) on the fake board:
// DShot "beacon 1" for the ESCs only in safe with every engine at zero, only once the pilot's
// link has been heard and then gone silent past the link timeout, once every 2 s; never while the
// link lives, never while an engine turns.
#include <gtest/gtest.h>

#include <vector>

#include <common/drivers/dshot_commands.hpp>
#include <common/messages.hpp>

#include "fake_flight.hpp"

namespace qr {
namespace {

using test::Firmware;

struct BeaconSafety : test::FakeFlight<> {
  wire::Control sticks;
  std::vector<Mode> mode_at_command;  // the flight's mode at each command the board was given

  // `ms` of time; the console's control frame every 20 ms while `heartbeat`.
  void run_ms(uint32_t ms, bool heartbeat = true) {
    for (uint32_t t = 0; t < ms; ++t) {
      if (heartbeat && t % 20 == 0) send(sticks);
      size_t before = board.esc_commands.size();
      pass_ms([&] {
        if (board.esc_commands.size() != before) mode_at_command.push_back(flight.mode());
        before = board.esc_commands.size();
      });
      board.tx.clear();
    }
  }
  // Every command so far was the beacon, given in safe with every engine at zero.
  void expect_only_stopped_beacons_in_safe() const {
    ASSERT_EQ(mode_at_command.size(), board.esc_commands.size());
    for (size_t i = 0; i < board.esc_commands.size(); ++i) {
      EXPECT_EQ(board.esc_commands[i].command, static_cast<uint8_t>(drivers::DshotCommand::beep1));
      EXPECT_TRUE(board.esc_commands[i].engines.all_zero()) << "command " << i;
      EXPECT_EQ(mode_at_command[i], Mode::safe) << "command " << i;
    }
  }
};

TEST_F(BeaconSafety, NoBeaconBeforeAPilotWasHeardNorWhileTheLinkLives) {
  run_ms(5000, false);  // powered up, no console yet
  EXPECT_TRUE(board.esc_commands.empty());
  run_ms(6000);  // the console's heartbeat
  EXPECT_TRUE(board.esc_commands.empty());
}

TEST_F(BeaconSafety, TheLinkLostInFlightBeaconsOnlyOnceStoppedInSafe) {
  run_ms(50);
  send(wire::ModeChange{++seq, Mode::manual});
  run_ms(5);
  sticks.lift = 500;
  run_ms(1500);
  ASSERT_EQ(flight.mode(), Mode::manual);
  const uint32_t lost_at_us = ticked_us;
  run_ms(1000, false);  // the link lost: panic, the engines ramp down
  EXPECT_EQ(flight.safety().panic_cause(), PanicCause::link_lost);
  run_ms(9000, false);
  ASSERT_EQ(flight.mode(), Mode::safe);
  expect_only_stopped_beacons_in_safe();
  // Once every 2 s from safe on: four or five in the 9 s after the panic's 3 s.
  ASSERT_GE(board.esc_commands.size(), 3u);
  EXPECT_LE(board.esc_commands.size(), 5u);
  EXPECT_GT(board.esc_commands.front().at_us, lost_at_us + 1000000u);
  for (size_t i = 1; i < board.esc_commands.size(); ++i)
    EXPECT_EQ(board.esc_commands[i].at_us - board.esc_commands[i - 1].at_us, kBeaconPeriodUs);

  // The link back: the beacon stops.
  const size_t sounded = board.esc_commands.size();
  sticks.lift = 0;
  run_ms(6000);
  EXPECT_EQ(board.esc_commands.size(), sounded);
}

// In safe with the link lost but an engine not at zero (here: the last command the board was
// given), nothing is sent: the check is on the flight's own engine values, not the board's.
TEST_F(BeaconSafety, TheBeaconWaitsForEveryEngineAtZero) {
  EngineCommand turning;
  turning.value[2] = 1;
  EXPECT_EQ(lost_model_beacon(Mode::safe, turning, 4000000, 1000000, 500000, kPeriodUs), 0);
  EXPECT_EQ(lost_model_beacon(Mode::safe, EngineCommand{}, 4000000, 1000000, 500000, kPeriodUs), kBeaconCommand);
  for (const Mode m :
       {Mode::panic, Mode::manual, Mode::calibration, Mode::yaw_control, Mode::full_control, Mode::height_hold})
    EXPECT_EQ(lost_model_beacon(m, EngineCommand{}, 4000000, 1000000, 500000, kPeriodUs), 0) << wire::mode_name(m);
  EXPECT_EQ(lost_model_beacon(Mode::safe, EngineCommand{}, 4000000, 3600000, 500000, kPeriodUs), 0) << "link alive";
  EXPECT_EQ(lost_model_beacon(Mode::safe, EngineCommand{}, 4000000, 0, 500000, kPeriodUs), 0) << "never heard";
  EXPECT_EQ(lost_model_beacon(Mode::safe, EngineCommand{}, 4000000 + kPeriodUs, 1000000, 500000, kPeriodUs), 0)
      << "one tick in each 2 s";
}

}  // namespace
}  // namespace qr
