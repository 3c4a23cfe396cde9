// The console's logic against the scripted fake QR: heartbeat, link state, parameters at connect,
// modes and their refusals, abort and exit, joystick loss, logs, files.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <common/battery_rest.hpp>
#include <common/link_timing.hpp>
#include <common/task_names.hpp>
#include <pc/core/key.hpp>
#include <pc/core/log_room.hpp>
#include <pc/core/task_figures.hpp>
#include <pc/core/telemetry_csv.hpp>

#include "console_bench.hpp"

namespace {

using qrterm::Console;
using qrterm::LinkState;
using qrterm::Severity;

// Defaults and ranges come from the shared table, so retuning the firmware does not break these.
const wire::ParameterSpec& spec_of(wire::ParamId id) { return *wire::find_parameter(static_cast<uint8_t>(id)); }
int32_t default_of(wire::ParamId id) { return spec_of(id).default_value; }
using qrterm_test::Bench;

size_t count_requests(const Bench& b, wire::MessageType type) {
  return static_cast<size_t>(std::count_if(b.qr.requests.begin(), b.qr.requests.end(),
                                           [type](const wire::Frame& f) { return f.type == type; }));
}

void enter_manual(Bench& b) {
  b.connect();
  b.key('2');
  ASSERT_TRUE(b.run_until(
      [&] { return b.console.telemetry().attitude && b.console.telemetry().attitude->mode == wire::Mode::manual; },
      200));
}

TEST(Console, SendsControlAt50HzWhichIsTheHeartbeat) {
  Bench b;
  b.run(1000);
  EXPECT_GE(b.qr.controls_received, 49u);
  EXPECT_LE(b.qr.controls_received, 51u);
}

// The battery row reads the resting voltage the QR's rules judge (docs/safety.md rule 8): the fake
// QR's measured 11.85 V plus the console's battery_sag_mv times the load of the engines it reports.
TEST(Console, TheBatteryRowTakesTheEnginesSagOutWithTheConsolesSagParameter) {
  Console::Setup setup;
  setup.params.set(static_cast<uint8_t>(wire::ParamId::battery_sag_mv), 2000);
  Bench b(setup);
  enter_manual(b);
  for (int i = 0; i < 60; ++i) b.key('a');
  b.run(8000);  // eight of the mean's time constants
  const std::optional<qrterm::BatteryReading> reading = b.console.battery();
  ASSERT_TRUE(reading);
  const uint16_t rested = wire::battery_rested_mv(11850, b.qr.engine, 2000);
  EXPECT_GT(rested, 11850 + 200) << "lift 600: the load counts";
  EXPECT_NEAR(reading->resting_v * 1000, rested, 1);
  EXPECT_EQ(reading->cells, 3);
  EXPECT_NEAR(reading->percent, qrterm::lipo_charge_percent(rested / 3000.0), 0.05);
}

TEST(Console, LinkWaitsThenComesUpWithTheFirstFrame) {
  Bench b;
  b.qr.telemetry = false;
  b.run(100);
  EXPECT_EQ(b.console.link_state(), LinkState::waiting);
  b.qr.telemetry = true;
  b.run(50);
  EXPECT_EQ(b.console.link_state(), LinkState::up);
  EXPECT_TRUE(b.logged("link up"));
}

TEST(Console, LinkLostAfterTwoSecondsWithoutAValidFrameAndBackAfter) {
  Bench b;
  b.connect();
  b.qr.silent = true;
  b.run(qrterm::kLinkLostAfterMs - 50);
  EXPECT_EQ(b.console.link_state(), LinkState::up);
  b.run(100);
  EXPECT_EQ(b.console.link_state(), LinkState::lost);
  const qrterm::LogLine* line = b.log.find_last("LINK LOST");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->severity, Severity::error);
  b.qr.silent = false;
  b.run(50);
  EXPECT_EQ(b.console.link_state(), LinkState::up);
  EXPECT_TRUE(b.logged("link back"));
}

TEST(Console, GarbageIsNoSignOfLife) {
  Bench b;
  b.connect();
  b.qr.silent = true;
  const uint8_t noise[] = {0x4D, 0x88, 1, 2, 3, 4, 5, 6, 7, 8, 9, 0};  // a frame start with a bad check
  for (int i = 0; i < 30; ++i) {
    b.run(100);
    b.console.receive(noise, sizeof noise, b.now);
  }
  EXPECT_EQ(b.console.link_state(), LinkState::lost);
  EXPECT_GT(b.console.link().counters().check_failures, 0u);
}

TEST(Console, ClosedLineIsLinkLostAtOnce) {
  Bench b;
  b.connect();
  b.console.line_closed("simulator exited with status 1", b.now);
  EXPECT_EQ(b.console.link_state(), LinkState::closed);
  EXPECT_TRUE(b.logged("LINK LOST: simulator exited with status 1"));
}

TEST(Console, ALineClosedInFlightSaysTheQrPanicsByItselfAndAbortDoesNotPretend) {
  Bench b;
  enter_manual(b);
  b.console.line_closed("/dev/pts/9 was closed at the other end", b.now);
  b.console.line_closed("simulator killed by signal 9 (Killed)", b.now);
  EXPECT_TRUE(
      b.logged("LINK LOST: /dev/pts/9 was closed at the other end; the QR was in manual: it panics by itself "
               "after the link timeout (safety rule 7)"));
  EXPECT_TRUE(b.logged("and: simulator killed by signal 9 (Killed)"));
  b.key(qrterm::kKeyEscape);
  EXPECT_TRUE(b.logged("ABORT (ESC): the line is gone, nothing can be sent"));
  EXPECT_FALSE(b.logged("panic requested"));
}

TEST(Console, SendsEveryParameterAtConnectOneAtATime) {
  Console::Setup setup;
  setup.params.set(static_cast<uint8_t>(wire::ParamId::roll_pitch_p1), 1088);
  setup.params.set(static_cast<uint8_t>(wire::ParamId::attitude_c2), 5000);
  Bench b(setup);
  b.qr.telemetry = false;
  b.run(100);
  EXPECT_EQ(count_requests(b, wire::MessageType::param_set), 0u) << "nothing before the link is up";
  b.qr.telemetry = true;
  b.connect();
  EXPECT_EQ(count_requests(b, wire::MessageType::param_set), wire::kParameterCount);
  EXPECT_EQ(b.qr.params.get(wire::ParamId::roll_pitch_p1), 1088);
  EXPECT_EQ(b.qr.params.get(wire::ParamId::attitude_c2), 5000);
  EXPECT_EQ(b.console.reported(wire::ParamId::roll_pitch_p1), 1088) << "the QR's report is what the screen shows";
  EXPECT_EQ(b.console.parameters_to_send(), 0u);
}

TEST(Console, ParametersAreReadBackAfterAnUpload) {
  Bench b;
  b.qr.report_after_set = false;
  b.connect();
  EXPECT_EQ(count_requests(b, wire::MessageType::param_get), 1u);
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    EXPECT_EQ(b.console.reported(spec.id), spec.default_value) << spec.name;
  }
  b.key('i');
  b.run(100);
  EXPECT_EQ(count_requests(b, wire::MessageType::param_get), 2u);
  EXPECT_EQ(b.console.reported(wire::ParamId::roll_pitch_p1),
            default_of(wire::ParamId::roll_pitch_p1) + 64);  // +0.25 in Q8
  EXPECT_FALSE(b.logged("the QR has"));
}

