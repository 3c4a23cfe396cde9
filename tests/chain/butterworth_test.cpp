// The Butterworth designs and filters: the design code against the closed form and published
// values, every entry of the flight tables against the analytic Butterworth response, and the
// Q filter against the double filter on long random and recorded inputs, within a bound computed
// for each filter (not a tolerance picked to pass).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <qr/core/chain/butterworth_table.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/sensor_calibration.hpp>
#include <qr/core/chain/sensor_units.hpp>
#include <qr/host/real_numbers.hpp>
#include <qr/tools/filter_response.hpp>

#include "chain_test_support.hpp"
#include "synthetic_flight.hpp"

namespace qr::chain {
namespace {

using Signal = FixedNumbers::Rate;              // Q<27>, what the gyro filters carry
using Coefficient = FixedNumbers::Coefficient;  // Q<30>
constexpr double kSignalLsb = 0x1p-27;
constexpr double kRadPerSecPerCount = 1.0 / sensor::kGyroCountsPerRadPerSec;

TEST(Butterworth, DesignMatchesPublishedValues) {
  // butter(2, 0.2) and butter(1, 0.2) (cut-off at 0.1 fs), as MATLAB and SciPy print them to
  // four decimals: b = [0.0675 0.1349 0.0675], a = [1 -1.1430 0.4128]; b = [0.2452 0.2452],
  // a = [1 -0.5095].
  const ButterworthDesign d2 = design_butterworth(2, 100, 1000);
  EXPECT_NEAR(d2.b[0], 0.0675, 5e-5);
  EXPECT_NEAR(d2.b[1], 0.1349, 5e-5);
  EXPECT_NEAR(d2.b[2], 0.0675, 5e-5);
  EXPECT_EQ(d2.a[0], 1.0);
  EXPECT_NEAR(d2.a[1], -1.1430, 5e-5);
  EXPECT_NEAR(d2.a[2], 0.4128, 5e-5);
  const ButterworthDesign d1 = design_butterworth(1, 100, 1000);
  EXPECT_NEAR(d1.b[0], 0.2452, 5e-5);
  EXPECT_NEAR(d1.b[1], 0.2452, 5e-5);
  EXPECT_NEAR(d1.a[1], -0.5095, 5e-5);
  EXPECT_EQ(d1.b[2], 0.0);
  EXPECT_EQ(d1.a[2], 0.0);
}

TEST(Butterworth, DesignMatchesTheClosedFormWithLibmTan) {
  double worst = 0;
  for (double ratio = 0.0005; ratio < 0.4999; ratio += 0.0007) {
    const double k = std::tan(std::numbers::pi * ratio);
    const double den = 1 + std::numbers::sqrt2 * k + k * k;
    const double expected2[5] = {k * k / den, 2 * k * k / den, k * k / den, 2 * (k * k - 1) / den,
                                 (1 - std::numbers::sqrt2 * k + k * k) / den};
    const ButterworthDesign d = design_butterworth(2, ratio * 1000, 1000);
    const double got2[5] = {d.b[0], d.b[1], d.b[2], d.a[1], d.a[2]};
    for (int i = 0; i < 5; ++i) worst = std::max(worst, std::fabs(got2[i] - expected2[i]));
    const ButterworthDesign d1 = design_butterworth(1, ratio * 1000, 1000);
    worst = std::max(worst, std::fabs(d1.b[0] - k / (1 + k)));
    worst = std::max(worst, std::fabs(d1.a[1] - (k - 1) / (k + 1)));
  }
  std::printf("  design vs closed form with std::tan: max difference %.3e\n", worst);
  EXPECT_LE(worst, 1e-13);
}

// Over the arguments the designs use, pi fc / fs for fc/fs up to 249/500. (Nearer pi/2, tan is
// ill-conditioned: pi/2 - x itself loses digits to the rounding of pi/2 in double.)
TEST(Butterworth, ConstexprTanMatchesLibm) {
  double worst = 0;
  for (int i = 1; i <= 20000; ++i) {
    const double x = std::numbers::pi * 0.498 * i / 20000;
    worst = std::max(worst, std::fabs(design::tan_first_quadrant(x) / std::tan(x) - 1));
  }
  std::printf("  constexpr tan vs std::tan on (0, 0.498 pi]: max relative difference %.3e\n", worst);
  EXPECT_LE(worst, 2e-14);
}

TEST(Butterworth, BadArgumentsGiveNoDesign) {
  EXPECT_FALSE(design_butterworth(3, 10, 1000).valid());
  EXPECT_FALSE(design_butterworth(0, 10, 1000).valid());
  EXPECT_FALSE(design_butterworth(2, 500, 1000).valid());
  EXPECT_FALSE(design_butterworth(2, 0, 1000).valid());
  EXPECT_FALSE(design_butterworth(2, 10, 0).valid());
  EXPECT_FALSE(design_butterworth(2, std::nan(""), 1000).valid());
  EXPECT_TRUE(design_butterworth(2, 499.9, 1000).valid());
}

// Every entry of a flight table: stored integers equal the quantised design, sum(b) == sum(a)
// (DC gain exactly 1), and the response of the stored coefficients follows the analytic
// Butterworth magnitude, -3.01 dB at the cut-off. Checked at f = 0 (exactly 0 dB), in the pass
// band and transition (fc/10 .. 2 fc) in dB, and in the stop band (0.45 fs) as an absolute
// difference of |H|: there the gain is down to -130 dB, and the quantised b1 that fixes the DC
// gain moves the zeros at fs/2 by about one lsb, which is a large share of a tiny number.
struct ResponseLimits {
  double pass_db;      // |gain_q - analytic| for fc/10 <= f <= 2 fc
  double at_fc_db;     // |gain_q(fc) + 3.0103|
  double stop_linear;  // ||H_q| - |H_analytic|| at 0.45 fs
};

template <int Order, uint32_t Fs>
void check_table(const ResponseLimits& limits) {
  using Table = ButterworthTable<Coefficient, Order, Fs>;
  using Range = typename Table::Range;
  double worst_pass = 0, worst_at_fc = 0, worst_stop = 0, worst_design_db = 0, worst_dc = 0;
  double worst_pass_fc = 0;
  for (int32_t fc = Range::kLowestHz; fc <= Range::kHighestHz; ++fc) {
    const ButterworthDesign d = design_butterworth(Order, fc, Fs);
    const QuantisedDesign q = quantise(d, Coefficient::frac_bits);
    const auto& stored = Table::for_cutoff(fc);
    ASSERT_EQ(stored.b0.raw(), q.b[0]);
    ASSERT_EQ(stored.b1.raw(), q.b[1]);
    ASSERT_EQ(stored.a1.raw(), q.a[1]);
    if constexpr (Order == 2) {
      ASSERT_EQ(stored.b2().raw(), q.b[2]);
      ASSERT_EQ(stored.a2.raw(), q.a[2]);
    }
    ASSERT_EQ(q.b[0] + q.b[1] + q.b[2], q.a[0] + q.a[1] + q.a[2]) << "DC gain of " << fc << " Hz";
    worst_dc = std::max(worst_dc, std::fabs(response_of(q, 0, Fs).gain_db));
    for (const double f : {fc / 10.0, fc / 2.0, fc * 0.9, double(fc), fc * 1.1, std::min(2.0 * fc, 0.49 * Fs)}) {
      const double analytic = analytic_butterworth_gain_db(Order, fc, Fs, f);
      const double error = std::fabs(response_of(q, f, Fs).gain_db - analytic);
      if (error > worst_pass) {
        worst_pass = error;
        worst_pass_fc = fc;
      }
      worst_design_db = std::max(worst_design_db, std::fabs(response_of(d, f, Fs).gain_db - analytic));
    }
    worst_at_fc = std::max(worst_at_fc, std::fabs(response_of(q, fc, Fs).gain_db + 10 * std::log10(2.0)));
    const double f_stop = 0.45 * Fs;
    const double stop_q = std::pow(10, response_of(q, f_stop, Fs).gain_db / 20);
    const double stop_analytic = std::pow(10, analytic_butterworth_gain_db(Order, fc, Fs, f_stop) / 20);
    worst_stop = std::max(worst_stop, std::fabs(stop_q - stop_analytic));
  }
  std::printf(
      "  order %d at %u Hz, %zu cut-offs: design vs analytic %.2e dB; Q<30>: DC %.1e dB, "
      "fc/10..2fc within %.2e dB of analytic (worst at fc = %g Hz), at fc -3.0103 dB within %.2e dB, "
      "|H| at 0.45 fs within %.2e\n",
      Order, static_cast<unsigned>(Fs), Range::kSize, worst_design_db, worst_dc, worst_pass, worst_pass_fc, worst_at_fc,
      worst_stop);
  EXPECT_LE(worst_design_db, 1e-9);
  EXPECT_LE(worst_dc, 1e-12);
  EXPECT_LE(worst_pass, limits.pass_db);
  EXPECT_LE(worst_at_fc, limits.at_fc_db);
  EXPECT_LE(worst_stop, limits.stop_linear);
}

TEST(Butterworth, EveryFlightDesignHasTheAnalyticResponseAt1kHz) {
  check_table<1, 1000>({1e-6, 1e-6, 1e-9});
  check_table<2, 1000>({2e-5, 1e-5, 2e-9});
}

TEST(Butterworth, EveryFlightDesignHasTheAnalyticResponseAt500Hz) {
  check_table<1, 500>({1e-6, 1e-6, 1e-9});
  check_table<2, 500>({1e-3, 1e-4, 3e-8});
}

TEST(Butterworth, TableCoversTheParameterRangeBelowNyquist) {
  EXPECT_EQ((CutoffRange<1000>::kHighestHz), 250);
  EXPECT_EQ((CutoffRange<500>::kHighestHz), 249);
  using Table = ButterworthTable<Coefficient, 2, 500>;
  EXPECT_EQ(Table::cutoff_used(0), 1);
  EXPECT_EQ(Table::cutoff_used(-5), 1);
  EXPECT_EQ(Table::cutoff_used(20), 20);
  EXPECT_EQ(Table::cutoff_used(250), 249);
  EXPECT_EQ(&Table::for_cutoff(1000), &Table::for_cutoff(249));
}

// A settled filter fed its own input holds it exactly: with sum(b) == sum(a) in integers the
// input is a fixed point of the Q recursion, for every entry.
TEST(Butterworth, SettledFilterHoldsItsInputExactly) {
  using Table = ButterworthTable<Coefficient, 2, 1000>;
  for (int32_t fc = 1; fc <= 250; ++fc) {
    for (const double v : {-8.3, -1.0, 0.0, 0.123456789, 3.5}) {
      const Signal x = test::quantise<Signal>(v);
      ButterworthLowpass<Signal, Coefficient, 2> f(Table::for_cutoff(fc));
      f.settle(x);
      for (int n = 0; n < 50; ++n) ASSERT_EQ(f.step(x), x) << fc << " Hz, " << v;
    }
  }
}

// The filter keeps what the rounding dropped in 32 bits (it is under half an output lsb in the
// sum's units). The error-feedback step written with the whole 64-bit residual, as it was, must
// give the same outputs bit for bit on the flight's inputs at their extremes: full-scale gyro
// counts at random and full-scale steps (the largest overshoot), every cut-off, both orders.
template <int Order>
class WideResidualLowpass {
  using Iir = IirOfOrder<Order>;

