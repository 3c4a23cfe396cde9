#include <pc/core/plot_canvas.hpp>

#include <algorithm>
#include <cmath>

namespace qrterm {
namespace {

// Braille dot bits by (column 0..1, row 0..3) within a cell (Unicode's dot numbering 1-8).
constexpr uint8_t kDotBits[2][4] = {{0x01, 0x02, 0x04, 0x40}, {0x08, 0x10, 0x20, 0x80}};

std::string utf8(uint32_t code) {
  std::string s;
  s += static_cast<char>(0xE0 | (code >> 12));
  s += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
  s += static_cast<char>(0x80 | (code & 0x3F));
  return s;
}

}  // namespace

std::vector<std::vector<PlotCell>> draw_plot(const PlotFrame& frame, const std::vector<PlotSeries>& series) {
  std::vector<std::vector<PlotCell>> cells(static_cast<size_t>(std::max(frame.rows, 0)),
                                           std::vector<PlotCell>(static_cast<size_t>(std::max(frame.columns, 0))));
  if (frame.rows <= 0 || frame.columns <= 0 || !(frame.t_end > frame.t_begin) || !(frame.high > frame.low))
    return cells;
  const int dots_x = frame.braille ? 2 : 1;
  const int dots_y = frame.braille ? 4 : 1;
  const int width = frame.columns * dots_x;
  const int height = frame.rows * dots_y;
  std::vector<std::vector<uint8_t>> bits(cells.size(), std::vector<uint8_t>(cells[0].size(), 0));

  const auto x_of = [&](double t) {
    return static_cast<int>(std::floor((t - frame.t_begin) / (frame.t_end - frame.t_begin) * width));
  };
  const auto y_of = [&](double v) {  // 0 at the top; clamped so an off-scale value shows at the edge
    const double y = (frame.high - v) / (frame.high - frame.low) * height;
    return std::clamp(static_cast<int>(std::floor(y)), 0, height - 1);
  };
  for (const PlotSeries& s : series) {
    if (s.points == nullptr) continue;
    // Every dot of this series; a cell it touches becomes its own (its style), even if another
    // series had dots there: the last drawn is on top.
    std::vector<std::vector<uint8_t>> mine(cells.size(), std::vector<uint8_t>(cells[0].size(), 0));
    bool joined = false;  // a previous dot to join
    int last_x = 0, last_y = 0;
    for (const PlotPoint& p : *s.points) {
      if (p.t_s < frame.t_begin || p.t_s > frame.t_end || !std::isfinite(p.value)) continue;
      const int x = std::min(x_of(p.t_s), width - 1);
      const int y = y_of(p.value);
      // Joined to the previous dot by a vertical run, so a step reads as a step.
      const bool adjacent = joined && (last_x == x - 1 || last_x == x);
      const int from = adjacent ? std::min(last_y, y) : y;
      const int to = adjacent ? std::max(last_y, y) : y;
      for (int yy = std::max(from, 0); yy <= to; ++yy) {
        const size_t row = static_cast<size_t>(yy / dots_y);
        const size_t column = static_cast<size_t>(x / dots_x);
        mine[row][column] = static_cast<uint8_t>(mine[row][column] |
                                                 (frame.braille ? kDotBits[x % 2][yy % 4] : uint8_t{1}));
      }
      last_x = x;
      last_y = y;
      joined = true;
    }
    for (size_t r = 0; r < cells.size(); ++r) {
      for (size_t c = 0; c < cells[r].size(); ++c) {
        if (mine[r][c] == 0) continue;
        bits[r][c] = mine[r][c];  // the owner's dots only: colour and shape agree
        cells[r][c].style = s.style;
        cells[r][c].text = frame.braille ? utf8(0x2800u + bits[r][c]) : std::string(1, s.glyph);
      }
    }
  }
  return cells;
}

std::vector<PlotSeries> plot_series(const PlotModel& plot, const std::vector<size_t>& traces) {
  const std::vector<Trace>& all = plot.traces();
  std::vector<PlotSeries> series;
  for (size_t i : traces) {
    if (const auto* truth = plot.truth_for(all[i])) series.push_back({truth, kTruthStyle, '.'});
  }
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t i : traces) {
      if (all[i].is_setpoint() == (pass == 0)) series.push_back({&all[i].points, static_cast<int>(i), kTraceGlyphs[i]});
    }
  }
  return series;
}

std::vector<PlotSeries> plot_series(const PlotModel& plot) {
  std::vector<size_t> every(plot.traces().size());
  for (size_t i = 0; i < every.size(); ++i) every[i] = i;
  return plot_series(plot, every);
}

}  // namespace qrterm