TEST(Console, AValueTheQrDoesNotHoldIsAWarning) {
  Bench b;
  b.connect();
  b.qr.params.set(static_cast<uint8_t>(wire::ParamId::roll_pitch_p2), 480);  // the QR changed it by itself
  b.key('p');
  b.run(50);
  const int32_t console_p2 = default_of(wire::ParamId::roll_pitch_p2) / 16;  // Q4, a whole number
  const qrterm::LogLine* line = b.log.find_last("the QR has roll_pitch_p2 = 30, the console " +
                                                std::to_string(console_p2));
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->severity, Severity::warning);
}

// A gyro scale measurement (docs/signal-chain.md): the QR writes the scale and ends the turns; the
// console keeps both as its own values, so they are saved and what goes up at the next connect
// is the measurement, not the file's old scale and not the turns again.
TEST(Console, AValueTheQrWritesItselfBecomesTheConsoles) {
  Console::Setup setup;
  setup.params.set(static_cast<uint8_t>(wire::ParamId::gyro_turns), 2);
  Bench b(setup);
  b.connect();
  ASSERT_EQ(b.qr.params.get(wire::ParamId::gyro_turns), 2);
  b.qr.params.set(static_cast<uint8_t>(wire::ParamId::gyro_scale_z_ppm), 23456);  // the turns measured
  b.qr.params.set(static_cast<uint8_t>(wire::ParamId::gyro_turns), 0);
  b.key('p');
  b.run(50);
  EXPECT_EQ(b.console.params().get(wire::ParamId::gyro_scale_z_ppm), 23456);
  EXPECT_EQ(b.console.params().get(wire::ParamId::gyro_turns), 0);
  const qrterm::LogLine* line = b.log.find_last("the QR set gyro_scale_z_ppm = 23456, and so does the console");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->severity, Severity::info);
  EXPECT_FALSE(b.logged("the QR has gyro"));
}

TEST(Console, ParametersGoUpAgainWhenTheLinkComesBack) {
  Bench b;
  b.connect();
  b.qr.params = wire::ParameterValues{};
  b.qr.params.set(static_cast<uint8_t>(wire::ParamId::yaw_p), 0);  // "restarted" with other values
  b.qr.silent = true;
  b.run(qrterm::kLinkLostAfterMs + 10);
  b.qr.silent = false;
  b.run(600);
  EXPECT_EQ(b.qr.params.get(wire::ParamId::yaw_p), wire::ParameterValues{}.get(wire::ParamId::yaw_p));
  EXPECT_EQ(count_requests(b, wire::MessageType::param_set), 2 * wire::kParameterCount);
}

TEST(Console, ModeKeyWithNeutralControlsEntersManual) {
  Bench b;
  enter_manual(b);
  EXPECT_EQ(b.qr.mode, wire::Mode::manual);
  EXPECT_TRUE(b.logged("QR mode: manual"));
}

TEST(Console, LiftKeysRaiseTheEnginesInManual) {
  Bench b;
  enter_manual(b);
  for (int i = 0; i < 30; ++i) b.key('a');
  b.run(200);
  EXPECT_EQ(b.qr.control.lift, 30 * qrterm::kLiftTrimStep);
  ASSERT_TRUE(b.console.telemetry().engines);
  EXPECT_EQ(b.console.telemetry().engines->engine[0], 300);
  b.key('z');
  b.run(100);
  EXPECT_EQ(b.qr.control.lift, 29 * qrterm::kLiftTrimStep);
}

TEST(Console, RefusesToLeaveSafeWithTrimsAndSaysWhy) {
  Bench b;
  b.connect();
  b.keys("a2");
  b.run(100);
  EXPECT_EQ(count_requests(b, wire::MessageType::mode_change), 0u);
  const qrterm::LogLine* line = b.log.find_last("not asking for manual");
  ASSERT_NE(line, nullptr);
  EXPECT_NE(line->text.find("trims"), std::string::npos);
  EXPECT_EQ(line->severity, Severity::warning);
  b.keys("c2");
  b.run(100);
  EXPECT_EQ(b.qr.mode, wire::Mode::manual);
}

TEST(Console, RefusesToFlyWithAJoystickNotNeutralOrNotYetHeard) {
  Console::Setup setup;
  setup.joystick = true;
  Bench b(setup);
  b.connect();
  b.key('2');
  EXPECT_TRUE(b.logged("has not reported its position"));
  b.console.joystick_moved({120, 0, 0, 0}, true, b.now);
  b.key('2');
  EXPECT_TRUE(b.logged("joystick throttle not at zero"));
  b.console.joystick_moved({0, 0, 300, 0}, true, b.now);
  b.key('2');
  EXPECT_TRUE(b.logged("stick or twist not centred"));
  b.run(50);
  EXPECT_EQ(count_requests(b, wire::MessageType::mode_change), 0u);
  b.console.joystick_moved({0, 0, 0, 0}, true, b.now);
  b.key('2');
  b.run(100);
  EXPECT_EQ(b.qr.mode, wire::Mode::manual);
}

TEST(Console, TrimsAddToTheJoystick) {
  Console::Setup setup;
  setup.joystick = true;
  Bench b(setup);
  b.console.joystick_moved({400, 100, -50, 0}, true, b.now);
  b.keys("aa");
  b.key(qrterm::kKeyRight);
  b.key(qrterm::kKeyUp);
  b.key('w');
  b.run(30);
  EXPECT_EQ(b.qr.control.lift, 420);
  EXPECT_EQ(b.qr.control.roll, 110);
  EXPECT_EQ(b.qr.control.pitch, -60);
  EXPECT_EQ(b.qr.control.yaw, 10);
}

TEST(Console, QrRefusalIsShownWithItsReason) {
  Bench b;
  b.connect();
  b.key('4');  // yaw control before a calibration
  b.run(100);
  const qrterm::LogLine* line = b.log.find_last("QR refused mode yaw control");
  ASSERT_NE(line, nullptr);
  EXPECT_NE(line->text.find("sensors not calibrated"), std::string::npos);
}

// A sensor fault as the firmware tells it (qr/core/sensor_fault_report.hpp: which sensor, which
// kind, how many) is a QR line in the log, and the refusal it causes shows its reason.
TEST(Console, ASensorFaultAndTheRefusalItCausesAreShown) {
  Bench b;
  b.connect();
  b.qr.say("imu fault: wrong identity (19 since power-up)\n");
  b.qr.refuse_leaving_safe = wire::NackReason::imu_fault;
  b.key('3');  // calibration
  b.run(100);
  const qrterm::LogLine* fault = b.log.find_last("imu fault:");
  ASSERT_NE(fault, nullptr);
  EXPECT_EQ(fault->text, "imu fault: wrong identity (19 since power-up)");
  EXPECT_EQ(fault->severity, Severity::qr);
  const qrterm::LogLine* refusal = b.log.find_last("QR refused mode calibration");
  ASSERT_NE(refusal, nullptr);
  EXPECT_NE(refusal->text.find("the IMU is not healthy"), std::string::npos) << refusal->text;
}

