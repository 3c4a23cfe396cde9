// The plot screen's state, without a terminal: which observables are traced (up to four, picked
// by name from the QR's table), at what rate, the time window, the scale of each unit, freeze; the
// samples of each trace over the longest window; and the simulator's true attitude, height and
// climb when the console has them, to draw over the estimate. Times are the console's seconds
// since start. Each unit has its own vertical scale: a roll angle in rad beside a height in m on
// one axis would draw the angle flat (plot_panels.hpp stacks one panel per unit).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <common/stream_budget.hpp>
#include <pc/core/observable_catalog.hpp>

namespace qrterm {

inline constexpr double kPlotWindowsS[] = {2, 5, 10, 30};
inline constexpr uint16_t kPlotRatesHz[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000};
inline constexpr size_t kDefaultRate = 7;  // 200 Hz
inline constexpr size_t kMaxTraces = wire::kStreamObservablesMax;

struct PlotPoint {
  double t_s;
  double value;
};

struct Trace {
  uint8_t id;
  std::string name;
  std::string unit;
  std::deque<PlotPoint> points;  // oldest first, the longest window's worth
  // The set-point this trace follows is drawn beside it: "phi" follows "phi_sp".
  bool is_setpoint() const { return name.size() > 3 && name.compare(name.size() - 3, 3, "_sp") == 0; }
};

class PlotModel {
 public:
  // Selection. add() refuses a fifth trace or one already there.
  bool add(uint8_t id, const ObservableRow& row);
  void remove_last();
  const std::vector<Trace>& traces() const { return traces_; }
  std::vector<uint8_t> ids() const;

  uint16_t rate_hz() const { return kPlotRatesHz[rate_]; }
  void faster() { rate_ = rate_ + 1 < std::size(kPlotRatesHz) ? rate_ + 1 : rate_; }
  void slower() { rate_ = rate_ > 0 ? rate_ - 1 : 0; }
  // Stream divider for the rate at the QR's control rate (at least 1).
  uint16_t divider(uint16_t control_hz) const;

  double window_s() const { return kPlotWindowsS[window_]; }
  void next_window() { window_ = (window_ + 1) % std::size(kPlotWindowsS); }

  // The traces' units, each once, in the order they were first picked.
  std::vector<std::string> units() const;

  bool autoscale() const { return !fixed_; }
  // Fixed: each unit's range now on the screen stays (a unit picked later is scaled to fit until
  // the next toggle or zoom); zoom() scales every unit's range about its middle.
  void toggle_scale(double now_s);
  void zoom(double factor, double now_s);
  // Low, high of the vertical axis of the traces in `unit` (and the truth under them).
  std::pair<double, double> scale(double now_s, const std::string& unit) const;

  bool frozen() const { return frozen_at_.has_value(); }
  void toggle_freeze(double now_s);
  double view_end_s(double now_s) const { return frozen_at_ ? *frozen_at_ : now_s; }

  // One sample of every trace, the values in their units, at `t_s`.
  void add_sample(double t_s, const std::vector<double>& values);
  void clear_points();
  // The simulator's truth, in the units of the observables it is drawn over: roll, pitch, yaw
  // (rad) over phi, theta, psi; height (m) and climb (m/s, up) over height and climb.
  struct TrueState {
    double roll = 0, pitch = 0, yaw = 0, height = 0, climb = 0;
  };
  void add_truth(double t_s, const TrueState& truth);
  // The truth series that belongs to a trace, if any ("phi" -> roll, "height" -> height).
  const std::deque<PlotPoint>* truth_for(const Trace& trace) const;

 private:
  void trim(std::deque<PlotPoint>& points, double now_s) const;

  std::vector<Trace> traces_;
  size_t rate_ = kDefaultRate;
  size_t window_ = 1;  // 5 s
  bool fixed_ = false;
  std::map<std::string, std::pair<double, double>> fixed_ranges_;  // by unit, while fixed
  std::optional<double> frozen_at_;
  std::deque<PlotPoint> truth_[5];  // roll, pitch, yaw, height, climb
};

}  // namespace qrterm
