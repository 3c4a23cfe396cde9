// The flight context end to end on the fake board: frames in through the serial line, acks,
// telemetry and engine values out, with a scripted signal chain.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "fake_flight.hpp"

namespace qr {
namespace {

using test::Firmware;

struct FlightTest : test::FakeFlight<> {
  wire::Control sticks;

  uint8_t request_mode(Mode mode) {
    send(wire::ModeChange{++seq, mode});
    return seq;
  }
  // Runs for `ms` with the console's heartbeat: a control frame every 20 ms.
  void run_ms(uint32_t ms, bool heartbeat = true) {
    for (uint32_t t = 0; t < ms; ++t) {
      if (heartbeat && t % 20 == 0) send(sticks);
      pass_ms();
      receive();
    }
  }
  void calibrate() {
    request_mode(Mode::calibration);
    run_ms(50);
    ASSERT_EQ(flight.mode(), Mode::safe) << "calibration returns to safe when done";
  }
};

TEST_F(FlightTest, StartsInSafeAndStreamsTelemetryAtTheParameterRate) {
  run_ms(1000);
  EXPECT_EQ(flight.mode(), Mode::safe);
  const auto attitude = got<wire::TelemetryAttitude>();
  const auto rate = wire::kParameterTable[static_cast<int>(wire::ParamId::telemetry_rate_hz) - 1].default_value;
  EXPECT_NEAR(static_cast<double>(attitude.size()), rate, 1.0);
  ASSERT_FALSE(attitude.empty());
  EXPECT_EQ(attitude.back().phi, 123);
  EXPECT_EQ(attitude.back().mode, Mode::safe);
  // The rates frame follows the attitude frame; the last one may still be on its way.
  EXPECT_NEAR(static_cast<double>(got<wire::TelemetryRates>().size()), static_cast<double>(attitude.size()), 1.0);
  EXPECT_NEAR(static_cast<double>(got<wire::TelemetrySystem>().size()), rate / 6.0, 1.0);  // a sixth: 6 slow groups
  EXPECT_NEAR(static_cast<double>(got<wire::LogStatus>().size()), rate / 6.0, 1.0);
  EXPECT_NEAR(static_cast<double>(got<wire::TelemetryHeight>().size()), rate / 6.0, 1.0);
  EXPECT_EQ(got<wire::TelemetrySystem>().back().battery_mv, 12000);
  EXPECT_EQ(flight.tx_dropped_frames(), 0u);

  // Every task's figures come round; those that ran have a count and cost.
  const auto tasks = got<wire::TelemetryTask>();
  ASSERT_GE(tasks.size(), size_t{kFlightTaskCount});
  EXPECT_EQ(tasks[kFlightTaskCount - 1].task, kFlightTaskCount - 1);
  EXPECT_EQ(scheduler.stats().task[kLinkTask].count, scheduler.stats().ticks);
  EXPECT_EQ(scheduler.stats().task[kAttitudeControlTask].count, 0u) << "not in safe's task set";
}

// Bytes the board's receiver had no room for never reach the parser: only the board can count
// them, and the console sees them in telemetry_link, saturated so a count never reads 0 again.
TEST_F(FlightTest, TheBoardsReceiveOverrunsReachTheConsole) {
  run_ms(500);
  ASSERT_FALSE(got<wire::TelemetryLink>().empty());
  EXPECT_EQ(got<wire::TelemetryLink>().back().rx_overruns, 0);
  board.overruns = 3;
  run_ms(500);
  EXPECT_EQ(got<wire::TelemetryLink>().back().rx_overruns, 3);
  board.overruns = 300;
  run_ms(500);
  EXPECT_EQ(got<wire::TelemetryLink>().back().rx_overruns, 255);
}

TEST_F(FlightTest, ModeChangeIsAckedWithItsSequenceNumberAndApplied) {
  const uint8_t s = request_mode(Mode::manual);
  run_ms(30);  // long enough for the debug text to get through the bounded transmitter
  EXPECT_EQ(flight.mode(), Mode::manual);
  const auto acks = got<wire::Ack>();
  ASSERT_EQ(acks.size(), 1u);
  EXPECT_EQ(acks[0].type, wire::MessageType::mode_change);
  EXPECT_EQ(acks[0].seq, s);
  EXPECT_NE(debug_text().find("mode: manual\n"), std::string::npos);
}

// The tick that reads a request's last byte answers it, and with the line idle its bytes go out
// in that tick (docs/devboard.md, "The ground line": every request answered within two control
// periods; GroundLine.* measures it at the full line rate).
TEST_F(FlightTest, ARequestIsAnsweredInTheTickThatReadsIt) {
  run_ms(10);  // the first telemetry period has gone out: the line is idle
  for (const Mode mode : {Mode::safe, Mode::manual, Mode::safe}) {
    received.clear();
    const uint8_t s = request_mode(mode);
    run_ms(qr::kPeriodUs / 1000);  // one period (1 ms at 1 kHz, 2 at 500 Hz): the tick that reads it
    receive();
    const auto acks = got<wire::Ack>();
    ASSERT_EQ(acks.size(), 1u) << "answered in the tick that read it, asking for " << wire::mode_key(mode);
    EXPECT_EQ(acks[0].seq, s);
    run_ms(6);  // a mode announcement, if any, goes out
  }
}

// An answer waits for nothing the QR queued before it but a frame already on its way (its
// transmit queue, docs/devboard.md "The ground line"): with the line held up while telemetry
// piles up, the ack comes out first, or second behind the frame it found part-way out.
TEST_F(FlightTest, AnAnswerGoesOutAheadOfTheTelemetryQueuedBeforeIt) {
  run_ms(100);
  board.tx_capacity = 0;  // the line takes nothing: three telemetry periods pile up in the QR
  run_ms(60);
  received.clear();
  const uint8_t s = request_mode(Mode::safe);
  run_ms(1);
  board.tx_capacity = 1u << 20;
  run_ms(20);
  size_t at = received.size();
  for (size_t i = 0; i < received.size() && at == received.size(); ++i) {
    wire::Ack ack;
    if (wire::decode(received[i], ack) && ack.seq == s) at = i;
  }
  ASSERT_LT(at, received.size()) << "the request was answered";
  EXPECT_LE(at, 1u) << "frames out before the ack";
  EXPECT_GE(got<wire::TelemetryAttitude>().size(), 3u) << "the telemetry held up came out after it";
  EXPECT_EQ(flight.tx_dropped_frames(), 0u);
}

TEST_F(FlightTest, RefusedModeChangeIsNackedWithTheSafetyReason) {
  sticks.lift = 100;
  run_ms(30);
  request_mode(Mode::manual);
  run_ms(5);
  EXPECT_EQ(flight.mode(), Mode::safe);
  const auto nacks = got<wire::Nack>();
  ASSERT_EQ(nacks.size(), 1u);
  EXPECT_EQ(nacks[0].reason, wire::NackReason::controls_not_neutral);
}

// Sensor faults reach the console (qr/core/sensor_fault_report.hpp): which sensor, which kind, how
// many, at most a line a second per sensor however fast they are counted.
TEST_F(FlightTest, SensorFaultsAreToldToTheConsoleAtMostOnceASecond) {
  board.sensors.health.imu_fault = static_cast<uint8_t>(drivers::Mpu6050Fault::bus_stuck);
  for (uint32_t ms = 0; ms < 3500; ++ms) {
    board.sensors.health.imu_faults = ms;  // a fault every tick: a stuck bus
    run_ms(1);
  }
  run_ms(30);
  const std::string text = debug_text();
  EXPECT_NE(text.find("imu fault: bus stuck ("), std::string::npos) << text;
  size_t lines = 0;
  for (size_t at = text.find("imu fault:"); at != std::string::npos; at = text.find("imu fault:", at + 1)) ++lines;
  EXPECT_GE(lines, 3u);
  EXPECT_LE(lines, 4u) << "one a second: " << text;
  EXPECT_EQ(text.find("barometer fault:"), std::string::npos);
  EXPECT_EQ(flight.tx_dropped_frames(), 0u);
}

// The MPU's address NACK while it starts (its first 100 ms) is start-up's: counted by the driver,
// not reported, no refusal once it streams.
TEST_F(FlightTest, TheImusStartUpNackIsNeitherReportedNorARefusal) {
  board.sensors.health.imu = false;
  board.sensors.health.imu_faults = 1;
  board.sensors.health.imu_fault = static_cast<uint8_t>(drivers::Mpu6050Fault::address_nack);
  run_ms(240);
  board.sensors.health.imu = true;
  run_ms(2000);
  EXPECT_EQ(debug_text().find("imu fault:"), std::string::npos) << debug_text();
  calibrate();
  EXPECT_TRUE(got<wire::Nack>().empty());
}

// An IMU that never streams (a wrong identity): calibration is refused with imu_fault, and once the
// start-up's second has passed its faults are told, the kind named.
TEST_F(FlightTest, AnUnhealthyImuRefusesCalibrationAndSaysWhy) {
  board.sensors.health.imu = false;
  board.sensors.health.imu_fault = static_cast<uint8_t>(drivers::Mpu6050Fault::wrong_identity);
  for (uint32_t ms = 0; ms < 1500; ++ms) {
    board.sensors.health.imu_faults = ms / 100;  // one each 100 ms, the driver's retry
    run_ms(1);
  }
  request_mode(Mode::calibration);
  run_ms(30);
  EXPECT_EQ(flight.mode(), Mode::safe);
  const auto nacks = got<wire::Nack>();
  ASSERT_EQ(nacks.size(), 1u);
  EXPECT_EQ(nacks[0].reason, wire::NackReason::imu_fault);
  EXPECT_NE(debug_text().find("imu fault: wrong identity ("), std::string::npos) << debug_text();
}

TEST_F(FlightTest, FullControlNeedsCalibrationThroughTheLink) {
  request_mode(Mode::full_control);
  run_ms(5);
  ASSERT_EQ(got<wire::Nack>().size(), 1u);
  EXPECT_EQ(got<wire::Nack>()[0].reason, wire::NackReason::not_calibrated);
  calibrate();
  request_mode(Mode::full_control);
  run_ms(5);
  EXPECT_EQ(flight.mode(), Mode::full_control);
}

TEST_F(FlightTest, ResentRequestIsAnsweredAgainButAppliedOnce) {
  const wire::ModeChange to_manual{7, Mode::manual};
  send(to_manual);
  run_ms(5);
  ASSERT_EQ(flight.mode(), Mode::manual);
  sticks.lift = 300;
  run_ms(40);
  // The ack was lost and the link dropped out long enough to panic. When it comes back, the
  // console's resend of the same request arrives: answered as before, not applied again (applied,
  // it would be refused now, in panic).
  run_ms(300, false);
  ASSERT_EQ(flight.mode(), Mode::panic);
  send(to_manual);
  run_ms(5);
  EXPECT_EQ(flight.mode(), Mode::panic);
  EXPECT_TRUE(got<wire::Nack>().empty());
  const auto acks = got<wire::Ack>();
  ASSERT_EQ(acks.size(), 2u);
  EXPECT_EQ(acks[1].seq, 7);
}

TEST_F(FlightTest, ARequestReusingASeqWithNewContentIsAppliedNotAckedFromMemory) {
  // Manual with seq 17, acked and flying; then panic with the same seq 17 (a console restarted
  // part-way through its numbers): applied, not answered as a resend of the manual request.
  send(wire::ModeChange{17, Mode::manual});
  run_ms(5);
  ASSERT_EQ(flight.mode(), Mode::manual);
  sticks.lift = 300;
  run_ms(500);
  ASSERT_EQ(board.engines.value[0], 300);
  send(wire::ModeChange{17, Mode::panic});
  run_ms(5);
  EXPECT_EQ(flight.mode(), Mode::panic);
  EXPECT_EQ(got<wire::Ack>().size(), 2u);

  const uint8_t level = static_cast<uint8_t>(wire::ParamId::panic_level);
  send(wire::ParamSet{17, level, 80});
  run_ms(5);
  send(wire::ParamSet{17, level, 70});
  run_ms(5);
  EXPECT_EQ(flight.parameters().get(wire::ParamId::panic_level), 70) << "the second value is the one acked";
}

TEST_F(FlightTest, AStopIsAppliedEvenWhenItIsAResend) {
  // The stop's first copy arrived in safe (nothing to stop); the pilot then takes off. A late copy
  // of that stop, byte for byte the same and within the dedup window, must still stop.
  const wire::ModeChange stop{9, Mode::panic};
  send(stop);
  run_ms(5);
  send(wire::ModeChange{3, Mode::manual});
  run_ms(5);
  ASSERT_EQ(flight.mode(), Mode::manual);
  sticks.lift = 300;
  run_ms(100);
  send(stop);  // byte for byte the first copy, within the dedup window
  run_ms(5);
  EXPECT_EQ(flight.mode(), Mode::panic);
}

// Rule 22 through the wire: the motor test's request spins its engine alone, acked, for 2 s to the
// tick; a control frame with lift ends it in the tick that reads it; a level above the cap is
// malformed (nack bad_value).
TEST_F(FlightTest, AMotorTestSpinsItsEngineForTwoSecondsAndTheLiftEndsIt) {
  run_ms(100);
  send(wire::MotorTest{++seq, 1, 120});
  uint32_t spinning_ticks = 0;
  bool others_still = true;
  for (uint32_t t = 0; t < 2500; ++t) {
    if (t % 20 == 0) send(sticks);
    pass_ms([&] {
      const EngineCommand e = board.engines;
      if (e.value[1] == 120) ++spinning_ticks;
      others_still = others_still && e.value[0] == 0 && e.value[2] == 0 && e.value[3] == 0;
    });
    receive();
  }
  ASSERT_EQ(got<wire::Ack>().size(), 1u);
  EXPECT_EQ(got<wire::Ack>()[0].type, wire::MessageType::motor_test);
  EXPECT_EQ(spinning_ticks, 2000000u / kPeriodUs) << "the right engine at its level for 2 s to the tick";
  EXPECT_TRUE(others_still);
  EXPECT_EQ(flight.mode(), Mode::safe);
  EXPECT_NE(debug_text().find("mode: motor test\nmode: safe\n"), std::string::npos);

  send(wire::MotorTest{++seq, 3, 200});
  run_ms(500);
  ASSERT_EQ(flight.mode(), Mode::motor_test);
  ASSERT_EQ(board.engines.value[3], 200);
  sticks.lift = 1;
  send(sticks);
  for (uint32_t ms = 0; ms < kPeriodUs / 1000; ++ms) pass_ms();  // one control period: one tick
  EXPECT_EQ(flight.mode(), Mode::safe) << "the tick that reads the lift";
  EXPECT_TRUE(board.engines.all_zero());

  sticks.lift = 0;
  run_ms(100);
  send(wire::MotorTest{++seq, 0, wire::kMotorTestMaxLevel + 1});
  run_ms(5);
  ASSERT_FALSE(got<wire::Nack>().empty());
  EXPECT_EQ(got<wire::Nack>().back().reason, NackReason::bad_value);
  EXPECT_EQ(flight.mode(), Mode::safe);
}

TEST_F(FlightTest, OutOfRangeControlsAreNotLifeAndEndInTheLinkLossPanic) {
  request_mode(Mode::manual);
  run_ms(5);
  sticks.lift = 500;
  run_ms(100);
  ASSERT_EQ(board.engines.value[0], 500);
  // Control frames with a good check but a field out of range, one field after another: ignored,
  // so the set-points stay at the last good frame only until the link watchdog ends the flight.
  const wire::Control bad[] = {{1001, 0, 0, 0}, {500, -1001, 0, 0}, {500, 0, 1001, 0}, {500, 0, 0, -1001}};
  // The last good frame came 20 ms before the end of run_ms(100).
  const uint32_t timeout_ms = flight.safety().limits().link_timeout_us / 1000u;
  for (uint32_t t = 20; t + 20 < timeout_ms; t += 20) {
    send(bad[(t / 20) % 4]);
    run_ms(20, false);
  }
  EXPECT_EQ(flight.mode(), Mode::manual);
  EXPECT_EQ(flight.controls().lift, 500) << "a bad frame never reaches the set-points";
  for (uint32_t t = 0; t < 40; t += 20) {
    send(bad[0]);
    run_ms(20, false);
  }
  EXPECT_EQ(flight.mode(), Mode::panic);
  EXPECT_EQ(flight.safety().panic_cause(), PanicCause::link_lost);
}

TEST_F(FlightTest, EnginesFollowTheMixerInManualAndStayZeroInSafe) {
  sticks.lift = 400;
  run_ms(30);
  EXPECT_TRUE(board.engines.all_zero()) << "safe: engines zero whatever the sticks say";
  sticks.lift = 0;
  run_ms(30);
  request_mode(Mode::manual);
  run_ms(5);
  ASSERT_EQ(flight.mode(), Mode::manual);
  sticks.lift = 400;
  run_ms(30);
  for (uint16_t v : board.engines.value) EXPECT_EQ(v, 400);
  sticks.lift = 20;  // below idle: the safety machine keeps the engines turning
  run_ms(30);
  for (uint16_t v : board.engines.value) EXPECT_EQ(v, flight.safety().limits().idle);
}

TEST_F(FlightTest, LinkLossInFlightPanicsThenSettlesInSafe) {
  request_mode(Mode::manual);
  run_ms(5);
  sticks.lift = 500;
  run_ms(1500);        // long enough for the machine's flying lift to be the lift
  run_ms(260, false);  // the console goes quiet
  EXPECT_EQ(flight.mode(), Mode::panic);
  EXPECT_NE(debug_text().find("mode: panic (link lost)\n"), std::string::npos);
  // Manual: the cut, every engine at panic_level % of the lift that was flying.
  EXPECT_FALSE(flight.safety().landing());
  EXPECT_NEAR(board.engines.value[0], 500 * flight.safety().limits().panic_hold_pct / 100, 2);
  run_ms(3100, false);
  EXPECT_EQ(flight.mode(), Mode::safe);
  EXPECT_TRUE(board.engines.all_zero());
}

TEST_F(FlightTest, TiltFromTheEstimatorPanicsFullControl) {
  calibrate();
  request_mode(Mode::full_control);
  run_ms(5);
  sticks.lift = 500;
  run_ms(50);
  flight.chain().tilt = flight.safety().limits().tilt_limit_mrad + 1;
  const uint32_t tilt_time_ms = flight.safety().limits().tilt_time_us / 1000u;
  run_ms(tilt_time_ms - 5);
  EXPECT_EQ(flight.mode(), Mode::full_control) << "an upset, not yet a lost vehicle";
  run_ms(10);
  EXPECT_EQ(flight.mode(), Mode::panic);
}

// Safety rule 6 through the flight: a panic in full control with a height estimate starts the
// chain's descent from the lift that was flying, passes the chain's engines, and ends at the
// chain's touchdown, the engines stopping in that tick.
TEST_F(FlightTest, APanicThatLandsFliesTheChainsDescentUntilTouchdown) {
  calibrate();
  request_mode(Mode::full_control);
  run_ms(5);
  sticks.lift = 520;
  run_ms(1500);
  flight.chain().descent_engines = 470;
  sticks.lift = 0;  // the pilot lets go as he hits the stop
  request_mode(Mode::panic);
  run_ms(30);
  ASSERT_EQ(flight.mode(), Mode::panic);
  EXPECT_TRUE(flight.safety().landing());
  EXPECT_EQ(flight.chain().descents_started, 1u);
  EXPECT_NEAR(flight.chain().descent_from_lift, 520, 30) << "the lift that was flying, not the stick at 0";
  EXPECT_GT(flight.chain().vertical_controlled, 0u) << "the panic runs the vertical loops";
  for (uint16_t v : board.engines.value) EXPECT_EQ(v, 470);
  run_ms(5000);
  EXPECT_EQ(flight.mode(), Mode::panic) << "a landing lasts until its touchdown";
  flight.chain().landed_now = true;
  scheduler.tick();
  EXPECT_EQ(flight.mode(), Mode::safe);
  EXPECT_TRUE(board.engines.all_zero());
  scheduler.tick();  // the safety task's transition reaches the chain at the next tick's door
  EXPECT_FALSE(flight.chain().descending) << "safe gives the lift back to the stick";
}

// Safety rule 15 through the flight: the control frame that changes the lift ends height hold in
// the tick that reads it, before the chain runs: that tick's engines are already the stick's.
TEST_F(FlightTest, ALiftChangeEndsHeightHoldInTheTickThatReadsIt) {
  calibrate();
  request_mode(Mode::full_control);
  run_ms(5);
  sticks.lift = 500;
  run_ms(200);
  flight.chain().hold_engines = 650;
  request_mode(Mode::height_hold);
  run_ms(100);
  ASSERT_EQ(flight.mode(), Mode::height_hold);
  EXPECT_EQ(flight.chain().height_holds_entered, 1u);
  for (uint16_t v : board.engines.value) EXPECT_EQ(v, 650) << "the chain flies the lift";
  const uint32_t attitude_entered = flight.chain().attitude_entered;
  sticks.lift = 501;
  send(sticks);
  for (int i = 0; i < 10 && flight.controls().lift != 501; ++i) scheduler.tick();
  ASSERT_EQ(flight.controls().lift, 501);
  EXPECT_EQ(flight.mode(), Mode::full_control) << "in the tick that read the frame";
  for (uint16_t v : board.engines.value) EXPECT_EQ(v, 501) << "that tick's engines are the stick's";
  EXPECT_EQ(flight.chain().attitude_entered, attitude_entered) << "back from height hold the integrals keep their trim";
  // The pilot's toggle: in again, and out with the mode request.
  request_mode(Mode::height_hold);
  run_ms(50);
  ASSERT_EQ(flight.mode(), Mode::height_hold);
  request_mode(Mode::full_control);
  run_ms(50);
  EXPECT_EQ(flight.mode(), Mode::full_control);
}

TEST_F(FlightTest, TaskSetsFollowTheMode) {
  run_ms(10);
  EXPECT_EQ(flight.chain().attitude_controlled, 0u);
  calibrate();
  request_mode(Mode::yaw_control);
  run_ms(10);
  EXPECT_GT(flight.chain().yaw_controlled, 0u);
  // Yaw control runs the flying set, attitude task included (its moments are fresh for a panic's
  // landing entered from there), but its sources leave roll and pitch to the sticks.
  EXPECT_GT(flight.chain().attitude_controlled, 0u);
  EXPECT_EQ(flight.chain().sources.tilt, chain::Tilt::stick);
  EXPECT_EQ(flight.chain().sources.yaw, chain::Yaw::rate);
  request_mode(Mode::safe);
  run_ms(3100);
  request_mode(Mode::full_control);
  run_ms(10);
  EXPECT_EQ(flight.mode(), Mode::full_control);
  EXPECT_GT(flight.chain().attitude_controlled, 0u);
}

// Acro is a row of the mode table (issue 31's worked example): entered from safe once calibrated,
// its sources the rate loops' on the pilot's lift, its integrals emptied on entry, and out
// through panic as every flight mode.
TEST_F(FlightTest, AcroIsARowOfTheModeTable) {
  request_mode(Mode::acro);
  run_ms(10);
  EXPECT_EQ(flight.mode(), Mode::safe) << "refused before a calibration";
  calibrate();
  const uint32_t attitude_entered = flight.chain().attitude_entered;
  request_mode(Mode::acro);
  run_ms(10);
  ASSERT_EQ(flight.mode(), Mode::acro);
  EXPECT_EQ(flight.chain().sources.tilt, chain::Tilt::rate);
  EXPECT_EQ(flight.chain().sources.yaw, chain::Yaw::rate);
  EXPECT_EQ(flight.chain().sources.lift, chain::Lift::stick);
  EXPECT_EQ(flight.chain().attitude_entered, attitude_entered + 1) << "the integrals start empty";
  EXPECT_GT(flight.chain().attitude_controlled, 0u);
  request_mode(Mode::safe);
  run_ms(10);
  EXPECT_EQ(flight.mode(), Mode::panic) << "a flight mode leaves through panic";
}

TEST_F(FlightTest, EnteringAModeRunsItsEntryActionOnceByTheTransition) {
  calibrate();
  EXPECT_EQ(flight.chain().calibrations_entered, 1u) << "calibration restarts its run on entry";
  request_mode(Mode::full_control);
  run_ms(100);
  ASSERT_EQ(flight.mode(), Mode::full_control);
  EXPECT_EQ(flight.chain().attitude_entered, 1u) << "full control empties the integrals on entry, once";
  request_mode(Mode::panic);
  run_ms(3100);  // panic, then safe
  ASSERT_EQ(flight.mode(), Mode::safe);
  request_mode(Mode::yaw_control);
  run_ms(10);
  EXPECT_EQ(flight.chain().attitude_entered, 1u) << "yaw control has no attitude loops to empty";
  request_mode(Mode::panic);
  run_ms(3100);
  request_mode(Mode::full_control);
  run_ms(10);
  EXPECT_EQ(flight.chain().attitude_entered, 2u);
  request_mode(Mode::calibration);
  run_ms(10);
  EXPECT_EQ(flight.mode(), Mode::full_control);
  EXPECT_EQ(flight.chain().calibrations_entered, 1u) << "refused from full control: no entry";
}

TEST_F(FlightTest, DividedTasksRunAtTheirRowsRates) {
  run_ms(1000);
  EXPECT_EQ(flight.chain().accel_angles, kControlHz / test::ScriptedChain::kAccelDivider);
  EXPECT_EQ(flight.chain().estimated, kControlHz);
  const uint8_t rate = static_cast<uint8_t>(wire::ParamId::telemetry_rate_hz);
  send(wire::ParamSet{++seq, rate, 10});
  run_ms(100);
  received.clear();
  run_ms(1000);
  EXPECT_NEAR(static_cast<double>(got<wire::TelemetryAttitude>().size()), 10.0, 1.0)
      << "the new rate after the next run";
}

// Rule 13: a change of the estimator's divisors or lag in safe (on the ground) restarts it from the
// accelerometer; in flight it applies as it comes; other parameters never restart it.
TEST_F(FlightTest, AnEstimatorParameterSetInSafeRestartsTheEstimator) {
  calibrate();
  const uint32_t after_calibration = flight.chain().estimator_restarts;
  for (const wire::ParamId id : {wire::ParamId::attitude_c1, wire::ParamId::attitude_c2, wire::ParamId::accel_lag_ms}) {
    const uint32_t before = flight.chain().estimator_restarts;
    send(wire::ParamSet{++seq, static_cast<uint8_t>(id), 1000});
    run_ms(5);
    EXPECT_EQ(flight.chain().estimator_restarts, before + 1) << "parameter " << static_cast<int>(id);
  }
  send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::yaw_p), 100});
  run_ms(5);
  EXPECT_EQ(flight.chain().estimator_restarts, after_calibration + 3) << "yaw_p does not feed the estimator";

  request_mode(Mode::full_control);
  run_ms(10);
  ASSERT_EQ(flight.mode(), Mode::full_control);
  send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::attitude_c2), 2000000});
  run_ms(5);
  EXPECT_EQ(flight.chain().estimator_restarts, after_calibration + 3) << "not in flight";
}