TEST(Console, CalibrationThenYawControl) {
  Bench b;
  b.connect();
  b.key('3');
  ASSERT_TRUE(b.run_until([&] { return b.console.telemetry().flag(wire::kFlagCalibrated); }, 1000));
  EXPECT_TRUE(b.logged("QR calibrated"));
  b.run(50);
  b.key('4');
  b.run(100);
  EXPECT_EQ(b.qr.mode, wire::Mode::yaw_control);
}

// The last mode the console asked for, as the QR received it.
wire::Mode last_mode_request(const Bench& b) {
  wire::Mode mode = wire::Mode::safe;
  for (const wire::Frame& f : b.qr.requests) {
    wire::ModeChange m;
    if (f.type == wire::MessageType::mode_change && wire::decode(f, m)) mode = m.mode;
  }
  return mode;
}

// 7 is IN4073's height mode key: a toggle, which way by the mode the QR reports.
TEST(Console, HeightHoldKeyToggles) {
  Bench b;
  b.connect();
  b.key('3');
  ASSERT_TRUE(b.run_until([&] { return b.console.telemetry().flag(wire::kFlagCalibrated); }, 1000));
  b.run(50);
  b.key('5');
  b.run(100);
  ASSERT_EQ(b.qr.mode, wire::Mode::full_control);
  b.key('7');
  b.run(50);
  EXPECT_EQ(last_mode_request(b), wire::Mode::height_hold) << "full control: 7 asks for height hold";
  b.qr.mode = wire::Mode::height_hold;  // as the firmware would, flying
  ASSERT_TRUE(b.run_until(
      [&] { return b.console.telemetry().attitude && b.console.telemetry().attitude->mode == wire::Mode::height_hold; },
      200));
  b.key('7');
  b.run(50);
  EXPECT_EQ(last_mode_request(b), wire::Mode::full_control) << "height hold: 7 asks for full control";
}

TEST(Console, EscapePanicsAndTheQrSettlesInSafe) {
  Bench b;
  enter_manual(b);
  b.keys("aaaaa");
  b.run(100);
  b.key(qrterm::kKeyEscape);
  b.run(50);
  EXPECT_EQ(b.qr.mode, wire::Mode::panic);
  EXPECT_TRUE(b.logged("ABORT (ESC): panic requested, trims centred"));
  EXPECT_TRUE(b.logged("QR mode: panic: asked by the pilot (ESC)"));
  EXPECT_EQ(b.console.controls().trims(), qrterm::Sticks{}) << "ready to leave safe again";
  EXPECT_TRUE(b.run_until([&] { return b.console.telemetry().attitude->mode == wire::Mode::safe; }, 1500));
  EXPECT_FALSE(b.console.finished());
}

// 0 in flight logged "mode: panic (requested)", the QR's words for a request, which name no key:
// the console's line says what the pilot did (the QR's own line stays as the QR sent it). A panic
// the QR enters by its own rules names nobody.
TEST(Console, APanicThePilotAskedForSaysWhichKey) {
  Bench b;
  enter_manual(b);
  b.keys("aaaaa");
  b.run(100);
  b.key('0');
  b.run(50);
  EXPECT_EQ(b.qr.mode, wire::Mode::panic);
  EXPECT_TRUE(b.logged("QR mode: panic: asked by the pilot (key 0, safe from flight goes through panic)"));
  ASSERT_TRUE(b.run_until([&] { return b.console.telemetry().attitude->mode == wire::Mode::safe; }, 1500));

  b.key('c');  // the lift trim back to zero: leaving safe needs it
  enter_manual(b);
  ASSERT_EQ(b.qr.mode, wire::Mode::manual);
  b.keys("aaaaa");
  b.run(qrterm::kPanicAskedMs + 100);
  b.cut = true;  // the QR's own rule: its link watchdog
  b.run(qrterm_test::FakeQr::kLinkTimeoutMs + 50);
  ASSERT_EQ(b.qr.mode, wire::Mode::panic);
  b.cut = false;
  b.run(50);
  const qrterm::LogLine* line = b.log.find_last("QR mode: panic");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->text, "QR mode: panic") << "nobody here asked";
}

TEST(Console, SecondEscapeInARowExitsAfterTheQrConfirms) {
  Bench b;
  enter_manual(b);
  b.key(qrterm::kKeyEscape);
  b.key(qrterm::kKeyEscape);
  EXPECT_TRUE(b.console.exiting());
  EXPECT_TRUE(b.run_until([&] { return b.console.finished(); }, 100));
  EXPECT_TRUE(b.console.exit_confirmed());
  EXPECT_TRUE(b.qr.exited);
}

TEST(Console, EscapeThenAnotherKeyDisarmsTheExit) {
  Bench b;
  b.connect();
  b.key(qrterm::kKeyEscape);
  b.key('c');
  b.key(qrterm::kKeyEscape);
  b.run(50);
  EXPECT_FALSE(b.console.exiting());
}

TEST(Console, ExitWaitsForTheConfirmationAtMostItsBound) {
  Bench b;
  b.connect();
  b.qr.answer_requests = false;
  const uint32_t start = b.now;
  b.key('x');
  ASSERT_TRUE(b.run_until([&] { return b.console.finished(); }, 3000));
  EXPECT_FALSE(b.console.exit_confirmed());
  EXPECT_LE(b.now - start, qrterm::kExitWaitMs);
  EXPECT_EQ(count_requests(b, wire::MessageType::exit), wire::kMaxSends);
  EXPECT_TRUE(b.logged("no answer from the QR to the exit"));
}

TEST(Console, ExitWithoutAQrFinishesAtOnce) {
  Bench b;
  b.qr.silent = true;
  b.run(100);
  b.key('x');
  EXPECT_TRUE(b.console.finished());
  EXPECT_TRUE(b.logged("no QR to tell"));
}

TEST(Console, SecondExitRequestDoesNotWait) {
  Bench b;
  b.connect();
  b.qr.answer_requests = false;
  b.console.request_exit(b.now);
  b.run(10);
  b.console.request_exit(b.now);
  EXPECT_TRUE(b.console.finished());
}

TEST(Console, UnansweredRequestGivesUpAfterTenSendsAndSaysSo) {
  Bench b;
  b.connect();
  b.qr.answer_requests = false;
  b.key('0');
  b.run(wire::kGiveUpAfterMs + 50);
  EXPECT_EQ(count_requests(b, wire::MessageType::mode_change), wire::kMaxSends);
  const qrterm::LogLine* line = b.log.find_last("no answer from the QR to the mode change");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->severity, Severity::error);
  EXPECT_EQ(b.console.link().figures().gave_up, 1u);
  EXPECT_EQ(b.console.link().figures().resends, wire::kMaxSends - 1u);
}

