#include <tune/axis_fit.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>

#include <tune/sensor_lowpass.hpp>

namespace tune {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

constexpr double kSmoothingHz = 8;

// The measured side, computed once: the rate's change per second, smoothed.
struct Problem {
  const AxisRecord& record;
  Lowpass sensor, smoothing;
  std::vector<double> change;  // row k: (rate[k+1] - rate[k]) fs, smoothed
  std::vector<double> rate;    // row k: rate[k], smoothed (yaw's damping column)
  std::size_t first = 0;       // the first row fitted
};

struct Fit {
  double cost = kInfinity;  // sum of squared equation errors over the fitted rows
  double gain = 0, lead = 0, damping = 0, bias = 0;
};

// Least squares by the normal equations X'X beta = X'y of up to four columns, solved by
// elimination with partial pivoting; the squared error is then y'y - beta'X'y.
template <std::size_t N>
struct NormalEquations {
  std::array<std::array<double, N>, N> a{};
  std::array<double, N> b{};
  double yy = 0;

  void add(const std::array<double, N>& x, double y) {
    for (std::size_t i = 0; i < N; ++i) {
      for (std::size_t j = 0; j < N; ++j) a[i][j] += x[i] * x[j];
      b[i] += x[i] * y;
    }
    yy += y * y;
  }
  std::optional<std::array<double, N>> solve() const {
    auto m = a;
    auto v = b;
    for (std::size_t c = 0; c < N; ++c) {
      std::size_t pivot = c;
      for (std::size_t r = c + 1; r < N; ++r) {
        if (std::fabs(m[r][c]) > std::fabs(m[pivot][c])) pivot = r;
      }
      if (!(std::fabs(m[pivot][c]) > 0)) return std::nullopt;
      std::swap(m[c], m[pivot]);
      std::swap(v[c], v[pivot]);
      for (std::size_t r = c + 1; r < N; ++r) {
        const double f = m[r][c] / m[c][c];
        for (std::size_t k = c; k < N; ++k) m[r][k] -= f * m[c][k];
        v[r] -= f * v[c];
      }
    }
    std::array<double, N> x{};
    for (std::size_t c = N; c-- > 0;) {
      double s = v[c];
      for (std::size_t k = c + 1; k < N; ++k) s -= m[c][k] * x[k];
      x[c] = s / m[c][c];
    }
    return x;
  }
  double squared_error(const std::array<double, N>& beta) const {
    double e = yy;
    for (std::size_t i = 0; i < N; ++i) e -= beta[i] * b[i];
    return std::max(e, 0.0);
  }
};

// The best gain (yaw: lead and damping too) and disturbance for one lag and delay. Columns: the
// motors' mean moment, (yaw: their change, minus the rate,) 1; all through the sensor low-pass
// (the rate already is) and the smoothing.
template <std::size_t N>
Fit fit_linear(const Problem& p, double tau, double delay) {
  static_assert(N == 2 || N == 4);
  SampledAxis path(AxisModel{1, tau, delay, 0, 0, 0}, p.record.sample_hz);
  path.settle(p.record.moment.front());
  LowpassRun mean_sensor(p.sensor), mean_smooth(p.smoothing), change_sensor(p.sensor), change_smooth(p.smoothing);
  NormalEquations<N> eq;
  for (std::size_t k = 0; k < p.change.size(); ++k) {
    const SampledAxis::Increment inc = path.increment(p.record.moment[k]);
    const double mean = mean_smooth.step(mean_sensor.step(inc.mean));
    if constexpr (N == 4) {
      const double change = change_smooth.step(change_sensor.step(inc.change));
      if (k >= p.first) eq.add({mean, change, -p.rate[k], 1.0}, p.change[k]);
    } else {
      if (k >= p.first) eq.add({mean, 1.0}, p.change[k]);
    }
  }
  const auto beta = eq.solve();
  if (!beta) return {};
  Fit fit;
  fit.cost = eq.squared_error(*beta);
  fit.gain = (*beta)[0];
  fit.bias = (*beta)[N - 1];
  if constexpr (N == 4) {
    fit.lead = fit.gain != 0 ? (*beta)[1] / fit.gain : 0;
    fit.damping = (*beta)[2];
  }
  return fit;
}

Fit fit_at(const Problem& p, double tau, double delay) {
  return p.record.yaw ? fit_linear<4>(p, tau, delay) : fit_linear<2>(p, tau, delay);
}

struct Point {
  double log_tau, delay;
  Fit fit;
};

// A grid over log lag and delay, then a pattern search (the four axis steps and the four
// diagonals: lag and delay trade against each other along a ridge) halving its steps to 0.2 % of
// lag and 5 us of delay (about 300 evaluations of the least squares).
Point search(const Problem& p) {
  using B = FitBounds;
  const double lo = std::log(B::kMinTauS), hi = std::log(B::kMaxTauS);
  constexpr int kTauSteps = 11, kDelaySteps = 8;
  double du = (hi - lo) / kTauSteps, dd = B::kMaxDelayS / kDelaySteps;
  Point best{lo, 0, {}};
  for (int i = 0; i <= kTauSteps; ++i) {
    for (int j = 0; j <= kDelaySteps; ++j) {
      const double u = lo + i * du, d = j * dd;
      const Fit f = fit_at(p, std::exp(u), d);
      if (f.cost < best.fit.cost) best = {u, d, f};
    }
  }
  while (du > 2e-3 || dd > 5e-6) {
    bool moved = false;
    for (int su = -1; su <= 1; ++su) {
      for (int sd = -1; sd <= 1; ++sd) {
        if (su == 0 && sd == 0) continue;
        const double u = std::clamp(best.log_tau + su * du, lo, hi);
        const double d = std::clamp(best.delay + sd * dd, 0.0, B::kMaxDelayS);
        const Fit f = fit_at(p, std::exp(u), d);
        if (f.cost < best.fit.cost) {
          best = {u, d, f};
          moved = true;
        }
      }
    }
    if (!moved) {
      du /= 2;
      dd /= 2;
    }
  }
  return best;
}

std::string text(const char* format, double a, double b = 0) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, format, a, b);
  return buffer;
}

