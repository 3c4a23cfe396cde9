// The motor test's screen (pc/core/motor_bench.hpp): its steps on keys and on the QR's mode, what
// the simulator saw turn; and the console around it against the fake QR (the key opens it in safe
// only, its keys are its own).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <pc/core/key.hpp>
#include <pc/core/motor_bench.hpp>

#include "console_bench.hpp"

namespace {

using qrterm::BenchStep;
using qrterm::EngineCheck;
using qrterm::MotorBench;
using wire::Mode;

struct MotorTestScreen : ::testing::Test {
  std::vector<std::pair<uint8_t, uint16_t>> spins;
  int stops = 0;
  int leaves = 0;
  std::vector<std::string> notes;
  bool send = true;    // the spin hook sends its request
  bool dshot = false;  // the QR's ESCs answer: DShot
  std::vector<std::pair<uint8_t, uint8_t>> directions;
  MotorBench bench{MotorBench::Hooks{
      [this](uint8_t engine, uint16_t level) {
        if (send) spins.emplace_back(engine, level);
        return send;
      },
      [this] { ++stops; }, [this](uint8_t engine, uint8_t direction) { directions.emplace_back(engine, direction); },
      [this] { return dshot; }, [this] { ++leaves; },
      [this](qrterm::Severity, const std::string& text) { notes.push_back(text); }}};
  uint32_t now = 1000;