TEST(Console, LostAnswerIsResentAndAppliedOnce) {
  Bench b;
  b.connect();
  const uint32_t applied = b.qr.requests_applied;
  b.key('2');
  // The request gets through; its answer is lost, so the console sends it again.
  b.console.tick(++b.now);
  b.qr.receive(b.console.output(), b.now);
  b.console.output().clear();
  b.qr.take_output();
  b.run(300);
  EXPECT_GE(count_requests(b, wire::MessageType::mode_change), 2u);
  EXPECT_EQ(b.qr.requests_applied, applied + 1);
  EXPECT_FALSE(b.console.link().pending(wire::MessageType::mode_change));
  EXPECT_EQ(b.qr.mode, wire::Mode::manual);
}

TEST(Console, RoundTripIsMeasuredOnFirstSends) {
  Bench b;
  b.connect();
  EXPECT_GE(b.console.link().figures().round_trip_ms, 0);
  EXPECT_LE(b.console.link().figures().round_trip_ms, 2);
}

TEST(Console, FramesPerSecondCountsValidFrames) {
  Bench b;
  b.run(2100);
  // Per 20 ms the fake sends attitude, rates and one slow group: 150 frames a second.
  EXPECT_GE(b.console.link().figures().frames_per_s, 140u);
  EXPECT_LE(b.console.link().figures().frames_per_s, 160u);
}

TEST(Console, JoystickLostInFlightPanics) {
  Console::Setup setup;
  setup.joystick = true;
  Bench b(setup);
  b.console.joystick_moved({}, true, b.now);
  enter_manual(b);
  b.console.joystick_lost(b.now);
  b.run(50);
  EXPECT_EQ(b.qr.mode, wire::Mode::panic);
  EXPECT_TRUE(b.logged("ABORT (joystick lost)"));
  EXPECT_EQ(b.console.joystick_state(), qrterm::JoystickState::lost);
  b.run(1200);
  b.key('2');
  EXPECT_TRUE(b.logged("the joystick is gone"));
}

TEST(Console, JoystickLostInSafeOnlyWarns) {
  Console::Setup setup;
  setup.joystick = true;
  Bench b(setup);
  b.console.joystick_moved({}, true, b.now);
  b.connect();
  b.console.joystick_lost(b.now);
  b.run(50);
  EXPECT_EQ(count_requests(b, wire::MessageType::mode_change), 0u);
  EXPECT_TRUE(b.logged("joystick lost"));
  b.console.joystick_back(b.now);
  EXPECT_EQ(b.console.joystick_state(), qrterm::JoystickState::ok);
  EXPECT_FALSE(b.console.joystick_position_known());
}

TEST(Console, JoystickFireAborts) {
  Console::Setup setup;
  setup.joystick = true;
  Bench b(setup);
  b.console.joystick_moved({}, true, b.now);
  enter_manual(b);
  b.console.joystick_fire(b.now);
  b.run(50);
  EXPECT_EQ(b.qr.mode, wire::Mode::panic);
}

TEST(Console, QrDebugTextBecomesCyanLines) {
  Bench b;
  b.connect();
  b.qr.say("hello from the QR, a long line\nsecond");
  b.run(5);
  const qrterm::LogLine* line = b.log.find_last("hello from the QR");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->text, "hello from the QR, a long line");
  EXPECT_EQ(line->severity, Severity::qr);
  EXPECT_FALSE(b.logged("second")) << "an unfinished line waits for its end";
}

TEST(Console, GainKeysStepTheParameterAndSendIt) {
  Bench b;
  b.connect();
  b.keys("uuj");
  b.run(100);
  EXPECT_EQ(b.qr.params.get(wire::ParamId::yaw_p), default_of(wire::ParamId::yaw_p) + 80);  // +5 +5 -5 in Q4
  b.keys("e");
  b.run(100);
  EXPECT_EQ(b.qr.params.get(wire::ParamId::attitude_c1),
            std::min(2 * default_of(wire::ParamId::attitude_c1), spec_of(wire::ParamId::attitude_c1).max));
  b.keys("ff");
  b.run(100);
  const int32_t c2 = default_of(wire::ParamId::attitude_c2) / 4;
  EXPECT_EQ(b.qr.params.get(wire::ParamId::attitude_c2), c2);
  b.run(qrterm::kStepsSettleMs);
  EXPECT_TRUE(b.logged("attitude_c2 = " + std::to_string(c2)));
}

// 30 presses of a gain key were 30 log lines: a burst of steps of one gain is one line, written
// when the steps stop for a second, when another gain is stepped, or when another key comes; every
// step still goes to the QR at once.
TEST(Console, ABurstOfGainStepsIsOneLogLine) {
  Bench b;
  b.connect();
  const auto lines_naming = [&](const std::string& what) {
    size_t n = 0;
    for (const qrterm::LogLine& line : b.log.lines()) n += line.text.find(what) != std::string::npos ? 1 : 0;
    return n;
  };
  for (int i = 0; i < 30; ++i) {
    b.key('u');
    b.run(50);  // a key held: its repeats 50 ms apart
  }
  EXPECT_EQ(lines_naming("yaw_p"), 0u) << "nothing while the steps go on";
  EXPECT_EQ(b.qr.params.get(wire::ParamId::yaw_p), default_of(wire::ParamId::yaw_p) + 30 * 80) << "each one sent";
  b.run(qrterm::kStepsSettleMs);
  EXPECT_EQ(lines_naming("yaw_p"), 1u);
  EXPECT_TRUE(b.logged("yaw_p = 450 (300 -> 450 in 30 steps)"));

  // Another gain's key ends the burst at once, and so does any other key.
  b.keys("ii");
  b.key('o');
  EXPECT_TRUE(b.logged("roll_pitch_p1 = 6 (5.5 -> 6 in 2 steps)"));
  b.key('c');
  EXPECT_TRUE(b.logged("roll_pitch_p2 = 222.5")) << "one step: the value alone, as before";
  EXPECT_EQ(lines_naming("roll_pitch_p2"), 1u);
}

TEST(Console, GainAtTheEndOfItsRangeStaysAndSaysSo) {
  Console::Setup setup;
  setup.params.set(static_cast<uint8_t>(wire::ParamId::roll_pitch_p1), 0);
  Bench b(setup);
  b.connect();
  b.key('k');
  EXPECT_EQ(b.console.params().get(wire::ParamId::roll_pitch_p1), 0);
  EXPECT_TRUE(b.logged("end of its range"));
}

TEST(Console, ReadsParametersBack) {
  Bench b;
  b.connect();
  b.qr.params.set(static_cast<uint8_t>(wire::ParamId::idle_level), 200);
  b.key('p');
  b.run(50);
  EXPECT_EQ(b.console.reported(wire::ParamId::idle_level), 200);
  // p says what came back (it used to say nothing): here the QR differs in the one it was given.
  EXPECT_TRUE(b.run_until([&] { return b.logged("parameters read back"); }, 500));
  EXPECT_TRUE(b.logged("parameters read back: the QR differs in idle_level"));
}

TEST(Console, ReadBackThatMatchesSaysSo) {
  Bench b;
  b.connect();
  b.run(200);
  b.key('p');
  EXPECT_TRUE(b.run_until([&] { return b.logged("parameters read back"); }, 500));
  EXPECT_TRUE(b.logged("parameters read back: the QR has the console's values"));
}

