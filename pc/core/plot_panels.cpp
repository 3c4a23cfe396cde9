#include <pc/core/plot_panels.hpp>

#include <algorithm>
#include <tuple>

namespace qrterm {

PlotLayout plot_layout(const PlotModel& plot, double now_s, int area_rows) {
  PlotLayout layout;
  std::vector<std::string> units = plot.units();
  if (units.empty()) units.push_back("");
  const int count = static_cast<int>(units.size());
  layout.separated = count * kPanelMinRows + (count - 1) <= area_rows;
  const int usable = area_rows - (layout.separated ? count - 1 : 0);
  int top = 0;
  for (int i = 0; i < count; ++i) {
    PlotPanel panel;
    panel.unit = units[static_cast<size_t>(i)];
    std::tie(panel.low, panel.high) = plot.scale(now_s, panel.unit);
    panel.top = top;
    panel.rows = std::max(1, usable / count + (i < usable % count ? 1 : 0));  // rows left over: the top panels'
    top += panel.rows + (layout.separated ? 1 : 0);
    layout.panels.push_back(panel);
  }
  const std::vector<Trace>& traces = plot.traces();
  for (size_t t = 0; t < traces.size(); ++t) {
    const auto panel = std::find(units.begin(), units.end(), traces[t].unit) - units.begin();
    layout.panels[static_cast<size_t>(panel)].traces.push_back(t);
  }
  return layout;
}

}  // namespace qrterm