TEST_F(FlightTest, ParameterSetIsRangeCheckedAppliedAndReported) {
  send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::link_timeout_ms), 500});
  send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::link_timeout_ms), 5});  // below range
  send(wire::ParamSet{++seq, 200, 1});                                                   // no such id
  run_ms(5);
  EXPECT_EQ(flight.safety().limits().link_timeout_us, 500000u);
  ASSERT_EQ(got<wire::Ack>().size(), 1u);
  const auto nacks = got<wire::Nack>();
  ASSERT_EQ(nacks.size(), 2u);
  EXPECT_EQ(nacks[0].reason, wire::NackReason::bad_value);
  EXPECT_EQ(nacks[1].reason, wire::NackReason::unknown_parameter);
  const auto after_set = got<wire::ParamReport>();  // the value now in force follows the ack
  ASSERT_EQ(after_set.size(), 1u);
  EXPECT_EQ(after_set[0].id, static_cast<uint8_t>(wire::ParamId::link_timeout_ms));
  EXPECT_EQ(after_set[0].value, 500);
  received.clear();

  send(wire::ParamGet{++seq, wire::kAllParameters});
  // One report a control period: the whole table, plus a few periods for the request to arrive.
  run_ms(static_cast<uint32_t>(wire::kParameterCount * kPeriodUs / 1000 + 10));
  const auto reports = got<wire::ParamReport>();
  ASSERT_EQ(reports.size(), wire::kParameterCount);
  for (const auto& r : reports) {
    if (r.id == static_cast<uint8_t>(wire::ParamId::link_timeout_ms)) EXPECT_EQ(r.value, 500);
  }
}