TEST(Console, LogStartAndStopAreAcknowledged) {
  Bench b;
  b.connect();
  b.key('s');
  b.run(50);
  EXPECT_TRUE(b.qr.logging);
  EXPECT_TRUE(b.console.telemetry().flag(wire::kFlagLogging));
  b.key('t');
  b.run(50);
  EXPECT_FALSE(b.qr.logging);
  EXPECT_TRUE(b.logged("QR logs stopped"));
}

TEST(Console, AStartThatWouldDropTheQrsLinesAsksForASecondPress) {
  Bench b;
  b.connect();
  b.qr.sensor_log[0] = wire::SensorLogRecord{};
  b.qr.telemetry_log[0] = wire::TelemetryLogRecord{};
  b.run(200);  // a log_status with a line in each log
  const auto starts = [&b] {
    return std::count_if(b.qr.requests.begin(), b.qr.requests.end(),
                         [](const wire::Frame& f) { return f.type == wire::MessageType::log_start; });
  };
  b.key('s');
  b.run(50);
  EXPECT_EQ(starts(), 0) << "one s does not empty a log that holds lines";
  EXPECT_TRUE(b.logged("the QR's log holds 1 lines"));
  b.run(qrterm::kLogRestartConfirmMs + 100);
  b.key('s');
  b.run(50);
  EXPECT_EQ(starts(), 0) << "a second s after the time asks again";
  b.key('s');
  b.run(50);
  EXPECT_EQ(starts(), 1) << "s twice within the time starts";
  EXPECT_TRUE(b.qr.logging);
}

wire::SensorLogRecord sensor_line(uint16_t line) {
  wire::SensorLogRecord r;
  r.line = line;
  r.time_us = 1000u * line;
  r.gyro[0] = static_cast<int16_t>(-line);
  r.battery_mv = 11850;
  return r;
}

TEST(Console, LogDownloadWritesBothLogsAsCsvAndAsksAgainForLostLines) {
  Bench b;
  b.connect();
  for (uint16_t line = 0; line < 40; ++line) b.qr.sensor_log[line] = sensor_line(line);
  wire::TelemetryLogRecord t;
  t.mode = wire::Mode::manual;
  t.engine[2] = 400;
  b.qr.telemetry_log[0] = t;
  int dropped = 0;
  b.qr.drop_log_part = [&dropped](uint16_t line, uint8_t part) {
    return (line == 7 || line == 8) && part == 2 && dropped++ < 2;
  };
  b.run(200);  // a log_status with the new line counts
  b.key('g');
  ASSERT_TRUE(b.run_until(
      [&] { return b.written.count("telemetry_log_1.csv") != 0 && !b.console.download_status().size(); }, 10000));
  const std::string& sensor = b.written["sensor_log_1.csv"];
  EXPECT_EQ(std::count(sensor.begin(), sensor.end(), '\n'), 41) << sensor;
  EXPECT_EQ(sensor.rfind("line,time_us,gyro_x", 0), 0u);
  EXPECT_NE(sensor.find("\r\n7,7000,-7,"), std::string::npos);
  EXPECT_NE(sensor.find("\r\n8,8000,-8,"), std::string::npos);
  // Part 2 of lines 7 and 8, by part: bits 2 and 5 + 2 of a log_resend from line 7.
  const auto again = std::find_if(b.qr.requests.begin(), b.qr.requests.end(), [](const wire::Frame& f) {
    wire::LogResend r;
    if (!wire::decode(f, r) || r.log != wire::LogKind::sensor || r.first_line != 7) return false;
    for (size_t bit = 0; bit < wire::kLogResendMaskBytes * 8; ++bit) {
      if (r.wants(bit) != (bit == 2 || bit == 7)) return false;
    }
    return true;
  });
  EXPECT_NE(again, b.qr.requests.end()) << "part 2 of lines 7 and 8 asked for again";
  EXPECT_EQ(count_requests(b, wire::MessageType::log_download), 2u) << "each log streamed once";
  const std::string& telemetry = b.written["telemetry_log_1.csv"];
  EXPECT_NE(telemetry.find("\r\n0,0,2,0,"), std::string::npos) << telemetry;
  EXPECT_TRUE(b.logged("sensor log: 40 lines -> sensor_log_1.csv"));
}

TEST(Console, LogDownloadShowsLinesPercentAndTimeLeft) {
  Bench b;
  b.connect();
  for (uint16_t line = 0; line < 400; ++line) b.qr.sensor_log[line] = sensor_line(line);
  b.run(200);
  // Line 300 on is lost the first time: the download stops there for a while.
  int dropped = 0;
  b.qr.drop_log_part = [&dropped](uint16_t line, uint8_t) { return line >= 300 && dropped++ < 500; };
  b.key('g');
  ASSERT_TRUE(b.run_until([&] { return b.console.download_status().find("sensor log: 300 of 400") == 0; }, 5000))
      << b.console.download_status();
  const std::string status = b.console.download_status();
  EXPECT_NE(status.find("lines, 75 %, "), std::string::npos) << status;
  EXPECT_NE(status.find(" s left"), std::string::npos) << status;
}

TEST(Console, EmptyLogsAreNotDownloaded) {
  Bench b;
  b.connect();
  b.key('g');
  b.run(100);
  EXPECT_TRUE(b.logged("the QR's logs are empty (s starts logging)"));
  EXPECT_EQ(count_requests(b, wire::MessageType::log_download), 0u);
}

TEST(Console, OnlyTheLogWithLinesIsDownloaded) {
  Bench b;
  b.connect();
  wire::TelemetryLogRecord t;
  for (uint16_t line = 0; line < 5; ++line) {
    t.line = line;
    b.qr.telemetry_log[line] = t;
  }
  b.run(200);  // a log_status with the new line counts
  b.key('g');
  ASSERT_TRUE(b.run_until([&] { return b.console.download_status().empty(); }, 3000));
  EXPECT_EQ(b.written.count("sensor_log_1.csv"), 0u);
  EXPECT_EQ(std::count(b.written["telemetry_log_1.csv"].begin(), b.written["telemetry_log_1.csv"].end(), '\n'), 6);
}

TEST(Console, LogDownloadGivesUpWhenNothingComes) {
  Bench b;
  b.connect();
  for (uint16_t line = 0; line < 10; ++line) b.qr.sensor_log[line] = sensor_line(line);
  b.run(200);
  b.qr.drop_log_part = [](uint16_t, uint8_t) { return true; };
  b.key('g');
  b.run(qrterm::LogDownloader::kGiveUpMs + 100);
  EXPECT_TRUE(b.logged("no new line for 5 s, given up at sensor log: 0 of 10 lines"));
  EXPECT_EQ(b.console.download_status(), "");
  EXPECT_GE(count_requests(b, wire::MessageType::log_resend), 5u) << "asked again while waiting";
}

