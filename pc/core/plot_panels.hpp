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

// A panel's fewest rows: its top value, its unit and its bottom value each need one. The plot
// area holds a panel for each of the most units a selection can have (kMaxTraces) with this many
// rows: at the console's least terminal, 80x24, it has 13 (plot_screen.cpp checks).
inline constexpr int kPanelMinRows = 3;

struct PlotPanel {
  std::string unit;            // "" when nothing is picked: the empty plot's one panel
  std::vector<size_t> traces;  // indices into PlotModel::traces(), in pick order
  double low = -1, high = 1;   // the vertical scale, in the unit
  int top = 0, rows = 0;       // rows of the plot area, 0 its top
};

struct PlotLayout {
  // In the order the units were first picked, filling the area; split by a row of their own when
  // the area has room for one between each two and kPanelMinRows each, else touching.
  std::vector<PlotPanel> panels;
  bool separated = false;
};

// `area_rows`: at least kMaxTraces * kPanelMinRows.
PlotLayout plot_layout(const PlotModel& plot, double now_s, int area_rows);

}  // namespace qrterm