// A calibration that measured turns (gyro_turns.hpp): a found scale becomes its axis' parameter,
// gyro_turns goes back to 0 found or not (the next calibration is one at rest, not a minute's wait
// for a turn nobody makes), and the console gets the four values and a line saying what happened.
TEST_F(FlightTest, ATurnMeasurementSetsItsAxisScaleAndEndsTheTurns) {
  using wire::ParamId;
  auto value = [&](ParamId id) { return flight.parameters().get(id); };
  send(wire::ParamSet{++seq, static_cast<uint8_t>(ParamId::gyro_turns), 2});
  send(wire::ParamSet{++seq, static_cast<uint8_t>(ParamId::gyro_scale_x_ppm), -700});
  run_ms(5);
  ASSERT_EQ(value(ParamId::gyro_turns), 2);
  received.clear();

  flight.chain().turns_scripted = true;
  flight.chain().turns_result = {true, 2, 23456};
  calibrate();
  run_ms(10);
  EXPECT_EQ(value(ParamId::gyro_scale_z_ppm), 23456);
  EXPECT_EQ(value(ParamId::gyro_scale_x_ppm), -700);
  EXPECT_EQ(value(ParamId::gyro_turns), 0);
  std::vector<std::pair<uint8_t, int32_t>> reports;
  for (const auto& r : got<wire::ParamReport>()) reports.emplace_back(r.id, r.value);
  const std::vector<std::pair<uint8_t, int32_t>> expected = {{static_cast<uint8_t>(ParamId::gyro_scale_x_ppm), -700},
                                                             {static_cast<uint8_t>(ParamId::gyro_scale_y_ppm), 0},
                                                             {static_cast<uint8_t>(ParamId::gyro_scale_z_ppm), 23456},
                                                             {static_cast<uint8_t>(ParamId::gyro_turns), 0}};
  EXPECT_EQ(reports, expected);
  EXPECT_NE(debug_text().find("gyro turns: z scale set"), std::string::npos) << debug_text();

  // Not found: the scales stay, the turns still end.
  send(wire::ParamSet{++seq, static_cast<uint8_t>(ParamId::gyro_turns), 1});
  run_ms(5);
  received.clear();
  flight.chain().turns_scripted = true;
  flight.chain().turns_result = {};
  calibrate();
  run_ms(10);
  EXPECT_EQ(value(ParamId::gyro_scale_z_ppm), 23456);
  EXPECT_EQ(value(ParamId::gyro_turns), 0);
  EXPECT_NE(debug_text().find("no turn"), std::string::npos) << debug_text();
}