TEST(Console, QrRefusalOfADownloadSaysWhatToDo) {
  Bench b;
  b.connect();
  for (uint16_t line = 0; line < 10; ++line) b.qr.sensor_log[line] = sensor_line(line);
  b.run(200);
  b.qr.logging = true;  // started by someone else: the console's status is a moment old
  b.key('g');
  b.run(50);
  EXPECT_TRUE(b.logged("log download refused: busy, try again later (the QR is logging: stop the logs first, key t)"));
  EXPECT_EQ(b.console.download_status(), "");
}

TEST(Console, FullLogIsAWarning) {
  Bench b;
  b.connect();
  const wire::FrameBytes frame = wire::encode(wire::LogStatus{wire::kLogStatusFull, 2340, 2340, 2340});
  b.console.receive(frame.bytes, frame.size, b.now);
  EXPECT_TRUE(b.logged("QR log full (2340 lines)"));
}

TEST(Console, LogDownloadWhileLoggingIsRefusedWithWhatToDo) {
  Bench b;
  b.connect();
  b.key('s');
  b.run(100);
  b.key('g');
  EXPECT_TRUE(b.logged("stop the logs first"));
  EXPECT_EQ(b.console.download_status(), "");
}

// The log folder under faults: nothing half-written passes for whole, the pilot is told, and the
// console flies on (the abort key still works).
TEST(Console, ADownloadOntoAFullDiskIsNamedPartialNeverWhole) {
  Bench b;
  b.connect();
  for (uint16_t line = 0; line < 40; ++line) b.qr.sensor_log[line] = sensor_line(line);
  b.run(200);
  b.disk_room = 600;  // the header and a few lines
  b.key('g');
  ASSERT_TRUE(b.run_until([&] { return b.console.download_status().empty(); }, 10000));
  EXPECT_EQ(b.written.count("sensor_log_1.csv"), 0u) << "a cut-short file must not have the whole file's name";
  ASSERT_EQ(b.written.count("sensor_log_1.partial.csv"), 1u);
  EXPECT_LE(b.written["sensor_log_1.partial.csv"].size(), 600u);
  const qrterm::LogLine* line = b.log.find_last("sensor log: writing sensor_log_1.partial.csv failed after ");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->severity, Severity::error);
  EXPECT_NE(line->text.find("of 40 lines (disk full or log folder read-only): the file is partial"), std::string::npos)
      << line->text;
}

TEST(Console, ADownloadIntoAReadOnlyFolderSaysItWasNotSaved) {
  Bench b;
  b.connect();
  for (uint16_t line = 0; line < 10; ++line) b.qr.sensor_log[line] = sensor_line(line);
  b.run(200);
  b.folder_read_only = true;
  b.key('g');
  ASSERT_TRUE(b.run_until([&] { return b.console.download_status().empty(); }, 10000));
  EXPECT_TRUE(b.written.empty());
  EXPECT_TRUE(
      b.logged("sensor log not saved: cannot create sensor_log_1.partial.csv (log folder read-only or disk full)"));
}

TEST(Console, AWholeDownloadIsWrittenPartialThenRenamed) {
  Bench b;
  b.connect();
  for (uint16_t line = 0; line < 10; ++line) b.qr.sensor_log[line] = sensor_line(line);
  b.run(200);
  b.key('g');
  ASSERT_TRUE(b.run_until([&] { return b.console.download_status().empty(); }, 10000));
  ASSERT_EQ(b.renamed.size(), 1u);
  EXPECT_EQ(b.renamed[0], std::make_pair(std::string("sensor_log_1.partial.csv"), std::string("sensor_log_1.csv")));
  EXPECT_EQ(b.written.count("sensor_log_1.partial.csv"), 0u);
}

TEST(Console, TelemetryCsvCutShortIsNamedPartialAndTheAbortKeyStillWorks) {
  Bench b;
  enter_manual(b);
  b.telemetry_csv.setstate(std::ios::badbit);  // the disk filled up under it
  b.run(100);
  const qrterm::LogLine* line = b.log.find_last(
      "cannot write telemetry.csv (disk full or log folder read-only): it ends here, renamed telemetry.partial.csv");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->severity, Severity::error);
  EXPECT_EQ(b.renamed, (std::vector<std::pair<std::string, std::string>>{{"telemetry.csv", "telemetry.partial.csv"}}));
  b.run(500);
  EXPECT_EQ(b.renamed.size(), 1u) << "said and renamed once";
  b.key(qrterm::kKeyEscape);
  b.run(50);
  EXPECT_EQ(b.qr.mode, wire::Mode::panic);
}

TEST(Console, HexLogCutShortIsNamedPartial) {
  Bench b;
  b.connect();
  b.hex.setstate(std::ios::badbit);
  b.run(100);
  EXPECT_TRUE(
      b.logged("cannot write rx.hex (disk full or log folder read-only): it ends here, renamed rx.partial.hex"));
}

TEST(Console, TelemetryCsvGetsARowPerAttitudeFrame) {
  Bench b;
  b.run(1000);
  const std::string csv = b.telemetry_csv.str();
  const size_t rows = static_cast<size_t>(std::count(csv.begin(), csv.end(), '\n'));
  EXPECT_GE(rows, 49u);
  EXPECT_LE(rows, 52u);
  EXPECT_EQ(csv.rfind("pc_time_ms,tick,mode,", 0), 0u);
}

TEST(Console, HexLogHoldsEveryByteReceived) {
  Bench b;
  const uint8_t bytes[] = {0x4D, 0x00, 0xFF};
  b.console.receive(bytes, sizeof bytes, b.now + 1234);
  EXPECT_EQ(b.hex.str(), "   1.234  4D 00 FF\n");
}

TEST(Console, HelpTogglesAndAnyOtherKeyClosesItAndStillActs) {
  Bench b;
  b.connect();
  b.key('h');
  EXPECT_TRUE(b.console.help_visible());
  b.key('?');
  EXPECT_FALSE(b.console.help_visible());
  b.key('?');
  b.key('a');
  EXPECT_FALSE(b.console.help_visible());
  EXPECT_EQ(b.console.controls().trims().lift, qrterm::kLiftTrimStep);
}

TEST(Console, UnboundKeySaysSo) {
  Bench b;
  b.key('%');
  EXPECT_TRUE(b.logged("key % does nothing"));
}

TEST(Console, TaskTableIsPrintedOnRequest) {
  Bench b;
  b.key('b');
  EXPECT_TRUE(b.logged("no task figures"));
  // The mixer's number, whatever rows come before it in the task table.
  uint8_t mixer = 0;
  while (std::string(wire::kTaskNames[mixer]) != "mixer") ++mixer;
  const wire::FrameBytes frame = wire::encode(wire::TelemetryTask{mixer, 212, 530, 3});
  b.console.receive(frame.bytes, frame.size, b.now);
  b.key('b');
  const qrterm::LogLine* line = b.log.find_last("mixer");
  ASSERT_NE(line, nullptr);
  EXPECT_NE(line->text.find("212    530        3"), std::string::npos) << line->text;
  EXPECT_TRUE(b.logged("cycles: mean    max overruns  (the board's cycle counter: instructions on the devboard)"))
      << "the unit";
  // Every task the QR reports has its name, none a bare number.
  for (uint8_t task = 0; task < wire::kTaskCount; ++task) {
    const wire::FrameBytes each = wire::encode(wire::TelemetryTask{task, 1, 2, 0});
    b.console.receive(each.bytes, each.size, b.now);
  }
  b.key('b');
  for (uint8_t task = 0; task < wire::kTaskCount; ++task) EXPECT_TRUE(b.logged(wire::kTaskNames[task])) << +task;

  // On the simulator the board's counter is the host's clock: the unit says so.
  qrterm::Console::Setup setup;
  setup.simulator = true;
  Bench sim(setup);
  sim.console.receive(frame.bytes, frame.size, sim.now);
  sim.key('b');
  EXPECT_TRUE(sim.logged("ns: mean    max overruns  (the host's ns: the simulator's board)"));
}