 public:
  using Coefficients = typename Iir::template Coefficients<Coefficient>;
  explicit WideResidualLowpass(const Coefficients& c) : c_(c) {}
  void settle(Signal x) {
    Iir::settle(state_, x);
    residual_ = {};
  }
  Signal step(Signal x) {
    const auto sum = Iir::sum(state_, c_, x) + residual_;
    const Signal y = fx::narrow<Signal>(sum);
    residual_ = sum - fx::mul_wide(Coefficient(1.0), y);
    Iir::shift(state_, x, y);
    return y;
  }

 private:
  const Coefficients& c_;
  typename Iir::template State<Signal> state_{};
  decltype(fx::mul_wide(Coefficient{}, Signal{})) residual_{};
};

template <int Order>
void check_narrow_residual_is_exact() {
  using Table = ButterworthTable<Coefficient, Order, 1000>;
  using Units = SensorUnits<FixedNumbers>;
  std::mt19937 random(13);
  std::uniform_int_distribution<int32_t> counts(INT16_MIN, INT16_MAX);
  for (int32_t fc = 1; fc <= 250; ++fc) {
    ButterworthLowpass<Signal, Coefficient, Order> filter(Table::for_cutoff(fc));
    WideResidualLowpass<Order> wide(Table::for_cutoff(fc));
    filter.settle(Signal{});
    wide.settle(Signal{});
    for (int n = 0; n < 4000; ++n) {
      // Full-scale steps every 500 samples for the first half, full-scale noise after.
      const int32_t c = n < 2000 ? ((n / 500) % 2 == 0 ? INT16_MAX : INT16_MIN) : counts(random);
      const Signal x = Units::rate_of(c);
      ASSERT_EQ(filter.step(x).raw(), wide.step(x).raw()) << "order " << Order << ", " << fc << " Hz, sample " << n;
    }
  }
}

TEST(Butterworth, NarrowResidualGivesTheWideResidualsOutputs) {
  check_narrow_residual_is_exact<1>();
  check_narrow_residual_is_exact<2>();
}

// Impulse response of B/A (or of 1/A with b = {1}), until it has died out.
std::vector<double> impulse_response(const double (&b)[3], const double (&a)[3]) {
  std::vector<double> h;
  double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  for (int n = 0; n < 2000000; ++n) {
    const double x = n == 0 ? 1.0 : 0.0;
    const double y = b[0] * x + b[1] * x1 + b[2] * x2 - a[1] * y1 - a[2] * y2;
    h.push_back(y);
    x2 = x1;
    x1 = x;
    y2 = y1;
    y1 = y;
    if (n > 100 && std::fabs(y1) + std::fabs(y2) < 1e-20) break;
  }
  return h;
}

struct Bound {
  double rounding;      // 1/2 lsb x sum |h_E|: narrow()'s rounding through the error path
  double coefficients;  // sum |h_q - h| x max |x|: the quantised filter against the designed one
};

Bound bound_for(const ButterworthDesign& d, const QuantisedDesign& q, double max_input) {
  double bq[3], aq[3];
  for (int i = 0; i < 3; ++i) {
    bq[i] = std::ldexp(static_cast<double>(q.b[i]), -q.frac_bits);
    aq[i] = std::ldexp(static_cast<double>(q.a[i]), -q.frac_bits);
  }
  // The filter feeds its rounding error back (butterworth_lowpass.hpp): the error reaches the
  // output through (1 - z^-1) / A(z).
  const double shaped[3] = {1, -1, 0};
  double sum_ha = 0;
  for (const double v : impulse_response(shaped, aq)) sum_ha += std::fabs(v);
  const std::vector<double> hq = impulse_response(bq, aq), h = impulse_response(d.b, d.a);
  double sum_dh = 0;
  for (size_t n = 0; n < std::max(hq.size(), h.size()); ++n) {
    sum_dh += std::fabs((n < hq.size() ? hq[n] : 0.0) - (n < h.size() ? h[n] : 0.0));
  }
  // The double reference's own rounding: far below either term, 1e-12 covers it.
  return {0.5 * kSignalLsb * sum_ha + 1e-12, sum_dh * max_input};
}

// Long inputs: a step, a chirp through the cut-off, full-scale noise, and the recorded (synthetic)
// roll gyro stream, all in rad/s within the gyro's full scale.
std::vector<double> long_input() {
  std::vector<double> x;
  for (int n = 0; n < 3000; ++n) x.push_back(n < 100 ? 0.0 : 5.0);
  for (int n = 0; n < 20000; ++n) {
    const double f = 0.5 + 300.0 * n / 20000;  // Hz at 1 kHz
    x.push_back(3.0 * std::sin(2 * std::numbers::pi * f * n / 1000.0));
  }
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> noise(-8.5, 8.5);
  for (int n = 0; n < 30000; ++n) x.push_back(noise(rng));
  synthetic::Flight<1000> flight;
  for (uint32_t n = 0; n < synthetic::Flight<1000>::kTicks; ++n) {
    x.push_back(flight.next().sample.gyro[0] * kRadPerSecPerCount);
  }
  for (int n = 0; n < 5000; ++n) x.push_back(-2.0);  // settle
  return x;
}

template <int Order>
void check_fixed_against_double(const std::vector<double>& input) {
  double max_input = 0;
  for (const double v : input) max_input = std::max(max_input, std::fabs(v));
  for (const int fc : {1, 2, 5, 10, 20, 50, 100, 250}) {
    const ButterworthDesign d = design_butterworth(Order, fc, 1000);
    const QuantisedDesign q = quantise(d, Coefficient::frac_bits);
    const auto qc = coefficients_of<Coefficient, Order>(d);
    const auto dc = coefficients_of<double, Order>(d);
    // The same quantised coefficients in double: isolates the rounding of the Q arithmetic.
    typename IirOfOrder<Order>::template Coefficients<double> same;
    if constexpr (Order == 1) {
      same = {qc.b0.to_double(), qc.b1.to_double(), qc.a1.to_double()};
    } else {
      same = {qc.b0.to_double(), qc.b1.to_double(), qc.a1.to_double(), qc.a2.to_double()};
    }
    ButterworthLowpass<Signal, Coefficient, Order> fq(qc);
    ButterworthLowpass<double, double, Order> fd(dc), fs(same);
    test::MaxError vs_design("order " + std::to_string(Order) + ", " + std::to_string(fc) +
                             " Hz: Q<27>/Q<30> vs double design");
    test::MaxError vs_same("order " + std::to_string(Order) + ", " + std::to_string(fc) +
                           " Hz: Q<27>/Q<30> vs double, same coefficients");
    for (size_t n = 0; n < input.size(); ++n) {
      const Signal x = test::quantise<Signal>(input[n]);
      const double yq = fq.step(x).to_double();
      vs_design.add(yq - fd.step(x.to_double()), static_cast<double>(n));
      vs_same.add(yq - fs.step(x.to_double()), static_cast<double>(n));
    }
    const Bound b = bound_for(d, q, max_input);
    vs_same.print(b.rounding, " rad/s");
    vs_design.print(b.rounding + b.coefficients, " rad/s");
    std::printf("    = %.2e gyro counts (rounding bound %.2e, coefficient bound %.2e counts)\n",
                vs_design.max() / kRadPerSecPerCount, b.rounding / kRadPerSecPerCount,
                b.coefficients / kRadPerSecPerCount);
    EXPECT_LE(vs_same.max(), b.rounding);
    EXPECT_LE(vs_design.max(), b.rounding + b.coefficients);
    // The figures docs/signal-chain.md states: against the design, within 0.005 of a gyro count
    // at every cut-off; the rounding alone within 1 lsb of Q<27> for order 1 (its error path
    // (1 - z^-1)/(1 - r z^-1) sums to 2), and within the computed bound for order 2 (printed in
    // lsb here: 76 at 1 Hz, 4.2 at 20 Hz, 1.2 at 250 Hz).
    std::printf("    rounding: %.2f lsb of Q<27> (bound %.2f lsb)\n", vs_same.max() / kSignalLsb,
                b.rounding / kSignalLsb);
    EXPECT_LE(vs_design.max(), 0.005 * kRadPerSecPerCount);
    if (Order == 1) EXPECT_LE(vs_same.max(), 1 * kSignalLsb);
  }
}

TEST(Butterworth, FirstOrderFixedFollowsDoubleWithinTheBound) { check_fixed_against_double<1>(long_input()); }
TEST(Butterworth, SecondOrderFixedFollowsDoubleWithinTheBound) { check_fixed_against_double<2>(long_input()); }

// The accelerometer's filters fold their outer taps into b0 (x + x2) (ButterworthStage): the
// same outputs as the five products, bit for bit, at the accelerometer's full scale (steps between
// its extremes, the largest overshoot, then full-scale noise) at every cut-off. The gyro's full
// scale is too wide for the fold: its filters keep the five products, and folding there would
// change outputs (x + x2 wraps), which the last part shows.
TEST(Butterworth, FoldedOuterTapsGiveTheSameOutputsWhereTheInputAllowsIt) {
  using Units = SensorUnits<FixedNumbers>;
  using Table = ButterworthTable<Coefficient, 2, 1000>;
  constexpr int64_t kAccelBound = -int64_t{Units::accel_of(INT16_MIN).raw()};
  constexpr int64_t kGyroBound = -int64_t{Units::rate_of(INT16_MIN).raw()};
  using Folded = ButterworthStage<Signal, Coefficient, 2, kAccelBound>;
  using Plain = ButterworthStage<Signal, Coefficient, 2>;
  static_assert(Folded::kFoldOuterTaps && !Plain::kFoldOuterTaps);
  static_assert(!ButterworthStage<Signal, Coefficient, 2, kGyroBound>::kFoldOuterTaps);
  static_assert(!ButterworthStage<double, double, 2, kAccelBound>::kFoldOuterTaps, "double is the reference");
  std::mt19937 random(17);
  std::uniform_int_distribution<int32_t> counts(INT16_MIN, INT16_MAX);
  bool gyro_scale_differs = false;
  for (int32_t fc = 1; fc <= 250; ++fc) {
    const auto& c = Table::for_cutoff(fc);
    Folded folded, gyro_folded;
    Plain plain, gyro_plain;
    for (int n = 0; n < 4000; ++n) {
      const int32_t count = n < 2000 ? ((n / 250) % 2 == 0 ? INT16_MAX : INT16_MIN) : counts(random);
      const Signal x = Units::accel_of(count);
      ASSERT_EQ(folded.step(c, x).raw(), plain.step(c, x).raw()) << fc << " Hz, sample " << n;
      const Signal r = Units::rate_of(count);
      gyro_scale_differs |= gyro_folded.step(c, r).raw() != gyro_plain.step(c, r).raw();
    }
  }
  EXPECT_TRUE(gyro_scale_differs);
}

// Both count scales are a whole number of Q<27> lsb for raw counts (1/8192 g is 2^14, the gyro's
// 572224 / 2^31 rad/s is 35764), and rate_of / accel_of multiply by that number in 32 bits: the
// same value as the rounded 64-bit product for every count, and for the calibration's sums
// (kCalibrationShift fractional bits, where the gyro's scale is not whole and the product stays)
// across the range 512 samples can add up to.
TEST(SensorUnits, ScalingByAWholeNumberIsTheProduct) {
  using Units = SensorUnits<FixedNumbers>;
  using Rate = FixedNumbers::Rate;
  using Accel = FixedNumbers::Accel;
  static_assert(Units::kRadPerSecPerCount.raw() % 16 == 0 && Units::kGPerCount.raw() % 16 == 0,
                "the flight's scales are whole numbers of Q<27> lsb (the test would still hold, unexercised)");
  for (int32_t count = INT16_MIN; count <= INT16_MAX; ++count) {
    const auto c = fx::Q<0>::from_raw(count);
    ASSERT_EQ(Units::rate_of(count).raw(), (product<Rate>(c, Units::kRadPerSecPerCount).raw())) << count;
    ASSERT_EQ(Units::accel_of(count).raw(), (product<Accel>(c, Units::kGPerCount).raw())) << count;
  }
  std::mt19937 random(19);
  std::uniform_int_distribution<int32_t> sums(INT16_MIN * 512, INT16_MAX * 512);
  for (int n = 0; n < 100000; ++n) {
    const int32_t sum = n < 2 ? (n == 0 ? INT16_MIN * 512 : INT16_MAX * 512) : sums(random);
    const auto c = fx::Q<kCalibrationShift>::from_raw(sum);
    ASSERT_EQ(Units::rate_of<kCalibrationShift>(sum).raw(), (product<Rate>(c, Units::kRadPerSecPerCount).raw())) << sum;
    ASSERT_EQ(Units::accel_of<kCalibrationShift>(sum).raw(), (product<Accel>(c, Units::kGPerCount).raw())) << sum;
  }
}

}  // namespace
}  // namespace qr::chain