TEST_F(FlightTest, ExitIsConfirmedThenTheFirmwareStops) {
  send(wire::Exit{++seq});
  for (int i = 0; i < 100 && flight.running(); ++i) run_ms(1);
  EXPECT_FALSE(flight.running());
  EXPECT_EQ(flight.mode(), Mode::safe);
  const auto acks = got<wire::Ack>();
  ASSERT_EQ(acks.size(), 1u);
  EXPECT_EQ(acks[0].type, wire::MessageType::exit);
}

TEST_F(FlightTest, GarbageOnTheLineIsCountedAndTheNextFrameStillWorks) {
  for (int i = 0; i < 200; ++i) board.rx.push_back(static_cast<uint8_t>(i * 37 + 11));
  request_mode(Mode::manual);
  run_ms(30);
  EXPECT_EQ(flight.mode(), Mode::manual);
  EXPECT_GT(flight.link_counters().bytes_skipped, 0u);
}

}  // namespace
}  // namespace qr

namespace qr {
namespace {

// The loggers through the link, on the fake board's log memory.
struct FlightLogTest : FlightTest {
  FlightLogTest() { flight = Firmware(board.log_area()); }

  wire::LogStatus status() const { return got<wire::LogStatus>().back(); }
  template <class Record>
  std::vector<Record> lines() const {
    wire::LogLineAssembler<Record> assembler;
    std::vector<Record> out;
    for (const auto& part : got<wire::LogPart<Record>>()) {
      Record r;
      if (assembler.add(part, r) == wire::LogLineAssembler<Record>::Result::complete) out.push_back(r);
    }
    return out;
  }
};

TEST_F(FlightLogTest, StartWritesALineEveryDividerTicksStopEndsIt) {
  send(wire::LogStart{++seq, wire::kLogSensor | wire::kLogTelemetry});
  run_ms(1000);
  send(wire::LogStop{++seq});
  run_ms(20);
  ASSERT_EQ(got<wire::Ack>().size(), 2u);
  const auto divider = wire::kParameterTable[static_cast<int>(wire::ParamId::log_divider) - 1].default_value;
  const double expected = 1000.0 * 1000 / kPeriodUs / divider;
  EXPECT_NEAR(status().sensor_lines, expected, 2.0);
  EXPECT_EQ(status().telemetry_lines, status().sensor_lines) << "at most 100 Hz: all of them at the default divider";
  EXPECT_EQ(status().flags, 0) << "stopped";
  const uint16_t lines = status().sensor_lines;
  run_ms(200);
  EXPECT_EQ(status().sensor_lines, lines);
}

TEST_F(FlightLogTest, DownloadWhileLoggingIsRefusedAsBusy) {
  send(wire::LogStart{++seq, wire::kLogSensor});
  run_ms(50);
  send(wire::LogDownload{++seq, wire::LogKind::sensor, 0, 0});
  run_ms(5);
  ASSERT_EQ(got<wire::Nack>().size(), 1u);
  EXPECT_EQ(got<wire::Nack>()[0].reason, wire::NackReason::busy);
}

TEST_F(FlightLogTest, DownloadSendsEveryLineOfTheRangeWithItsRecord) {
  send(wire::LogStart{++seq, wire::kLogSensor | wire::kLogTelemetry});
  run_ms(600);  // 30 lines at 500 Hz, 60 at 1 kHz
  send(wire::LogStop{++seq});
  run_ms(20);
  const uint16_t total = status().telemetry_lines;
  ASSERT_GT(total, 20);
  send(wire::LogDownload{++seq, wire::LogKind::telemetry, 5, 10});
  run_ms(300);
  const auto telemetry = lines<wire::TelemetryLogRecord>();
  ASSERT_EQ(telemetry.size(), 10u);
  for (size_t i = 0; i < telemetry.size(); ++i) {
    EXPECT_EQ(telemetry[i].line, 5 + i);
    EXPECT_EQ(telemetry[i].phi, 123) << "the estimate at the time";
    EXPECT_EQ(telemetry[i].battery_mv, 12000);
  }
  EXPECT_LT(telemetry[0].time_us, telemetry[9].time_us);

  send(wire::LogDownload{++seq, wire::LogKind::sensor, 0, 0});  // to the end
  run_ms(1000);
  const auto sensor = lines<wire::SensorLogRecord>();
  ASSERT_EQ(sensor.size(), status().sensor_lines);
  EXPECT_EQ(sensor.back().gyro_filtered[2], 12);
  EXPECT_EQ(sensor.back().accel_filtered[0], -20);
  EXPECT_EQ(sensor.back().accel[2], 0);
}

TEST_F(FlightLogTest, DownloadOfLinesThatDoNotExistIsRefused) {
  send(wire::LogDownload{++seq, wire::LogKind::sensor, 0, 0});
  run_ms(5);
  ASSERT_EQ(got<wire::Nack>().size(), 1u);
  EXPECT_EQ(got<wire::Nack>()[0].reason, wire::NackReason::bad_value);
}

TEST_F(FlightLogTest, ResentPartsGoOutBeforeTheStreamGoesOnWhereItWas) {
  send(wire::LogStart{++seq, wire::kLogSensor | wire::kLogTelemetry});
  run_ms(600);
  send(wire::LogStop{++seq});
  run_ms(20);
  ASSERT_GT(status().telemetry_lines, 20);
  send(wire::LogDownload{++seq, wire::LogKind::telemetry, 0, 0});
  run_ms(10);  // the stream is under way
  const size_t before = got<wire::TelemetryLogPart>().size();
  wire::LogResend again{++seq, wire::LogKind::telemetry, 2, {}};
  again.want(3);      // line 2, part 3
  again.want(7 + 6);  // line 3, part 6
  send(again);
  run_ms(300);
  const auto parts = got<wire::TelemetryLogPart>();
  ASSERT_GT(parts.size(), before + 2);
  // Right after the ack: the two parts asked for, then the stream on from where it was.
  size_t first = before;
  while (first < parts.size() && !(parts[first].line == 2 && parts[first].part == 3)) ++first;
  ASSERT_LT(first + 2, parts.size()) << "line 2 part 3 was sent again";
  EXPECT_EQ(parts[first + 1].line, 3);
  EXPECT_EQ(parts[first + 1].part, 6);
  const wire::TelemetryLogPart& next = parts[first + 2];
  const wire::TelemetryLogPart& last = parts[first - 1];
  EXPECT_EQ(uint32_t{next.line} * 7 + next.part, uint32_t{last.line} * 7 + last.part + 1u) << "the stream went on";
  run_ms(2000);
  std::set<uint32_t> seen;
  for (const auto& p : got<wire::TelemetryLogPart>()) seen.insert(uint32_t{p.line} * 7 + p.part);
  EXPECT_EQ(seen.size(), size_t{status().telemetry_lines} * 7) << "and ended whole";
}

TEST_F(FlightLogTest, ResendRequestsBeyondEightOrThePartsAreBusyOrRefused) {
  send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::log_divider), 1});
  send(wire::LogStart{++seq, wire::kLogSensor});
  run_ms(200);
  send(wire::LogResend{++seq, wire::LogKind::sensor, 0, {1, 0, 0, 0, 0}});
  run_ms(5);
  EXPECT_EQ(got<wire::Nack>().back().reason, wire::NackReason::busy) << "while logging";
  send(wire::LogStop{++seq});
  run_ms(20);
  const uint16_t total = status().sensor_lines;
  send(wire::LogResend{++seq, wire::LogKind::sensor, total, {1, 0, 0, 0, 0}});
  run_ms(5);
  EXPECT_EQ(got<wire::Nack>().back().reason, wire::NackReason::bad_value) << "no such line";
  ASSERT_GE(total, 8) << "eight lines to ask for";
  // Nine at once, each for every part of eight lines (40 parts: longer to send than the nine take
  // to arrive): the ninth finds no room.
  for (int i = 0; i < 9; ++i) {
    send(wire::LogResend{++seq, wire::LogKind::sensor, 0, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF}});
  }
  run_ms(20);
  const auto nacks = got<wire::Nack>();
  ASSERT_EQ(nacks.size(), 3u);
  EXPECT_EQ(nacks.back().reason, wire::NackReason::busy);
  EXPECT_EQ(nacks.back().seq, seq);
}

TEST_F(FlightLogTest, AFullLogStopsKeepingLinesAndSaysSo) {
  send(wire::ParamSet{++seq, static_cast<uint8_t>(wire::ParamId::log_divider), 1});
  send(wire::LogStart{++seq, wire::kLogSensor | wire::kLogTelemetry});
  run_ms(8000);  // more lines than the fake board's memory holds
  const wire::LogStatus s = status();
  EXPECT_EQ(s.sensor_lines, s.capacity_lines);
  EXPECT_NE(s.flags & wire::kLogStatusFull, 0);
  EXPECT_NE(got<wire::TelemetryAttitude>().back().flags & wire::kFlagLogFull, 0) << "the pilot sees it";
}

TEST_F(FlightLogTest, WithoutLogMemoryLoggingIsRefused) {
  Firmware without;
  flight = without;
  send(wire::LogStart{++seq, wire::kLogSensor});
  run_ms(5);
  ASSERT_EQ(got<wire::Nack>().size(), 1u);
  EXPECT_EQ(got<wire::Nack>()[0].reason, wire::NackReason::not_supported);
}

}  // namespace
}  // namespace qr
