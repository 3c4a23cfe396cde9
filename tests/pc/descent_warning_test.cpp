// The descent warning: the rule as a table of heights and climb rates, the acceleration it counts
// on, and the console that shows it once, before the ground, and holds it without blinking.
#include <gtest/gtest.h>

#include <cmath>

#include <pc/core/descent_warning.hpp>

#include "console_bench.hpp"

namespace {

using qrterm::DescentDanger;
using qrterm::judge_descent;
using qrterm_test::Bench;

// The default simulated vehicle learns a hover lift of about 535.
constexpr uint16_t kHover = 535;

TEST(DescentWarning, TheSpareAccelerationComesFromTheHoverAgainstFullLift) {
  // Full lift over a hover at 535: (1000 / 535)^2 = 3.494 times the weight; half of the 2.494 g
  // above it.
  EXPECT_NEAR(qrterm::spare_acceleration_m_s2(kHover), 0.5 * 9.81 * 2.4938, 0.01);
  // A vehicle that hovers at 707 weighs half of full thrust ((1000 / 707)^2 = 2.0): 1 g spare at
  // full lift, half of it counted.
  EXPECT_NEAR(qrterm::spare_acceleration_m_s2(707), 0.5 * 9.81, 0.01);
  EXPECT_EQ(qrterm::spare_acceleration_m_s2(1000), 0.0) << "a hover at full lift spares nothing";
  EXPECT_EQ(qrterm::spare_acceleration_m_s2(0), qrterm::kUnknownSpareMS2) << "not learnt yet";
  // The stand-in is conservative: below what any vehicle hovering under 840 has.
  EXPECT_LT(qrterm::kUnknownSpareMS2, qrterm::spare_acceleration_m_s2(840));
}

struct Case {
  double height_m;
  double climb_m_s;
  uint16_t hover_lift;
  bool flying;
  DescentDanger expected;
  const char* what;
};

// Hover 535: a = 12.23 m/s^2, so at 5.7 m/s the descent needs 5.7 (a second to act) + 1.33
// (braking) + 1 (margin) = 8.03 m.
constexpr Case kCases[] = {
    {149.0, -5.7, kHover, true, DescentDanger::none, "the pilot's fall, high up: room to stop"},
    {8.5, -5.7, kHover, true, DescentDanger::none, "the pilot's fall, just above what it needs"},
    {8.0, -5.7, kHover, true, DescentDanger::cannot_stop, "the pilot's fall, at what it needs"},
    {2.0, -5.7, kHover, true, DescentDanger::cannot_stop, "the pilot's fall, late"},
    {14.0, -5.7, 0, true, DescentDanger::cannot_stop, "no hover learnt: 2 m/s^2 counted, 14.8 m needed"},
    {15.0, -5.7, 0, true, DescentDanger::none, "no hover learnt, above the 14.8 m"},
    {18.5, -12.0, kHover, true, DescentDanger::cannot_stop, "12 m/s needs 12 + 5.9 + 1 = 18.9 m"},
    {19.5, -12.0, kHover, true, DescentDanger::none, "12 m/s, above its 18.9 m"},
    {2.9, -1.1, kHover, true, DescentDanger::too_fast_low, "near the ground, a little faster than a safe touchdown"},
    {3.1, -1.1, kHover, true, DescentDanger::none, "above the near-ground band, room to stop"},
    {0.5, -0.9, kHover, true, DescentDanger::none, "a landing slower than 1 m/s never warns"},
    {0.2, -0.5, kHover, true, DescentDanger::none, "the panic's landing at 0.5 m/s"},
    {0.5, -5.7, kHover, false, DescentDanger::none, "landed: the ground, not a descent"},
    {1.0, 3.0, kHover, true, DescentDanger::none, "climbing"},
    {-2.0, -2.0, kHover, true, DescentDanger::cannot_stop, "below where it was calibrated"},
    {100.0, -1.5, 1000, true, DescentDanger::cannot_stop, "hovering at full lift: it cannot stop at all"},
};

TEST(DescentWarning, TableOfHeightsAndClimbRates) {
  for (const Case& c : kCases) {
    const qrterm::DescentVerdict v = judge_descent(c.height_m, c.climb_m_s, c.hover_lift, c.flying);
    EXPECT_EQ(v.danger, c.expected) << c.what << ": h " << c.height_m << " v " << c.climb_m_s << " needs "
                                    << v.needed_m;
    EXPECT_EQ(v.warn, c.expected != DescentDanger::none) << c.what;
  }
}

TEST(DescentWarning, WhatTheDescentNeedsIsReactionBrakingAndMargin) {
  const qrterm::DescentVerdict v = judge_descent(50.0, -5.7, kHover, true);
  const double a = qrterm::spare_acceleration_m_s2(kHover);
  EXPECT_NEAR(v.needed_m, 5.7 * qrterm::kReactionS + 5.7 * 5.7 / (2 * a) + qrterm::kMarginM, 1e-9);
  EXPECT_NEAR(v.needed_m, 8.03, 0.01);
  EXPECT_TRUE(std::isinf(judge_descent(50.0, -2.0, 1000, true).needed_m));
}

// What the rule promises: a pilot who acts within kReactionS of the warning and then brakes at
// the acceleration counted on stops kMarginM above the ground, whatever the speed (the descent
// taken as steady until the pilot acts).
TEST(DescentWarning, WarnedAtTheFirstReportAPilotWhoActsInTimeStopsAboveTheGround) {
  for (double speed = 1.1; speed < 20.0; speed += 0.7) {
    for (uint16_t hover : {uint16_t{0}, uint16_t{450}, kHover, uint16_t{700}, uint16_t{900}}) {
      // Reports every 0.12 s on the way down from high up: the first one that warns.
      double h = 200.0;
      while (!judge_descent(h, -speed, hover, true).warn) h -= speed * 0.12;
      const double a = qrterm::spare_acceleration_m_s2(hover);
      const double stopped_at = h - speed * qrterm::kReactionS - speed * speed / (2 * a);
      EXPECT_GE(stopped_at, qrterm::kMarginM - speed * 0.12) << "speed " << speed << " hover " << hover;
      EXPECT_GT(h, 0.0);
    }
  }
}

// --- the console

void flying_full_control(Bench& b) {
  b.connect();
  b.key('3');
  ASSERT_TRUE(b.run_until([&] { return b.qr.calibrated && b.qr.mode == wire::Mode::safe; }, 2000));
  b.key('5');
  ASSERT_TRUE(b.run_until([&] { return b.qr.mode == wire::Mode::full_control; }, 500));
  b.qr.flying_flag = true;
}

size_t sinking_lines(const Bench& b) {
  size_t n = 0;
  for (const qrterm::LogLine& line : b.log.lines()) n += line.text.rfind("SINKING", 0) == 0 ? 1 + line.repeats : 0;
  return n;
}

// A fall at 5.7 m/s from 20 m with hover 535, reported every telemetry period: the warning comes
// at 8 m and not before, once, as an error.
TEST(DescentWarning, TheConsoleWarnsOnceBeforeTheGround) {
  Bench b;
  flying_full_control(b);
  double h = 20.0;
  double warned_at = -1;
  while (h > 0.3) {
    b.qr.height = wire::TelemetryHeight{static_cast<int32_t>(std::lround(h * 1000)), -5700, wire::kHeightValid, kHover};
    b.run(20);
    if (warned_at < 0 && b.console.sinking_m_s()) warned_at = h;
    h -= 5.7 * 0.020;
  }
  EXPECT_LE(warned_at, 8.03 + 0.12);
  EXPECT_GE(warned_at, 8.03 - 0.12) << "at what the descent needs, not later";
  ASSERT_TRUE(b.console.sinking_m_s());
  EXPECT_NEAR(*b.console.sinking_m_s(), 5.7, 1e-9);
  EXPECT_EQ(sinking_lines(b), 1u) << "one line when it starts";
  const qrterm::LogLine* line = b.log.find_last("SINKING 5.7 m/s at ");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->severity, qrterm::Severity::error);
  // docs/console.md quotes this line.
  EXPECT_EQ(line->text,
            "SINKING 5.7 m/s at 7.9 m: it needs 8.0 m to stop (1 s to act, braking at 12.2 m/s^2, 1 m to spare); lift "
            "now (PgUp)");
}

