// The plot area cut into panels stacked top to bottom, one per unit, sharing the time axis: each
// with its own vertical scale and its unit on the axis, so an angle in rad is not drawn flat beside
// a height in m. Pure: the screen draws what this decides, and the tests check it without a
// terminal.
#pragma once

#include <stddef.h>

#include <string>
#include <vector>

#include <pc/core/plot_model.hpp>

namespace qrterm {

// A panel's fewest rows: its top value, its unit and its bottom value each need one.
inline constexpr int kPanelMinRows = 3;

struct PlotPanel {
  std::string unit;            // "" when nothing is picked: the empty plot's one panel
  std::vector<size_t> traces;  // indices into PlotModel::traces(), in pick order
  double low = -1, high = 1;   // the vertical scale, in the unit
  int top = 0, rows = 0;       // rows of the plot area, 0 its top
};

struct PlotLayout {
  // In the order the units were first picked. Panels are split by a row of their own when the
  // area has room for one between each two, else they touch.
  std::vector<PlotPanel> panels;
  // Traces whose unit found no panel (the area holds only area_rows / kPanelMinRows of them): the
  // readout still shows their values and says they are not drawn.
  std::vector<size_t> not_drawn;
  bool separated = false;
};

PlotLayout plot_layout(const PlotModel& plot, double now_s, int area_rows);

}  // namespace qrterm