  void key(qrterm::Key k) { bench.key(k, now); }
  void opened() {
    bench.open();
    key('y');
    ASSERT_EQ(bench.step(), BenchStep::choose);
  }
  // The QR runs the test and ends it, as telemetry reports its mode.
  void qr_runs_the_test() {
    bench.mode(Mode::safe);  // a period before the test began
    bench.mode(Mode::motor_test);
    bench.mode(Mode::motor_test);
    bench.mode(Mode::safe);
  }
};

TEST_F(MotorTestScreen, ThePropellersQuestionComesFirstAndAnyOtherKeyLeaves) {
  bench.open();
  EXPECT_EQ(bench.step(), BenchStep::props);
  EXPECT_NE(bench.lines().back().find("propellers OFF"), std::string::npos);
  key('2');
  EXPECT_EQ(leaves, 1) << "not a yes: back to the cockpit";
  EXPECT_TRUE(spins.empty()) << "and nothing spun";
  opened();
  key('q');
  EXPECT_EQ(leaves, 2);
  bench.open();
  EXPECT_EQ(bench.step(), BenchStep::props) << "asked again every time the screen opens";
}

TEST_F(MotorTestScreen, ItSpinsTheChosenEngineAtTenPercentAndAnyKeyStopsIt) {
  opened();
  key('3');
  ASSERT_EQ(spins.size(), 1u);
  EXPECT_EQ(spins[0].first, 2) << "engine 3 on the screen is the wire's 2, the back";
  EXPECT_EQ(spins[0].second, qrterm::kBenchLevel);
  EXPECT_LE(qrterm::kBenchLevel, wire::kMotorTestMaxLevel);
  EXPECT_EQ(bench.step(), BenchStep::spinning);
  EXPECT_NE(bench.lines().back().find("ANY KEY STOPS IT"), std::string::npos);
  bench.mode(Mode::motor_test);
  key('5');  // a mode key in the cockpit: here it stops the engine and flies nothing
  EXPECT_EQ(stops, 1);
  EXPECT_EQ(spins.size(), 1u);
  EXPECT_EQ(bench.step(), BenchStep::confirm) << "the pilot saw what turned";
}

TEST_F(MotorTestScreen, TheQrsEndAsksThePilotWhatTurnedAndTheAnswerIsKept) {
  opened();
  key('2');
  qr_runs_the_test();
  ASSERT_EQ(bench.step(), BenchStep::confirm);
  EXPECT_EQ(stops, 0) << "the QR ended it by itself";
  EXPECT_NE(bench.lines().back().find("Did the right rotor turn, counter-clockwise seen from above?"),
            std::string::npos)
      << bench.lines().back();
  key('x');
  EXPECT_EQ(bench.step(), BenchStep::confirm) << "only y or n answers";
  key('y');
  EXPECT_EQ(bench.check(1), EngineCheck::confirmed);
  EXPECT_EQ(bench.step(), BenchStep::choose);
  key('4');
  qr_runs_the_test();
  key('n');
  EXPECT_EQ(bench.check(3), EngineCheck::wrong);
  EXPECT_EQ(bench.check(0), EngineCheck::untested);
  EXPECT_NE(bench.lines()[3].find("WRONG"), std::string::npos) << bench.lines()[3];
  EXPECT_NE(bench.lines()[1].find("confirmed"), std::string::npos) << bench.lines()[1];
}

TEST_F(MotorTestScreen, ARefusalNoAnswerOrARequestNotSentGoesBackToChoosing) {
  opened();
  key('1');
  bench.answer(wire::NackReason::none);
  EXPECT_EQ(bench.step(), BenchStep::spinning) << "an ack: the test runs";
  bench.answer(wire::NackReason::controls_not_neutral);
  EXPECT_EQ(bench.step(), BenchStep::choose);
  EXPECT_NE(notes.back().find("QR refused the motor test: sticks and lift not neutral"), std::string::npos);
  key('1');
  bench.unanswered();
  EXPECT_EQ(bench.step(), BenchStep::choose);
  send = false;  // the console's own check refused it (a lift trim standing)
  key('1');
  EXPECT_EQ(bench.step(), BenchStep::choose);
}

// With DShot ESCs an engine found wrong may have its ESC's direction set (and saved); without,
// the log says what to do by hand.
TEST_F(MotorTestScreen, WithDshotEscsAWrongEnginesDirectionCanBeSetInItsEsc) {
  opened();
  key('3');
  qr_runs_the_test();
  key('n');
  EXPECT_EQ(bench.step(), BenchStep::choose) << "no DShot: nothing to set from here";
  EXPECT_NE(notes.back().find("swap two of its motor's wires"), std::string::npos) << notes.back();
  dshot = true;
  key('3');
  qr_runs_the_test();
  key('n');
  ASSERT_EQ(bench.step(), BenchStep::direction);
  EXPECT_NE(bench.lines().back().find("1 normal  2 reversed"), std::string::npos) << bench.lines().back();
  key('2');
  ASSERT_EQ(directions.size(), 1u);
  EXPECT_EQ(directions[0], (std::pair<uint8_t, uint8_t>{2, 2})) << "engine 3's ESC (the wire's 2), reversed";
  EXPECT_EQ(bench.step(), BenchStep::choose);
  key('1');
  qr_runs_the_test();
  key('n');
  key('x');
  EXPECT_EQ(directions.size(), 1u) << "any other key leaves the ESC as it is";
  EXPECT_EQ(bench.step(), BenchStep::choose);
}

// Should the QR's end never be seen (telemetry lost), the console stops the test itself.
TEST_F(MotorTestScreen, TheConsoleStopsATestWhoseEndItDoesNotSee) {
  opened();
  key('1');
  bench.mode(Mode::motor_test);
  now += 3000;
  bench.tick(now);
  EXPECT_EQ(stops, 0) << "within the 2 s test and its margin";
  now += 600;
  bench.tick(now);
  EXPECT_EQ(stops, 1);
  EXPECT_EQ(bench.step(), BenchStep::confirm);
}

// The simulator's truth: the fastest rotor during the test, its way, against the engine's own.
TEST_F(MotorTestScreen, TheSimulatorNamesTheRotorThatTurnedAndItsWay) {
  opened();
  EXPECT_EQ(bench.simulator_saw(), "") << "no truth, no line (a real QR)";
  key('2');
  bench.rotors({0, 0, 0, 0});
  bench.rotors({0.5, -104.7, 0, 0});
  bench.rotors({0, -60, 0, 0});  // running down: the peak stays
  EXPECT_EQ(bench.simulator_saw(), "sim: rotor 2 (right) turned counter-clockwise, as engine 2 must");
  qr_runs_the_test();
  bench.rotors({0, 104.7, 0, 0});  // after the test: not this test's
  EXPECT_EQ(bench.simulator_saw(), "sim: rotor 2 (right) turned counter-clockwise, as engine 2 must");
  key('y');

  key('1');
  bench.rotors({0, 0, 0, -104.7});
  EXPECT_EQ(bench.simulator_saw(), "sim: rotor 4 (left) turned counter-clockwise: the wrong rotor for engine 1");
  qr_runs_the_test();
  key('n');
  key('3');
  bench.rotors({0, 0, -104.7, 0});
  EXPECT_EQ(bench.simulator_saw(), "sim: rotor 3 (back) turned counter-clockwise: the wrong way");
  qr_runs_the_test();
  key('n');
  key('4');
  bench.rotors({1, 0, 0, -2});
  EXPECT_EQ(bench.simulator_saw(), "sim: no rotor turned");
  EXPECT_EQ(bench.lines()[4], "sim: no rotor turned");
}

size_t count_of(const qrterm_test::Bench& b, wire::MessageType type) {
  return static_cast<size_t>(std::count_if(b.qr.requests.begin(), b.qr.requests.end(),
                                           [type](const wire::Frame& f) { return f.type == type; }));
}

// The console: 6 opens the bench in safe only; on it the digits choose engines (no mode changes),
// the QR's test and its end come back to the bench, and so does a refusal.
TEST(ConsoleMotorTest, TheKeyOpensTheBenchInSafeOnlyAndItsKeysAreItsOwn) {
  qrterm_test::Bench b;
  b.connect();
  b.key('6');
  ASSERT_EQ(b.console.screen(), qrterm::Screen::motor_test);
  b.key('y');
  b.key('2');
  b.run(5);
  ASSERT_EQ(count_of(b, wire::MessageType::motor_test), 1u);
  EXPECT_EQ(count_of(b, wire::MessageType::mode_change), 0u) << "2 is engine 2 here, not manual";
  wire::MotorTest sent;
  for (const wire::Frame& f : b.qr.requests) {
    if (f.type == wire::MessageType::motor_test) ASSERT_TRUE(wire::decode(f, sent));
  }
  EXPECT_EQ(sent.engine, 1);
  EXPECT_EQ(sent.level, qrterm::kBenchLevel);
  b.run(995);
  EXPECT_EQ(b.console.motor_bench().step(), BenchStep::spinning);
  ASSERT_TRUE(b.console.telemetry().engines);
  EXPECT_EQ(b.console.telemetry().engines->engine[1], qrterm::kBenchLevel);
  EXPECT_TRUE(b.run_until([&] { return b.console.motor_bench().step() == BenchStep::confirm; }, 1500))
      << "the QR's end of its 2 s";
  b.key('y');
  EXPECT_EQ(b.console.motor_bench().check(1), EngineCheck::confirmed);

  b.qr.refuse_leaving_safe = wire::NackReason::imu_fault;
  b.key('1');
  b.run(50);
  EXPECT_EQ(b.console.motor_bench().step(), BenchStep::choose);
  EXPECT_TRUE(b.logged("QR refused the motor test: the IMU is not healthy"));
  b.qr.refuse_leaving_safe = wire::NackReason::none;
  b.key('q');
  EXPECT_EQ(b.console.screen(), qrterm::Screen::cockpit);

  b.key('2');
  ASSERT_TRUE(b.run_until(
      [&] { return b.console.telemetry().attitude && b.console.telemetry().attitude->mode == Mode::manual; }, 200));
  b.key('6');
  EXPECT_EQ(b.console.screen(), qrterm::Screen::cockpit);
  EXPECT_TRUE(b.logged("the motor test opens in safe only"));
}

}  // namespace