// Why the record cannot be fitted, before any fitting ("" if it can).
std::string record_problem(const AxisRecord& r, const Problem& p) {
  using B = FitBounds;
  if (r.moment.size() != r.rate.size()) return "the moment and the rate differ in length";
  for (std::size_t k = 0; k < r.moment.size(); ++k) {
    if (!std::isfinite(r.moment[k]) || !std::isfinite(r.rate[k])) return "a sample is not a number";
  }
  const double seconds = static_cast<double>(r.moment.size()) / r.sample_hz;
  if (seconds < B::kSettleS + B::kMinSeconds) {
    return text("the record is too short: %.2f s, the fit needs %.2f s", seconds, B::kSettleS + B::kMinSeconds);
  }
  // The excitation: the moment's slow part (what the vibration leaves out), about its mean.
  LowpassRun smooth(p.smoothing);
  double sum = 0, squares = 0, n = 0;
  for (std::size_t k = 0; k < r.moment.size(); ++k) {
    const double m = smooth.step(r.moment[k]);
    if (k < p.first) continue;
    sum += m;
    squares += m * m;
    n += 1;
  }
  const double spread = std::sqrt(std::max(0.0, squares / n - (sum / n) * (sum / n)));
  if (spread < B::kMinExcitation) {
    return text("no excitation: the moment moves by %.2f thrust units RMS, the fit needs %.0f", spread,
                B::kMinExcitation);
  }
  return "";
}

// Why the best fit is not a model of this axis ("" if it is): first whether the model explains
// the rate at all, then whether it does so the right way round, then whether the search's bounds
// held the answer.
std::string fit_problem(const Point& best, double residual) {
  using B = FitBounds;
  if (!(residual <= B::kMaxResidual)) {
    return text(
        "the model explains too little of the rate (residual %.2f, at most %.2f): too little excitation or too "
        "much noise",
        residual, B::kMaxResidual);
  }
  if (!(best.fit.gain > 0)) {
    return text("the rate turns against the moment (gain %.3g): a sign is wrong (the axis, or the IMU's mounting)",
                best.fit.gain);
  }
  const double tau = std::exp(best.log_tau);
  if (tau < B::kMinTauS * 1.01 || tau > B::kMaxTauS * 0.99) {
    return text(
        "the motor lag found (%.1f ms) is at the edge of the search (2-250 ms): the record does not show "
        "this model",
        tau * 1e3);
  }
  if (best.delay > B::kMaxDelayS * 0.99) {
    return text("the delay found (%.1f ms) is at the edge of the search (up to 80 ms)", best.delay * 1e3);
  }
  return "";
}

}  // namespace

std::optional<AxisModel> fit_axis(const AxisRecord& record, std::string* why_not) {
  const auto refuse = [&](const std::string& why) -> std::optional<AxisModel> {
    if (why_not != nullptr) *why_not = why;
    return std::nullopt;
  };
  if (!(record.sample_hz > 0) || !std::isfinite(record.sample_hz)) {
    return refuse("the sample rate is not a positive number");
  }
  Problem p{record,
            butterworth_lowpass(record.filter_cutoff_hz, record.sample_hz),
            butterworth_lowpass(kSmoothingHz, record.sample_hz),
            {},
            {},
            0};
  p.first = static_cast<std::size_t>(FitBounds::kSettleS * record.sample_hz);
  const std::string problem = record_problem(record, p);
  if (!problem.empty()) return refuse(problem);

  LowpassRun smooth_change(p.smoothing), smooth_rate(p.smoothing);
  p.change.resize(record.rate.size() - 1);
  p.rate.resize(record.rate.size() - 1);
  for (std::size_t k = 0; k + 1 < record.rate.size(); ++k) {
    p.change[k] = smooth_change.step((record.rate[k + 1] - record.rate[k]) * record.sample_hz);
    p.rate[k] = smooth_rate.step(record.rate[k]);
  }
  const Point best = search(p);

  double sum = 0, squares = 0, n = 0;
  for (std::size_t k = p.first; k < p.change.size(); ++k) {
    sum += p.change[k];
    squares += p.change[k] * p.change[k];
    n += 1;
  }
  const double variance = squares - sum * sum / n;
  const double residual = variance > 0 ? std::sqrt(best.fit.cost / variance) : kInfinity;
  const std::string bad_fit = fit_problem(best, residual);
  if (!bad_fit.empty()) return refuse(bad_fit);
  return AxisModel{best.fit.gain, std::exp(best.log_tau), best.delay, best.fit.lead, best.fit.damping, residual};
}

}  // namespace tune