TEST(DescentWarning, ItHoldsASecondAfterTheDescentIsStoppedThenEnds) {
  Bench b;
  flying_full_control(b);
  b.qr.height = wire::TelemetryHeight{5000, -5000, wire::kHeightValid, kHover};
  b.run(100);
  ASSERT_TRUE(b.console.sinking_m_s());
  // Braked: 0.5 m/s down, then a report that wavers back to 1.2 m/s: still the same warning.
  b.qr.height = wire::TelemetryHeight{4000, -500, wire::kHeightValid, kHover};
  b.run(500);
  ASSERT_TRUE(b.console.sinking_m_s()) << "held";
  EXPECT_NEAR(*b.console.sinking_m_s(), 0.5, 1e-9) << "showing the speed now";
  b.qr.height = wire::TelemetryHeight{2500, -1200, wire::kHeightValid, kHover};
  b.run(100);
  b.qr.height = wire::TelemetryHeight{2400, -300, wire::kHeightValid, kHover};
  b.run(qrterm::kSinkingHoldMs - 100);
  EXPECT_TRUE(b.console.sinking_m_s());
  b.run(200);
  EXPECT_FALSE(b.console.sinking_m_s()) << "a second clear";
  EXPECT_EQ(sinking_lines(b), 1u) << "no line for the waver";
}

