// The scoring functions on traces whose figures are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <qr/sim_runner/scoring.hpp>

namespace {

using qrsim::Trace;

// y(t) for a step of height 1 at t = 1 s, sampled at 1 kHz until t = 4 s.
template <class F>
Trace sampled(F response) {
  Trace trace;
  for (int i = 0; i <= 4000; ++i) {
    const double t = i * 1e-3;
    trace.push_back({t, t < 1 ? 0.0 : response(t - 1)});
  }
  return trace;
}

TEST(Scoring, FirstOrderStepHasTheTextbookFigures) {
  const double tau = 0.2;
  const Trace trace = sampled([&](double t) { return 10 * (1 - std::exp(-t / tau)); });
  const qrsim::StepFigures f = qrsim::step_response(trace, 1.0, 0, 10, 1.0);
  EXPECT_NEAR(f.rise_s, tau * std::log(9.0), 1e-4);  // 10 % to 90 %
  EXPECT_EQ(f.overshoot_pct, 0);
  // Within 1 of 10 when e^(-t/tau) < 0.1: t = tau ln 10, to the next sample.
  EXPECT_NEAR(f.settle_s, tau * std::log(10.0), 1e-3);
}

TEST(Scoring, UnderdampedStepOvershootsByTheTextbookAmount) {
  const double zeta = 0.4, wn = 10;
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  const Trace trace = sampled([&](double t) {
    return 10 * (1 - std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta * wn / wd * std::sin(wd * t)));
  });
  const qrsim::StepFigures f = qrsim::step_response(trace, 1.0, 0, 10, 1.0);
  const double overshoot = 100 * std::exp(-std::numbers::pi * zeta / std::sqrt(1 - zeta * zeta));
  EXPECT_NEAR(f.overshoot_pct, overshoot, 0.05);
  // Settled once the envelope 10 e^(-zeta wn t)/sqrt(1-zeta^2) is inside the band, give or take
  // where in its swing the last excursion ends.
  EXPECT_GT(f.settle_s, 0.3);
  EXPECT_LT(f.settle_s, std::log(10 / std::sqrt(1 - zeta * zeta)) / (zeta * wn));
  EXPECT_GT(f.rise_s, 0.1);
  EXPECT_LT(f.rise_s, 0.2);
}

TEST(Scoring, AStepThatNeverArrivesHasNoRiseOrSettlingTime) {
  const Trace trace = sampled([](double t) { return 5 * (1 - std::exp(-t / 0.1)); });  // stops at half
  const qrsim::StepFigures f = qrsim::step_response(trace, 1.0, 0, 10, 1.0);
  EXPECT_TRUE(std::isnan(f.rise_s));
  EXPECT_TRUE(std::isnan(f.settle_s));
  EXPECT_EQ(f.overshoot_pct, 0);
}

TEST(Scoring, ANegativeStepIsScoredLikeAPositiveOne) {
  const Trace up = sampled([](double t) { return 10 * (1 - std::exp(-t / 0.2)); });
  Trace down = up;
  for (auto& s : down) s.value = -s.value;
  const qrsim::StepFigures a = qrsim::step_response(up, 1.0, 0, 10, 1.0);
  const qrsim::StepFigures b = qrsim::step_response(down, 1.0, 0, -10, 1.0);
  EXPECT_DOUBLE_EQ(a.rise_s, b.rise_s);
  EXPECT_DOUBLE_EQ(a.settle_s, b.settle_s);
  EXPECT_DOUBLE_EQ(a.overshoot_pct, b.overshoot_pct);
}

TEST(Scoring, RmsPeakMeanAndRecovery) {
  Trace sine;
  for (int i = 0; i < 10000; ++i) sine.push_back({i * 1e-3, 2 * std::sin(2 * std::numbers::pi * i * 1e-3)});
  EXPECT_NEAR(qrsim::rms(sine, 0, 10), std::sqrt(2.0), 1e-3);
  EXPECT_NEAR(qrsim::peak_abs(sine, 0, 10), 2, 1e-3);
  EXPECT_NEAR(qrsim::mean(sine, 0, 10), 0, 1e-3);
  EXPECT_TRUE(std::isnan(qrsim::rms(sine, 20, 30)));  // nothing in the window

  // A decaying error: back within 0.5 for good at t = ln(4) / 2 after the kick.
  Trace decay;
  for (int i = 0; i <= 3000; ++i) decay.push_back({i * 1e-3, 2 * std::exp(-2 * i * 1e-3)});
  EXPECT_NEAR(qrsim::recovery_time(decay, 0, 0.5), std::log(4.0) / 2, 1e-3);
  // One that ends outside the band never recovered.
  decay.push_back({3.001, 0.6});
  EXPECT_TRUE(std::isnan(qrsim::recovery_time(decay, 0, 0.5)));
}

}  // namespace
