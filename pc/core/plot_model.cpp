#include <pc/core/plot_model.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace qrterm {
namespace {

// Samples older than the longest window, and a little, are let go.
constexpr double kKeepS = kPlotWindowsS[std::size(kPlotWindowsS) - 1] + 1;

// The observable each truth series is drawn over, with the unit both are in (TrueState's order).
struct TruthOver {
  const char* name;
  const char* unit;
};
constexpr TruthOver kTruthOver[] = {
    {"phi", "rad"}, {"theta", "rad"}, {"psi", "rad"}, {"height", "m"}, {"climb", "m/s"}};

}  // namespace

bool PlotModel::add(uint8_t id, const ObservableRow& row) {
  if (traces_.size() >= kMaxTraces) return false;
  for (const Trace& t : traces_) {
    if (t.id == id) return false;
  }
  traces_.push_back(Trace{id, row.name, row.unit, {}});
  return true;
}

void PlotModel::remove_last() {
  if (!traces_.empty()) traces_.pop_back();
}

std::vector<uint8_t> PlotModel::ids() const {
  std::vector<uint8_t> ids;
  for (const Trace& t : traces_) ids.push_back(t.id);
  return ids;
}

uint16_t PlotModel::divider(uint16_t control_hz) const {
  const uint32_t d = control_hz / rate_hz();
  return static_cast<uint16_t>(std::clamp<uint32_t>(d, 1, 65535));
}

std::vector<std::string> PlotModel::units() const {
  std::vector<std::string> units;
  for (const Trace& t : traces_) {
    if (std::find(units.begin(), units.end(), t.unit) == units.end()) units.push_back(t.unit);
  }
  return units;
}

std::pair<double, double> PlotModel::scale(double now_s, const std::string& unit) const {
  if (fixed_) {
    if (const auto found = fixed_ranges_.find(unit); found != fixed_ranges_.end()) return found->second;
  }
  const double end = view_end_s(now_s);
  const double begin = end - window_s();
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  const auto take = [&](const std::deque<PlotPoint>& points) {
    for (const PlotPoint& p : points) {
      if (p.t_s < begin || p.t_s > end) continue;
      low = std::min(low, p.value);
      high = std::max(high, p.value);
    }
  };
  for (const Trace& t : traces_) {
    if (t.unit != unit) continue;
    take(t.points);
    if (const auto* truth = truth_for(t)) take(*truth);
  }
  if (!(low <= high)) return {-1, 1};
  // A flat trace still gets a visible band; a little room above and below the extremes.
  const double span = std::max(high - low, std::max(std::fabs(high), std::fabs(low)) * 0.1 + 1e-3);
  const double middle = (high + low) / 2;
  return {middle - span * 0.55, middle + span * 0.55};
}

void PlotModel::toggle_scale(double now_s) {
  fixed_ranges_.clear();
  if (!fixed_) {
    for (const std::string& unit : units()) fixed_ranges_[unit] = scale(now_s, unit);
  }
  fixed_ = !fixed_;
}

void PlotModel::zoom(double factor, double now_s) {
  if (!fixed_) toggle_scale(now_s);
  for (const std::string& unit : units()) {
    const auto [low, high] = scale(now_s, unit);  // a unit picked since the toggle: its fitted range
    const double middle = (low + high) / 2;
    const double half = (high - low) / 2 * factor;
    fixed_ranges_[unit] = {middle - half, middle + half};
  }
}

void PlotModel::toggle_freeze(double now_s) {
  if (frozen_at_) {
    frozen_at_.reset();
  } else {
    frozen_at_ = now_s;
  }
}

void PlotModel::trim(std::deque<PlotPoint>& points, double now_s) const {
  // While frozen nothing the screen shows is let go.
  const double oldest = (frozen_at_ ? std::min(*frozen_at_, now_s) - window_s() : now_s) - kKeepS;
  while (!points.empty() && points.front().t_s < oldest) points.pop_front();
}

void PlotModel::add_sample(double t_s, const std::vector<double>& values) {
  for (size_t i = 0; i < traces_.size() && i < values.size(); ++i) {
    traces_[i].points.push_back({t_s, values[i]});
    trim(traces_[i].points, t_s);
  }
}

void PlotModel::clear_points() {
  for (Trace& t : traces_) t.points.clear();
}

void PlotModel::add_truth(double t_s, const TrueState& truth) {
  const double values[] = {truth.roll, truth.pitch, truth.yaw, truth.height, truth.climb};
  static_assert(std::size(values) == std::size(kTruthOver) && std::size(values) == std::extent_v<decltype(truth_)>);
  for (size_t i = 0; i < std::size(values); ++i) {
    if (!std::isfinite(values[i])) continue;  // not in this truth line
    truth_[i].push_back({t_s, values[i]});
    trim(truth_[i], t_s);
  }
}

const std::deque<PlotPoint>* PlotModel::truth_for(const Trace& trace) const {
  for (size_t i = 0; i < std::size(kTruthOver); ++i) {
    if (trace.name == kTruthOver[i].name && trace.unit == kTruthOver[i].unit && !truth_[i].empty()) return &truth_[i];
  }
  return nullptr;
}

}  // namespace qrterm