TEST(DescentWarning, LandedEndsItAtOnce) {
  Bench b;
  flying_full_control(b);
  b.qr.height = wire::TelemetryHeight{1000, -4000, wire::kHeightValid, kHover};
  b.run(100);
  ASSERT_TRUE(b.console.sinking_m_s());
  b.qr.flying_flag = false;
  b.qr.height = wire::TelemetryHeight{0, -4000, wire::kHeightValid, kHover};
  b.run(40);
  EXPECT_FALSE(b.console.sinking_m_s());
}

// The advice is what the pilot can do: in panic nothing (the QR ignores the sticks); with a real
// radio flying, its throttle, not the console's keys.
TEST(DescentWarning, InPanicItAsksForNoLift) {
  Bench b;
  flying_full_control(b);
  b.key(qrterm::kKeyEscape);
  ASSERT_TRUE(b.run_until([&] { return b.console.sinking_in_panic(); }, 200));
  b.qr.height = wire::TelemetryHeight{3000, -4000, wire::kHeightValid, kHover};
  b.run(100);
  ASSERT_TRUE(b.console.sinking_m_s());
  EXPECT_TRUE(b.logged("; the QR is in panic: the sticks do nothing, it comes down by itself"));
  EXPECT_FALSE(b.logged("PgUp"));
}

TEST(DescentWarning, WithARealRadioFlyingItNamesTheRadiosThrottle) {
  Bench b;
  flying_full_control(b);
  const wire::FrameBytes radio = wire::encode(wire::TelemetryRadio{wire::kRadioPilot | wire::kRadioLinkUp, 60, 100});
  b.console.receive(radio.bytes, radio.size, b.now);
  b.qr.height = wire::TelemetryHeight{3000, -4000, wire::kHeightValid, kHover};
  b.run(100);
  ASSERT_TRUE(b.console.sinking_m_s());
  EXPECT_TRUE(b.logged("; lift now, on the radio's throttle"));
}

TEST(DescentWarning, NoWarningOnTheGroundWithoutAHeightReferenceOrWithoutTheLink) {
  Bench b;
  flying_full_control(b);
  b.qr.flying_flag = false;
  b.qr.height = wire::TelemetryHeight{1000, -4000, wire::kHeightValid, kHover};
  b.run(100);
  EXPECT_FALSE(b.console.sinking_m_s()) << "landed";
  b.qr.flying_flag = true;
  b.qr.height = wire::TelemetryHeight{0, 0, 0, kHover};  // no barometer reference: no figures
  b.run(100);
  EXPECT_FALSE(b.console.sinking_m_s()) << "no height reference";
  b.qr.height = wire::TelemetryHeight{1000, -4000, wire::kHeightValid, kHover};
  b.run(100);
  ASSERT_TRUE(b.console.sinking_m_s());
  b.qr.silent = true;
  b.run(qrterm::kLinkLostAfterMs + 100);
  EXPECT_FALSE(b.console.sinking_m_s()) << "LINK LOST says it all: the figures are old";
  EXPECT_EQ(sinking_lines(b), 1u);
}

}  // namespace
