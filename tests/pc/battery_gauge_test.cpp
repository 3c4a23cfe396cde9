// The battery row's model (pc/core/battery_gauge.hpp): the charge from a LiPo cell's resting
// voltage, the cells counted at connection or named, the sag of the engines' load taken out as the
// QR's battery rules take it out, and the time left to the QR's panic from the charge's fall.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include <common/battery_rest.hpp>
#include <common/parameter_table.hpp>
#include <pc/core/battery_gauge.hpp>
#include <sim/battery.hpp>

namespace qrterm {
namespace {

constexpr uint16_t kAtRest[4] = {0, 0, 0, 0};
const uint16_t kPanicMv = static_cast<uint16_t>(wire::ParameterValues{}.get(wire::ParamId::battery_panic_mv));
const uint16_t kSagMv = static_cast<uint16_t>(wire::ParameterValues{}.get(wire::ParamId::battery_sag_mv));

TEST(BatteryGauge, TheChartsPointsAndBetween) {
  EXPECT_DOUBLE_EQ(lipo_charge_percent(4.20), 100);
  EXPECT_DOUBLE_EQ(lipo_charge_percent(3.84), 50);
  EXPECT_DOUBLE_EQ(lipo_charge_percent(3.61), 5);
  EXPECT_DOUBLE_EQ(lipo_charge_percent(3.27), 0);
  EXPECT_NEAR(lipo_charge_percent(3.86), 57.5, 1e-9) << "halfway between 3.85 V (55 %) and 3.87 V (60 %)";
  EXPECT_DOUBLE_EQ(lipo_charge_percent(4.30), 100) << "an HV cell or a charger's overshoot: full";
  EXPECT_DOUBLE_EQ(lipo_charge_percent(3.00), 0);
}

// The simulator's pack follows the same chart at every tenth: the console reads its charge within
// the chart's difference from a straight line between tenths (1.5 points at most, at 36 % and 86 %).
TEST(BatteryGauge, TheSimulatorsPackReadsAsItsCharge) {
  for (int soc = 0; soc <= 100; ++soc) {
    EXPECT_NEAR(lipo_charge_percent(sim::lipo_cell_volts(soc / 100.0)), soc, 1.5 + 1e-9) << soc << " %";
  }
}

TEST(BatteryGauge, CellsAreCountedFromTheVoltage) {
  EXPECT_EQ(count_cells(12600), 3) << "a full 3S";
  EXPECT_EQ(count_cells(9000), 3) << "an empty 3S";
  EXPECT_EQ(count_cells(16800), 4) << "a full 4S";
  EXPECT_EQ(count_cells(13200), 4) << "a 4S at 3.3 V a cell";
  EXPECT_EQ(count_cells(12700), 3) << "a 4S at 3.18 V a cell reads as a 3S: --cells";
  EXPECT_EQ(count_cells(4200), 1);
  EXPECT_EQ(count_cells(25200), 6);
  EXPECT_EQ(count_cells(0), 1);
  EXPECT_EQ(count_cells(60000), kMaxCells);
}

TEST(BatteryGauge, NamedCellsAreTakenAsTheyAre) {
  BatteryGauge counted, named(4);
  counted.on_report(12600, kAtRest, kSagMv, 0);
  named.on_report(12600, kAtRest, kSagMv, 0);
  EXPECT_EQ(counted.reading(kPanicMv)->cells, 3);
  EXPECT_DOUBLE_EQ(counted.reading(kPanicMv)->percent, 100);
  EXPECT_EQ(named.reading(kPanicMv)->cells, 4);
  EXPECT_DOUBLE_EQ(named.reading(kPanicMv)->percent, 0) << "3.15 V a cell";
  EXPECT_FALSE(BatteryGauge{}.reading(kPanicMv)) << "nothing before the first report";
}

TEST(BatteryGauge, ALinkThatComesUpCountsTheCellsAgain) {
  BatteryGauge gauge;
  gauge.on_report(12600, kAtRest, kSagMv, 0);
  gauge.link_up();
  EXPECT_FALSE(gauge.reading(kPanicMv));
  gauge.on_report(16000, kAtRest, kSagMv, 1);
  EXPECT_EQ(gauge.reading(kPanicMv)->cells, 4);
  EXPECT_DOUBLE_EQ(gauge.reading(kPanicMv)->resting_v, 16.0) << "no mean with the old pack";
}

// A climb's sag is the load, not the charge: with battery_sag_mv the QR's resting voltage stays;
// without it the charge would drop by a quarter.
TEST(BatteryGauge, TheEnginesSagIsNotTheCharge) {
  constexpr uint16_t kFull[4] = {1000, 1000, 1000, 1000};
  BatteryGauge gauge, unaware;
  gauge.on_report(12000, kAtRest, kSagMv, 0);
  unaware.on_report(12000, kAtRest, 0, 0);
  const double before = gauge.reading(kPanicMv)->percent;
  const auto sagging = static_cast<uint16_t>(12000 - kSagMv);
  ASSERT_EQ(wire::battery_rested_mv(sagging, kFull, kSagMv), 12000);
  for (int i = 1; i <= 40; ++i) {
    gauge.on_report(sagging, kFull, kSagMv, i * 0.125);
    unaware.on_report(sagging, kFull, 0, i * 0.125);
  }
  EXPECT_DOUBLE_EQ(gauge.reading(kPanicMv)->percent, before);
  EXPECT_LT(unaware.reading(kPanicMv)->percent, before - 25);
}

// The QR's one-second mean: a step is 63 % there after a second.
TEST(BatteryGauge, TheVoltageIsTheQrsOneSecondMean) {
  BatteryGauge gauge;
  gauge.on_report(12000, kAtRest, kSagMv, 0);
  for (int i = 1; i <= 8; ++i) gauge.on_report(11000, kAtRest, kSagMv, i * 0.125);
  EXPECT_NEAR(gauge.reading(kPanicMv)->resting_v, 12.0 - (1 - std::exp(-1.0)), 1e-9);
}

// 3S between 4.02 V (80 %) and 4.08 V (85 %) a cell: 36 mV of pack a per cent of charge.
uint16_t pack_mv(double percent) { return static_cast<uint16_t>(std::lround(3 * (4020 + (percent - 80) * 12))); }

TEST(BatteryGauge, TimeLeftComesFromTheChargesFallOverTheLastTensOfSeconds) {
  BatteryGauge gauge;
  // 0.1 % a second, a report every 1/8 s (telemetry_system at 50 Hz / 6), a 16 mV ADC's steps.
  double t = 0;
  for (; t < kChargeMinSpanS - 0.5; t += 0.125) gauge.on_report(pack_mv(85 - 0.1 * t) / 16 * 16, kAtRest, kSagMv, t);
  EXPECT_FALSE(gauge.reading(kPanicMv)->seconds_left) << "under 10 s of reports: not known yet";
  EXPECT_TRUE(std::regex_match(charge_text(*gauge.reading(kPanicMv)), std::regex(R"(3S 8\d % -- left)")))
      << charge_text(*gauge.reading(kPanicMv));
  for (; t < 40; t += 0.125) gauge.on_report(pack_mv(85 - 0.1 * t) / 16 * 16, kAtRest, kSagMv, t);
  const BatteryReading r = *gauge.reading(kPanicMv);
  ASSERT_TRUE(r.seconds_left);
  EXPECT_NEAR(r.percent, 81, 0.6);
  EXPECT_NEAR(r.panic_percent, 5 * (3.5 - 3.27) / (3.61 - 3.27), 1e-9) << "10.5 V on 3S: 3.5 V a cell";
  EXPECT_NEAR(*r.seconds_left, (r.percent - r.panic_percent) / 0.1, 0.05 * *r.seconds_left);
  EXPECT_FALSE(r.near_panic);
  EXPECT_TRUE(std::regex_match(charge_text(r), std::regex(R"(3S 8[01] % 1[23]:[0-5]\d left)"))) << charge_text(r);
}

TEST(BatteryGauge, APackThatDoesNotFallHasNoTimeLeft) {
  BatteryGauge gauge;
  for (double t = 0; t < 60; t += 0.125) {
    gauge.on_report(static_cast<uint16_t>(12200 + (static_cast<int>(t * 8) % 2) * 16), kAtRest, kSagMv, t);
  }
  EXPECT_FALSE(gauge.reading(kPanicMv)->seconds_left) << "on the bench: the charge stays";
}

// The sag model misses part of the hover's sag (here 100 mV): the engines starting step the resting
// voltage down. That is no charge spent: the fall is measured from 3 s after they start.
TEST(BatteryGauge, ATakeOffIsNoFallOfTheCharge) {
  constexpr uint16_t kHover[4] = {550, 550, 550, 550};
  const int modelled = wire::battery_rested_mv(12000, kHover, kSagMv) - 12000;  // the sag the model adds
  const auto hovering = static_cast<uint16_t>(12200 - modelled - 100);
  BatteryGauge gauge;
  double t = 0;
  for (; t < 20; t += 0.125) gauge.on_report(12200, kAtRest, kSagMv, t);
  for (; t < 20 + kLoadSettleS + kChargeMinSpanS + 2; t += 0.125) {
    gauge.on_report(hovering, kHover, kSagMv, t);
  }
  const BatteryReading r = *gauge.reading(kPanicMv);
  EXPECT_NEAR(r.resting_v, 12.1, 1e-3) << "the step itself is in the charge";
  EXPECT_FALSE(r.seconds_left) << "but not in its fall";
}

// Near the panic: within 10 points of its charge, or a minute before it, in yellow and once in the
// log; a fresh pack is warned of again.
TEST(BatteryGauge, ItWarnsOnceBeforeThePanic) {
  BatteryGauge gauge;
  gauge.on_report(11600, kAtRest, kSagMv, 0);  // 3.87 V a cell: 60 %
  EXPECT_FALSE(gauge.reading(kPanicMv)->near_panic);
  EXPECT_EQ(gauge.notice(kPanicMv), "");
  gauge.link_up();
  gauge.on_report(11130, kAtRest, kSagMv, 0);  // 3.71 V: 15 %, 11.6 points above the panic's 3.4 %
  EXPECT_FALSE(gauge.reading(kPanicMv)->near_panic);
  gauge.link_up();
  gauge.on_report(11070, kAtRest, kSagMv, 0);  // 3.69 V: 10 %
  EXPECT_TRUE(gauge.reading(kPanicMv)->near_panic);
  EXPECT_EQ(gauge.notice(kPanicMv), "battery 3S 10 % -- left: near the QR's panic level (10.50 V, 3 %), land");
  EXPECT_EQ(gauge.notice(kPanicMv), "") << "once";
  gauge.link_up();
  gauge.on_report(12600, kAtRest, kSagMv, 0);
  EXPECT_EQ(gauge.notice(kPanicMv), "");
  gauge.link_up();
  gauge.on_report(11070, kAtRest, kSagMv, 0);
  EXPECT_NE(gauge.notice(kPanicMv), "") << "a fresh pack, run down again";
}

// A fast fall is near the panic a minute before it, however much charge there is still: here
// against a panic threshold of 11.8 V (3.93 V a cell, 68 %), with the default's 10.5 V far away.
TEST(BatteryGauge, AMinuteBeforeThePanicIsNearWhateverTheCharge) {
  BatteryGauge gauge;
  for (double t = 0; t < 12; t += 0.125) gauge.on_report(pack_mv(85 - 0.3 * t), kAtRest, kSagMv, t);
  const BatteryReading far = *gauge.reading(kPanicMv);
  ASSERT_TRUE(far.seconds_left);
  EXPECT_GT(*far.seconds_left, kNearPanicS);
  EXPECT_FALSE(far.near_panic);
  const BatteryReading near = *gauge.reading(11800);
  ASSERT_TRUE(near.seconds_left);
  EXPECT_GT(near.percent - near.panic_percent, kNearPanicPoints);
  EXPECT_LE(*near.seconds_left, kNearPanicS);
  EXPECT_TRUE(near.near_panic);
}

}  // namespace
}  // namespace qrterm