// The devboard flown by the simulator printed "the host's ns" for its RV32 instruction counts, and
// its CPU row read n/a: its figures are labelled instructions, the whole tick comes from the
// simulator's devboard line, and without a core clock the log says what clock the tick needs, with
// one what share of the period it takes.
TEST(Console, TheDevboardsFiguresAreInstructions) {
  qrterm::Console::Setup setup;
  setup.simulator = true;
  setup.devboard = true;
  Bench b(setup);
  const wire::FrameBytes frame = wire::encode(wire::TelemetryTask{8, 212, 530, 0});
  b.console.receive(frame.bytes, frame.size, b.now);
  EXPECT_EQ(b.console.figures_from(), qrterm::FiguresFrom::simulator_devboard) << "from the simulator's arguments";
  b.key('b');
  EXPECT_TRUE(b.logged("instr.: mean    max overruns  (RV32 instructions: the devboard in the simulator)"));
  EXPECT_FALSE(b.logged("host's ns"));
  EXPECT_FALSE(b.logged("the whole tick")) << "nothing before the simulator's line";

  b.console.truth_line("devboard t=3.000 core_mhz=0 tick_instr_mean=2738 tick_instr_max=8012 ticks=3000");
  b.key('b');
  EXPECT_TRUE(b.logged("tick             2738   8012           (the whole tick)"));
  EXPECT_TRUE(b.logged("no clock (qrsim --core-mhz N): 8.0 MHz runs the longest tick in 1000 us"));

  b.console.truth_line("devboard t=4.000 core_mhz=16 tick_instr_mean=2738 tick_instr_max=8012 ticks=4000");
  b.key('b');
  EXPECT_TRUE(b.logged("at 16 MHz: the tick 171 us mean, 501 us at most, of 1000 us"));
}

// The CPU row: what the figures are, said on the row itself.
TEST(CpuRow, SaysWhatItsFiguresAre) {
  const wire::TelemetrySystem s{11850, 171, 501, 0};
  using qrterm::FiguresFrom;
  EXPECT_EQ(qrterm::cpu_row(s, FiguresFrom::board, std::nullopt).text, "cpu  17.1 %  loop   501 us  misses 0");
  EXPECT_FALSE(qrterm::cpu_row(wire::TelemetrySystem{11850, 0, 0, 0}, FiguresFrom::board, std::nullopt).figures);
  EXPECT_EQ(qrterm::cpu_row(s, FiguresFrom::simulator_host, std::nullopt).text,
            "cpu n/a  loop n/a  misses n/a (simulator)");
  const qrterm::DevboardFigures no_clock{0, 2738, 8012, 3000};
  EXPECT_EQ(qrterm::cpu_row(s, FiguresFrom::simulator_devboard, no_clock).text,
            "cpu 2738 instr/tick, max 8012 (no clock)");
  const qrterm::DevboardFigures clocked{16, 2738, 8012, 3000};
  const qrterm::CpuRow row = qrterm::cpu_row(s, FiguresFrom::simulator_devboard, clocked);
  EXPECT_EQ(row.text, "cpu 17.1 %  loop 501 us  misses 0 at 16 MHz") << "the board's own, its clock said";
  EXPECT_TRUE(row.figures);
  EXPECT_LE(row.text.size(), 43u) << "fits the row at 80 columns, after the battery";
  EXPECT_FALSE(qrterm::cpu_row(s, FiguresFrom::simulator_devboard, std::nullopt).figures);
}

// A simulator key on a real serial port: the log says "no simulator", and nothing goes out.
void expect_no_simulator(qrterm::Key key) {
  Bench real;
  real.key(key);
  EXPECT_TRUE(real.logged("no simulator"));
  EXPECT_TRUE(real.console.take_sim_commands().empty());
}

qrterm::Console::Setup simulator_setup() {
  qrterm::Console::Setup setup;
  setup.simulator = true;
  return setup;
}

// The push key: a command for the simulator's truth channel when the console started qrsim,
// "no simulator" on a real serial port. Truth lines become the screen's truth text; error lines
// go to the log.
TEST(Console, PushKeyNeedsTheSimulator) {
  Bench real;
  real.key('n');
  EXPECT_TRUE(real.logged("no simulator"));
  EXPECT_TRUE(real.console.take_sim_commands().empty());
  EXPECT_EQ(real.console.truth(), "");

  Bench sim(simulator_setup());
  sim.key('N');
  const std::vector<std::string> commands = sim.console.take_sim_commands();
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0], "push 0.3 0 0 0.1\n");
  EXPECT_TRUE(sim.console.take_sim_commands().empty());
  sim.console.truth_line(
      "truth t=12.340 roll=1.23 pitch=-0.50 yaw=10.00 height=1.500 north=0.100 east=-0.020 climb=0.000");
  EXPECT_EQ(sim.console.truth(), "truth roll +1.2 pitch -0.5 yaw +10.0 height 1.50 m");
  sim.console.truth_line("ok push");
  sim.console.truth_line("truth t=garbled");
  EXPECT_EQ(sim.console.truth(), "truth roll +1.2 pitch -0.5 yaw +10.0 height 1.50 m");
  sim.console.truth_line("error bad number 'x'");
  EXPECT_TRUE(sim.logged("sim: error bad number 'x'"));
}

// The reset key (a newcomer's vehicle lay at 48 degrees after a panic, and only a restart of the
// simulator set it upright): a reset command on the truth channel, "no simulator" on a real port.
TEST(Console, ResetKeySetsTheSimulatedQrUpright) {
  expect_no_simulator('v');

  Bench sim(simulator_setup());
  sim.key('v');
  const std::vector<std::string> commands = sim.console.take_sim_commands();
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0], "reset\n");
  sim.console.truth_line("ok reset");
  EXPECT_TRUE(sim.logged("sim: the QR stands upright"));
  sim.console.truth_line("error reset: the engines are running (safe first)");
  EXPECT_TRUE(sim.logged("sim: error reset: the engines are running"));
}

