// The plot screen: the chosen observables against time, newest at the right, a panel per unit.
#include <cmath>

#include <pc/core/completion.hpp>
#include <pc/core/plot_canvas.hpp>
#include <pc/core/plot_panels.hpp>
#include <pc/core/screen_keys.hpp>
#include <pc/ui/cockpit.hpp>
#include <pc/ui/screen_draw.hpp>
#include <pc/ui/screens.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {
namespace {

// Trace i's colour (its glyph: plot_canvas.hpp); the truth is drawn dim, in dots.
constexpr short kTraceColors[kMaxTraces] = {kInfo, kWarning, kQr, kMagenta};
constexpr int kLabelColumns = 9;
// Beside the plot area: the selection's two rows, the time axis, two of readout, the keys, the
// prompt. Below the cockpit's four status rows, the least terminal leaves the area a panel of
// kPanelMinRows for each unit of a full selection.
constexpr int kRowsBesideArea = 7;
static_assert(Cockpit::kMinRows - 4 - kRowsBesideArea >= static_cast<int>(kMaxTraces) * kPanelMinRows);

std::string value_text(double v) {
  const double a = std::fabs(v);
  if (a >= 1e5) return text("%+.2e", v);
  return text(a < 10 ? "%+.4f" : a < 1000 ? "%+.2f" : "%+.0f", v);
}

// One panel: its traces on its own scale, the axis beside it with its ends, its middle when there
// is room, and its unit under the top value.
void draw_panel(const PlotModel& plot, const PlotPanel& panel, int area_top, int columns, double begin, double end,
                bool braille) {
  const int top = area_top + panel.top;
  const PlotFrame frame{begin, end, panel.low, panel.high, columns, panel.rows, braille};
  const auto cells = draw_plot(frame, plot_series(plot, panel.traces));
  for (int r = 0; r < panel.rows; ++r) {
    put(top + r, kLabelColumns - 1, "|", kDim);
    for (int c = 0; c < columns; ++c) {
      const PlotCell& cell = cells[static_cast<size_t>(r)][static_cast<size_t>(c)];
      if (cell.style < 0) continue;
      const short color = cell.style == kTruthStyle ? kDim : kTraceColors[cell.style];
      put(top + r, kLabelColumns + c, cell.text, color, cell.style == kTruthStyle ? A_NORMAL : A_BOLD);
    }
  }
  put(top, 0, value_text(panel.high), kDim);
  put(top + 1, 0, panel.unit.substr(0, kLabelColumns - 1), kDim, A_BOLD);
  if (panel.rows >= 5) put(top + panel.rows / 2, 0, value_text((panel.low + panel.high) / 2), kDim);
  put(top + panel.rows - 1, 0, value_text(panel.low), kDim);
}

}  // namespace

void draw_prompt_or_log(const Console& console, int row, int width) {
  if (const auto& prompt = console.prompt()) {
    constexpr const char* kAsk[] = {"observables (names, Tab completes, Enter): ", "value (Enter sends): ",
                                    "save parameters to file: ", "load parameters from file: "};
    put(row, 0, std::string(kAsk[static_cast<size_t>(prompt->kind)]) + prompt->text + "_", kTitle, A_BOLD);
    if (prompt->kind == PromptKind::observables) {
      // The names the word being typed may still become, as a shell lists them: Tab completes as
      // far as they agree.
      const std::vector<std::string> names = console.streams().catalog().names_starting(last_word(prompt->text));
      put(row - 1, 0, std::string(static_cast<size_t>(width), ' '));
      put(row - 1, 0,
          names.empty() ? std::string("(no observable starts so)")
                        : candidates_line(names, static_cast<size_t>(std::max(1, width - 1))),
          kQr);
    }
    return;
  }
  const auto& lines = console.log().lines();
  if (lines.empty()) return;
  const LogLine& last = lines.back();
  constexpr short kColors[] = {kInfo, kWarning, kError, kQr};
  put(row, 0, format_seconds(last.time_ms) + " " + last.text, kColors[static_cast<size_t>(last.severity)]);
}

void draw_plot_screen(const Console& console, int top, int rows, int width, bool braille) {
  const StreamSession& streams = console.streams();
  const PlotModel& plot = streams.plot();
  const double now_s = console.uptime_ms() / 1000.0;
  const std::vector<Trace>& traces = plot.traces();

  // The selection, its rate and cost, and the state of its stream.
  std::string scale = plot.autoscale() ? "auto" : "fixed";
  put(top, 0, "PLOT", 0, A_BOLD);
  put(top, 5,
      text("%u Hz  %.0f s  %s%s  %s", plot.rate_hz(), plot.window_s(), scale.c_str(), plot.frozen() ? "  FROZEN" : "",
           streams.state().c_str()),
      plot.frozen() ? kWarning : 0, plot.frozen() ? A_BOLD : A_NORMAL);
  put(top + 1, 5, streams.cost_text(console.telemetry_hz()) + text("  lost %u", streams.samples_lost()), kDim);

  const int area_top = top + 2;
  const int area_rows = std::max(3, rows - kRowsBesideArea);
  const int area_columns = std::max(10, width - kLabelColumns - 1);
  const double end = plot.view_end_s(now_s);
  const double begin = end - plot.window_s();

  // One panel per unit, stacked, each on its own scale; a dashed row between two when there is room.
  const PlotLayout layout = plot_layout(plot, now_s, area_rows);
  for (const PlotPanel& panel : layout.panels) {
    draw_panel(plot, panel, area_top, area_columns, begin, end, braille);
    if (layout.separated && &panel != &layout.panels.back()) {
      std::string dashes;
      for (int c = 0; c < area_columns; ++c) dashes += c % 2 == 0 ? '-' : ' ';
      put(area_top + panel.top + panel.rows, kLabelColumns - 1, "+" + dashes, kDim);
    }
  }
  // The time axis.
  const int axis = area_top + area_rows;
  put(axis, kLabelColumns - 1, "+" + std::string(static_cast<size_t>(area_columns), '-'), kDim);
  put(axis, kLabelColumns, text(" -%.0f s ", plot.window_s()), kDim);
  put(axis, kLabelColumns + area_columns - 6, plot.frozen() ? " frozen" : " now", kDim);

  // The latest values, two to a row.
  const int readout = axis + 1;
  if (traces.empty()) {
    put(readout, 0, "/ picks observables by name, e.g. phi phi_sp (Tab completes)", kWarning);
  }
  for (size_t i = 0; i < traces.size(); ++i) {
    const Trace& t = traces[i];
    std::string latest = t.points.empty() ? "--" : value_text(t.points.back().value);
    if (const auto* truth = plot.truth_for(t); truth != nullptr && !truth->empty())
      latest += " truth " + value_text(truth->back().value);
    const int row = readout + static_cast<int>(i / 2);
    const int column = static_cast<int>(i % 2) * (width / 2);
    put(row, column, text("%c %s %s %s", kTraceGlyphs[i], t.name.c_str(), latest.c_str(), t.unit.c_str()),
        kTraceColors[i], A_BOLD);
  }
  put(top + rows - 2, 0, "/ pick  Bksp drop  m window  y scale  +/- zoom  spc freeze  ,/. rate  Tab next", kDim);
  draw_prompt_or_log(console, top + rows - 1, width);
}

}  // namespace qrterm
