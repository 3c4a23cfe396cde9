#include <pc/core/battery_gauge.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include <common/battery_rest.hpp>

namespace qrterm {
namespace {

// A LiPo cell's charge against its resting voltage: the chart RC battery vendors publish, here
// its 1S column as Ampow gives it ("LiPo Voltage Chart", blog.ampow.com/lipo-voltage-chart: 4.20 V
// full, a flat 3.7-3.9 V middle, 3.27 V empty after the rebound from a 3.0 V cut-off). The
// simulator's pack (sim/battery.cpp) follows the same chart at every tenth. Linear between points.
struct CellPoint {
  double volts;
  double percent;
};
constexpr CellPoint kCellChart[] = {
    {3.27, 0},  {3.61, 5},  {3.69, 10}, {3.71, 15}, {3.73, 20}, {3.75, 25}, {3.77, 30},
    {3.79, 35}, {3.80, 40}, {3.82, 45}, {3.84, 50}, {3.85, 55}, {3.87, 60}, {3.91, 65},
    {3.95, 70}, {3.98, 75}, {4.02, 80}, {4.08, 85}, {4.11, 90}, {4.15, 95}, {4.20, 100},
};

std::string minutes_text(double seconds) {
  const long s = std::lround(seconds);
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

// The charge's fall, per cent a second, by least squares over the samples (positive: falling).
double fall_rate(const std::deque<ChargeSample>& samples) {
  const double n = static_cast<double>(samples.size());
  double mean_t = 0, mean_p = 0;
  for (const ChargeSample& s : samples) {
    mean_t += s.t_s / n;
    mean_p += s.percent / n;
  }
  double tp = 0, tt = 0;
  for (const ChargeSample& s : samples) {
    tp += (s.t_s - mean_t) * (s.percent - mean_p);
    tt += (s.t_s - mean_t) * (s.t_s - mean_t);
  }
  return tt > 0 ? -tp / tt : 0.0;
}

}  // namespace

double lipo_charge_percent(double cell_volts) {
  if (cell_volts <= kCellChart[0].volts) return 0;
  for (size_t i = 1; i < std::size(kCellChart); ++i) {
    const CellPoint& hi = kCellChart[i];
    if (cell_volts <= hi.volts) {
      const CellPoint& lo = kCellChart[i - 1];
      return lo.percent + (hi.percent - lo.percent) * (cell_volts - lo.volts) / (hi.volts - lo.volts);
    }
  }
  return 100;
}

int count_cells(uint16_t resting_mv) {
  return std::clamp((resting_mv + kHighestCellMv - 1) / kHighestCellMv, 1, kMaxCells);
}

void BatteryGauge::link_up() {
  mean_mv_.reset();
  samples_.clear();
  cells_ = 0;
  running_ = false;
  settled_s_ = 0;
}

void BatteryGauge::on_report(uint16_t measured_mv, const uint16_t (&engines)[4], uint16_t sag_mv, double now_s) {
  const double rested = wire::battery_rested_mv(measured_mv, engines, sag_mv);
  if (!mean_mv_) {
    mean_mv_ = rested;
    cells_ = given_cells_ > 0 ? given_cells_ : count_cells(static_cast<uint16_t>(rested));
  } else {
    // The QR's first-order mean, on reports that come a few times a second.
    const double alpha = 1.0 - std::exp(-std::max(0.0, now_s - last_s_) / kRestingMeanS);
    *mean_mv_ += alpha * (rested - *mean_mv_);
  }
  last_s_ = now_s;
  const bool running = (engines[0] | engines[1] | engines[2] | engines[3]) != 0;
  if (running != running_) {
    running_ = running;
    settled_s_ = now_s + kLoadSettleS;
    samples_.clear();
  }
  const double percent = lipo_charge_percent(*mean_mv_ / 1000.0 / cells_);
  if (samples_.empty() || now_s >= settled_s_) samples_.push_back({now_s, percent});
  else samples_.back() = {now_s, percent};  // the charge now, but no fall measured yet
  while (samples_.front().t_s < now_s - kChargeWindowS) samples_.pop_front();
}

std::optional<BatteryReading> BatteryGauge::reading(uint16_t panic_mv) const {
  if (!mean_mv_) return std::nullopt;
  BatteryReading r;
  r.cells = cells_;
  r.resting_v = *mean_mv_ / 1000.0;
  r.percent = samples_.back().percent;
  r.panic_percent = lipo_charge_percent(panic_mv / 1000.0 / cells_);
  const double span = samples_.back().t_s - samples_.front().t_s;
  if (span >= kChargeMinSpanS) {
    const double rate = fall_rate(samples_);
    if (rate * span >= kChargeMinFall) r.seconds_left = std::max(0.0, (r.percent - r.panic_percent) / rate);
  }
  r.near_panic = r.percent - r.panic_percent <= kNearPanicPoints || (r.seconds_left && *r.seconds_left <= kNearPanicS);
  return r;
}

std::string BatteryGauge::notice(uint16_t panic_mv) {
  const std::optional<BatteryReading> r = reading(panic_mv);
  if (!r) return "";
  if (!r->near_panic) {
    // Well above the warning again: a fresh pack, which gets its own warning.
    if (r->percent > r->panic_percent + kNearPanicPoints + 5) warned_ = false;
    return "";
  }
  if (warned_) return "";
  warned_ = true;
  char panic[64];
  std::snprintf(panic, sizeof panic, "%.2f V, %.0f %%", panic_mv / 1000.0, r->panic_percent);
  return "battery " + charge_text(*r) + ": near the QR's panic level (" + panic + "), land";
}

std::string charge_text(const BatteryReading& reading) {
  char text[64];
  std::snprintf(text, sizeof text, "%dS %.0f %% %s left", reading.cells, reading.percent,
                reading.seconds_left ? minutes_text(*reading.seconds_left).c_str() : "--");
  return text;
}

}  // namespace qrterm