// The turn key: the hand's turn on the truth channel, the axes in turn (a gyro scale calibration
// of all three), "no simulator" on a real port.
TEST(Console, TurnKeyTurnsTheSimulatedQrAboutEachAxisInTurn) {
  expect_no_simulator('y');

  Bench sim(simulator_setup());
  for (int i = 0; i < 4; ++i) sim.key('y');
  const std::vector<std::string> commands = sim.console.take_sim_commands();
  EXPECT_EQ(commands, (std::vector<std::string>{"turn z 2 4\n", "turn x 2 4\n", "turn y 2 4\n", "turn z 2 4\n"}));
  EXPECT_TRUE(sim.logged("sim: the hand turns the QR twice about its x axis"));
  sim.console.truth_line("error turn: the engines are running (safe first)");
  EXPECT_TRUE(sim.logged("sim: error turn: the engines are running"));
}

// The orientation check's key: refused without the link or outside safe; in safe its screen, whose
// Enter has the simulator's hand tilt the QR for the first step, and Tab back to the cockpit.
TEST(Console, OrientationCheckOpensInSafeAndItsEnterTiltsTheSimulatedQr) {
  Bench sim(simulator_setup());
  sim.key('9');
  EXPECT_TRUE(sim.logged("the orientation check runs in safe with the link up: 0 first"));
  EXPECT_EQ(sim.console.screen(), qrterm::Screen::cockpit);
  sim.connect();
  sim.qr.mode = wire::Mode::manual;
  sim.run(100);
  sim.key('9');
  EXPECT_EQ(sim.console.screen(), qrterm::Screen::cockpit) << "not in manual";
  sim.qr.mode = wire::Mode::safe;
  sim.run(100);
  sim.key('9');
  ASSERT_EQ(sim.console.screen(), qrterm::Screen::orientation);
  EXPECT_TRUE(sim.logged("orientation check: imu_orientation 0 in force"));
  sim.key(qrterm::kKeyEnter);
  EXPECT_EQ(sim.console.take_sim_commands(), (std::vector<std::string>{"tilt x 45 1\n"}));
  EXPECT_EQ(sim.console.orientation_check().phase(), qrterm::OrientationCheck::Phase::moving);
  sim.key('a');
  EXPECT_EQ(sim.console.controls().control().lift, qrterm::kLiftTrimStep) << "the cockpit's keys still act";
  sim.key(qrterm::kKeyTab);
  EXPECT_EQ(sim.console.screen(), qrterm::Screen::cockpit);
}

// The simulator's radio (qrsim --rc crsf): while the QR says the radio flies, a flight-mode key
// moves the radio's switches (the mode switch, the arm switch off and on) instead of asking the QR,
// which would refuse; `m` puts the arm switch off. Other requests still go to the QR, and on a real
// serial port (no simulator) `m` sends nothing.
TEST(Console, WhileTheRadioFliesTheModeKeysMoveTheSimulatedRadiosSwitches) {
  expect_no_simulator('m');

  Bench sim(simulator_setup());
  sim.connect();
  wire::TelemetryRadio radio;
  radio.flags = wire::kRadioPilot | wire::kRadioLinkUp;
  const wire::FrameBytes f = wire::encode(radio);
  sim.console.receive(f.bytes, f.size, sim.now);
  sim.key('5');
  sim.key('4');
  sim.key('2');
  sim.key('m');
  const std::vector<std::string> commands = sim.console.take_sim_commands();
  ASSERT_EQ(commands.size(), 4u);
  EXPECT_EQ(commands[0], "radio arm full\n");
  EXPECT_EQ(commands[1], "radio arm yaw\n");
  EXPECT_EQ(commands[2], "radio arm manual\n");
  EXPECT_EQ(commands[3], "radio off\n");
  EXPECT_TRUE(sim.logged("sim radio: mode switch to manual"));
  // In flight the keys leave the switches alone: their off-and-on would be a panic.
  wire::TelemetryAttitude flying;
  flying.mode = wire::Mode::full_control;
  const wire::FrameBytes a = wire::encode(flying);
  sim.console.receive(a.bytes, a.size, sim.now);
  sim.key('4');
  EXPECT_TRUE(sim.console.take_sim_commands().empty());
  EXPECT_TRUE(sim.logged("not moving the radio's switches for yaw control"));
  flying.mode = wire::Mode::safe;
  const wire::FrameBytes back = wire::encode(flying);
  sim.console.receive(back.bytes, back.size, sim.now);
  sim.run(100);
  EXPECT_EQ(count_requests(sim, wire::MessageType::mode_change), 0u) << "the QR is not asked";
  sim.key('3');  // calibration is the PC's
  sim.run(100);
  EXPECT_EQ(count_requests(sim, wire::MessageType::mode_change), 1u);
  EXPECT_TRUE(sim.console.take_sim_commands().empty());

  // The radio no longer the pilot: the keys ask the QR again.
  radio.flags = wire::kRadioLinkUp;
  const wire::FrameBytes g = wire::encode(radio);
  sim.console.receive(g.bytes, g.size, sim.now);
  sim.run(2000);  // calibration over
  sim.key('2');
  sim.run(100);
  EXPECT_TRUE(sim.console.take_sim_commands().empty());
  EXPECT_EQ(count_requests(sim, wire::MessageType::mode_change), 2u);
}

// One of every message the QR may send, as the wire library lists them: the console must have a
// use for each (a new message type added to the wire shows up here first).
template <class... Msgs>
void feed_every_qr_message(Bench& b, wire::MessageList<Msgs...>) {
  const auto feed = [&b](auto message) {
    if (wire::message_spec(decltype(message)::kType)->direction != wire::Direction::qr_to_pc) return;
    const wire::FrameBytes frame = wire::encode(message);
    b.console.receive(frame.bytes, frame.size, b.now);
  };
  (feed(Msgs{}), ...);
}

TEST(Console, HandlesEveryMessageTheQrSends) {
  Bench b;
  feed_every_qr_message(b, wire::AllMessages{});
  EXPECT_GE(b.console.link().counters().frames_ok, 13u);
  EXPECT_EQ(b.console.unhandled_frames(), 0u);
  EXPECT_EQ(b.console.invalid_frames(), 0u);
  EXPECT_FALSE(b.logged("which this console ignores"));
}

TEST(Console, TelemetryCsvRowFitsItsHeaderEvenWithGroupsMissing) {
  qrterm::TelemetryModel empty;
  EXPECT_EQ(qrterm::telemetry_csv_row(0, empty, {}).fields().size(), qrterm::telemetry_csv_header().size());
  qrterm::TelemetryModel full;
  full.attitude = wire::TelemetryAttitude{};
  full.rates = wire::TelemetryRates{};
  full.engines = wire::TelemetryEngines{};
  full.setpoints = wire::TelemetrySetpoints{};
  full.system = wire::TelemetrySystem{};
  full.qr_link = wire::TelemetryLink{};
  full.height = wire::TelemetryHeight{};
  EXPECT_EQ(qrterm::telemetry_csv_row(0, full, {}).fields().size(), qrterm::telemetry_csv_header().size());
}

TEST(Console, LostTelemetryIsCountedFromTheTick) {
  qrterm::TelemetryModel model;
  wire::TelemetryAttitude a;
  a.tick = 250;
  model.on(a);
  a.tick = 3;  // 251..255, 0..2 lost: 8 frames
  model.on(a);
  EXPECT_EQ(model.attitude_lost, 8u);
}

}  // namespace
