// The ESCs' special commands (docs/safety.md rule 18) on the fake board. The lost-model beacon
// (qr/core/lost_model_beacon.hpp): DShot "beacon 1" for the ESCs only in safe with every engine at
// zero, only once the pilot's link has been heard and then gone silent past the link timeout, once
// every 2 s; never while the link lives, never while an engine turns. An ESC's direction set on the
// bench (qr/core/esc_direction.hpp): "spin direction" then "save settings" to that engine alone, in
// safe with every engine stopped, dropped when that ends.
#include <gtest/gtest.h>

#include <string>
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
  for (const Mode m : {Mode::panic, Mode::manual, Mode::calibration, Mode::yaw_control, Mode::full_control,
                       Mode::height_hold, Mode::motor_test})
    EXPECT_EQ(lost_model_beacon(m, EngineCommand{}, 4000000, 1000000, 500000, kPeriodUs), 0) << wire::mode_name(m);
  EXPECT_EQ(lost_model_beacon(Mode::safe, EngineCommand{}, 4000000, 3600000, 500000, kPeriodUs), 0) << "link alive";
  EXPECT_EQ(lost_model_beacon(Mode::safe, EngineCommand{}, 4000000, 0, 500000, kPeriodUs), 0) << "never heard";
  EXPECT_EQ(lost_model_beacon(Mode::safe, EngineCommand{}, 4000000 + kPeriodUs, 1000000, 500000, kPeriodUs), 0)
      << "one tick in each 2 s";
}

struct EscDirectionSafety : test::FakeFlight<> {
  wire::Control sticks;

  void run_ms(uint32_t ms) {
    for (uint32_t t = 0; t < ms; ++t) {
      if (t % 20 == 0) send(sticks);
      pass_ms();
      receive();
    }
  }
  static constexpr uint8_t kSpinDirection2 = static_cast<uint8_t>(drivers::DshotCommand::spin_direction_2);
  static constexpr uint8_t kSave = static_cast<uint8_t>(drivers::DshotCommand::save_settings);
};

TEST_F(EscDirectionSafety, TheDirectionThenItsSaveGoToThatEngineAloneInSafe) {
  run_ms(100);
  send(wire::EscDirection{++seq, 2, 2});
  run_ms(100);
  ASSERT_EQ(got<wire::Ack>().size(), 1u);
  ASSERT_EQ(board.esc_commands.size(), 2u);
  const auto& direction = board.esc_commands[0];
  const auto& save = board.esc_commands[1];
  EXPECT_EQ(direction.command, kSpinDirection2);
  EXPECT_EQ(save.command, kSave);
  EXPECT_EQ(direction.to, 1u << 2) << "the back engine's ESC alone";
  EXPECT_EQ(save.to, 1u << 2);
  EXPECT_TRUE(direction.engines.all_zero() && save.engines.all_zero());
  EXPECT_EQ(save.at_us - direction.at_us, kEscSaveAfterUs) << "after the direction's six frames";
  EXPECT_NE(debug_text().find("ESC 3: spin direction 2, saved\n"), std::string::npos) << debug_text();

  // A board whose ESCs take no command (no DShot): the pilot is told, and nothing is saved.
  board.esc_commands_taken = false;
  send(wire::EscDirection{++seq, 0, 1});
  run_ms(100);
  EXPECT_EQ(board.esc_commands.size(), 3u);
  EXPECT_NE(debug_text().find("ESC 1: spin direction 1 not set"), std::string::npos) << debug_text();
}

TEST_F(EscDirectionSafety, OnlyInSafeAndDroppedWhenAnEngineStarts) {
  run_ms(100);
  send(wire::MotorTest{++seq, 0, 100});
  run_ms(10);
  ASSERT_EQ(flight.mode(), Mode::motor_test);
  send(wire::EscDirection{++seq, 0, 2});
  run_ms(10);
  ASSERT_FALSE(got<wire::Nack>().empty());
  EXPECT_EQ(got<wire::Nack>().back().reason, NackReason::not_from_this_mode) << "an engine turns in a motor test";
  run_ms(2100);
  ASSERT_EQ(flight.mode(), Mode::safe);
  EXPECT_TRUE(board.esc_commands.empty());

  // Asked for in safe; the engines start before its save: the save is never sent.
  send(wire::EscDirection{++seq, 1, 2});
  run_ms(5);
  ASSERT_EQ(board.esc_commands.size(), 1u);
  send(wire::MotorTest{++seq, 3, 100});
  run_ms(100);
  ASSERT_EQ(flight.mode(), Mode::motor_test);
  EXPECT_EQ(board.esc_commands.size(), 1u) << "no save once an engine turns";
  EXPECT_NE(debug_text().find("ESC 2: spin direction 2 not set"), std::string::npos) << debug_text();

  // The job alone: an engine turning in safe (as no flight has it) refuses and drops it too.
  EscDirection job;
  EngineCommand turning;
  turning.value[1] = 1;
  EXPECT_EQ(job.request(1, 2, Mode::safe, turning, 0), NackReason::engines_running);
  EXPECT_EQ(job.request(1, 3, Mode::safe, EngineCommand{}, 0), NackReason::bad_value);
  ASSERT_EQ(job.request(1, 2, Mode::safe, EngineCommand{}, 0), NackReason::none);
  EXPECT_EQ(job.request(0, 1, Mode::safe, EngineCommand{}, 0), NackReason::busy) << "one at a time";
  EXPECT_EQ(job.due(Mode::safe, turning, 1000).command, 0);
  EXPECT_FALSE(job.pending()) << "dropped";
}

}  // namespace
}  // namespace qr
