// Traces onto a grid of terminal cells: in braille (each cell 2 x 4 dots, U+2800..U+28FF) when the
// terminal speaks UTF-8, else one plain character per cell. Pure: the screen layer only copies the
// cells out, so the drawing is tested without a terminal.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <deque>
#include <string>
#include <vector>

#include <pc/core/plot_model.hpp>

namespace qrterm {

struct PlotSeries {
  const std::deque<PlotPoint>* points;
  int style;   // the colour the screen gives it; also the cell's owner
  char glyph;  // in plain cells
};

struct PlotCell {
  std::string text = " ";
  int style = -1;  // -1: empty
};

struct PlotFrame {
  double t_begin, t_end;  // s
  double low, high;       // the vertical axis, in the traces' unit
  int columns, rows;
  bool braille;
};

// Rows of cells, top row first. Later series draw over earlier ones where they share a cell.
std::vector<std::vector<PlotCell>> draw_plot(const PlotFrame& frame, const std::vector<PlotSeries>& series);

// The plot's traces as the screen draws them, in drawing order: the simulator's truth under
// the traces it belongs to (style kTruthStyle, glyph '.'), then the set-points, then what follows
// them, so the followers end on top. Trace i has style i and glyph kTraceGlyphs[i]. Of the traces
// listed (indices into the plot's traces: one panel's), or of all.
inline constexpr char kTraceGlyphs[kMaxTraces] = {'*', 'o', '+', 'x'};
inline constexpr int kTruthStyle = static_cast<int>(kMaxTraces);
std::vector<PlotSeries> plot_series(const PlotModel& plot, const std::vector<size_t>& traces);
std::vector<PlotSeries> plot_series(const PlotModel& plot);

}  // namespace qrterm
