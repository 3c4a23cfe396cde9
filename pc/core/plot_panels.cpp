#include <pc/core/plot_panels.hpp>

#include <algorithm>
#include <tuple>

namespace qrterm {

PlotLayout plot_layout(const PlotModel& plot, double now_s, int area_rows) {
  PlotLayout layout;
  std::vector<std::string> units = plot.units();
  if (units.empty()) units.push_back("");
  // The first picked units keep their panels when not all fit; one panel at least, however short.
  const size_t fit = static_cast<size_t>(std::max(1, area_rows / kPanelMinRows));
  const size_t shown = std::min(units.size(), fit);
  const int count = static_cast<int>(shown);
  layout.separated = count * kPanelMinRows + (count - 1) <= area_rows;
  const int usable = area_rows - (layout.separated ? count - 1 : 0);
  int top = 0;
  for (int i = 0; i < count; ++i) {
    PlotPanel panel;
    panel.unit = units[static_cast<size_t>(i)];
    std::tie(panel.low, panel.high) = plot.scale(now_s, panel.unit);
    panel.top = top;
    panel.rows = usable / count + (i < usable % count ? 1 : 0);  // the rows left over to the top panels
    top += panel.rows + (layout.separated ? 1 : 0);
    layout.panels.push_back(panel);
  }
  const std::vector<Trace>& traces = plot.traces();
  for (size_t t = 0; t < traces.size(); ++t) {
    const auto found = std::find(units.begin(), units.end(), traces[t].unit);
    const size_t panel = static_cast<size_t>(found - units.begin());
    if (panel < shown) {
      layout.panels[panel].traces.push_back(t);
    } else {
      layout.not_drawn.push_back(t);
    }
  }
  return layout;
}

}  // namespace qrterm
