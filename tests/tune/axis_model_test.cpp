// The model's pieces that the fit and the design rest on: the sensor low-pass is the firmware's,
// the sampled axis is the continuous one, and its frequency response is what stepping it does.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include <qr/core/chain/butterworth_design.hpp>
#include <tune/axis_model.hpp>
#include <tune/sensor_lowpass.hpp>

#include "closed_loop_flight.hpp"

namespace tune {
namespace {

TEST(TuneModel, SensorLowpassIsTheFirmwaresDesign) {
  for (double cutoff : {5.0, 20.0, 80.0, 240.0}) {
    for (double rate : {500.0, 1000.0}) {
      const qr::chain::ButterworthDesign firmware = qr::chain::design_butterworth(2, cutoff, rate);
      const Lowpass ours = butterworth_lowpass(cutoff, rate);
      ASSERT_TRUE(firmware.valid()) << cutoff << " Hz at " << rate;
      EXPECT_NEAR(ours.b0, firmware.b[0], 1e-12);
      EXPECT_NEAR(ours.b1, firmware.b[1], 1e-12);
      EXPECT_NEAR(ours.b2, firmware.b[2], 1e-12);
      EXPECT_NEAR(ours.a1, firmware.a[1], 1e-12);
      EXPECT_NEAR(ours.a2, firmware.a[2], 1e-12);
      // -3 dB at the cut-off, as the pre-warped design promises.
      const std::complex<double> z = std::polar(1.0, 2 * std::numbers::pi * cutoff / rate);
      EXPECT_NEAR(std::abs(ours.response(z)), std::sqrt(0.5), 1e-9);
    }
  }
  const Lowpass none = butterworth_lowpass(0, 1000);
  EXPECT_EQ(none.b0, 1.0);
  EXPECT_EQ(none.a1, 0.0);
}

// The sampled axis against the tests' own continuous integration (20 steps a period), on a
// moment that jumps every few periods: the rates at the samples agree.
TEST(TuneModel, SampledAxisIsTheContinuousAxisAtTheSamples) {
  for (const AxisModel truth : {AxisModel{0.18, 0.03, 0.0045, 0, 0, 0}, AxisModel{0.007, 0.04, 0.0031, 0.23, 0.8, 0}}) {
    test::FlightSetup open;  // no loop: every gain 0, the excitation alone
    open.truth = truth;
    open.yaw = truth.lead_s > 0;
    open.gains = {0, 0, 0, 0, 0, 0};
    open.gyro_noise = 0;
    open.disturbance = 0;
    open.filter_cutoff_hz = 0;
    open.seconds = 1;
    const test::Flight f = test::fly(open);
    SampledAxis axis(truth, 1000);
    double worst = 0, largest = 0;
    for (std::size_t k = 0; k + 1 < f.rate.size(); ++k) {
      axis.step(f.record.moment[k]);
      worst = std::max(worst, std::fabs(axis.rate() - f.rate[k + 1]));
      largest = std::max(largest, std::fabs(f.rate[k + 1]));
    }
    EXPECT_GT(largest, 0.05);
    EXPECT_LT(worst, 1e-3 * largest) << "gain " << truth.gain;
  }
}

// The response the margins read is the response the step simulation has: a sine of moment,
// stepped through the model until it settles, comes out with the amplitude and phase of
// response() (the integrator removed by differencing the rate, which response() gives as well).
TEST(TuneModel, FrequencyResponseIsWhatSteppingDoes) {
  const AxisModel model{0.18, 0.03, 0.0045, 0.1, 2.0, 0};  // damped, so a sine settles
  const double fs = 1000;
  for (double hz : {0.5, 2.0, 10.0, 40.0}) {  // whole cycles in the 8 s summed
    const double w = 2 * std::numbers::pi * hz;
    SampledAxis axis(model, fs);
    std::complex<double> in{}, out{};
    const int settle = 4000, n = 8000;
    for (int k = 0; k < settle + n; ++k) {
      const double m = std::sin(w * k / fs);
      axis.step(m);
      if (k >= settle) {
        const std::complex<double> e = std::polar(1.0, -w * k / fs);
        in += m * e;
        out += axis.rate() * e;  // the rate after this tick's moment: one period later
      }
    }
    // out / in is the response times z (the rate is read a period after the moment).
    const std::complex<double> measured = out / in / std::polar(1.0, w / fs);
    const std::complex<double> predicted = axis.response(w);
    EXPECT_NEAR(std::abs(measured) / std::abs(predicted), 1.0, 0.01) << hz << " Hz";
    EXPECT_NEAR(std::arg(measured / predicted), 0.0, 0.01) << hz << " Hz";
  }
}

}  // namespace
}  // namespace tune
