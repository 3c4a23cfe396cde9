// The console's side of the plot (issue 17), without a terminal: the observable table learned from
// the wire, the samples of a stream into the plot and its CSV, the canvas a trace is drawn on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <common/messages.hpp>
#include <common/sample_packing.hpp>
#include <pc/core/completion.hpp>
#include <pc/core/observable_catalog.hpp>
#include <pc/core/plot_canvas.hpp>
#include <pc/core/plot_panels.hpp>
#include <pc/core/stream_session.hpp>

#include "observable_table_feed.hpp"

namespace qrterm {
namespace {

TEST(ObservableCatalog, LearnsEveryRowIncludingTextsOfSevenCharactersExactly) {
  ObservableCatalog catalog;
  send_observable_table(catalog);
  ASSERT_TRUE(catalog.complete());
  // "accel_x counts" is 14 characters: two full parts and an empty last one.
  const auto id = catalog.find("accel_x");
  ASSERT_TRUE(id.has_value());
  EXPECT_EQ(catalog.row(*id)->unit, "counts");
  const ObservableRow& battery = *catalog.row(*catalog.find("battery"));
  EXPECT_DOUBLE_EQ(battery.value(static_cast<int16_t>(static_cast<uint16_t>(50000))), 50.0) << "u16, 1e-3";
  EXPECT_NEAR(catalog.row(*catalog.find("phi"))->value(-1234), -0.1234, 1e-12);
}

TEST(ObservableCatalog, ARowWithoutItsLastPieceIsNotUsable) {
  ObservableCatalog catalog;
  catalog.on(wire::ObservableInfo{0, 1, wire::ObservableType::i16, -4, 1000});
  wire::ObservableText piece{0, 0, {'a', 'c', 'c', 'e', 'l', '_', 'x'}};
  catalog.on(piece);
  EXPECT_FALSE(catalog.complete());
  EXPECT_FALSE(catalog.find("accel_x").has_value());
}

struct Files {
  std::vector<std::pair<std::string, std::ostringstream*>> opened;
  std::unique_ptr<std::ostream> open(const std::string& name) {
    auto out = std::make_unique<std::ostringstream>();
    opened.push_back({name, out.get()});
    return out;
  }
};

TEST(StreamSession, SamplesReachThePlotAndTheCsvWithUnitsInTheColumnNames) {
  std::vector<std::string> notes;
  Files files;
  StreamSession session(StreamSession::Hooks{[&](Severity, const std::string& t) { notes.push_back(t); },
                                             [&](const std::string& name) {
                                               auto out = files.open(name);
                                               return out;
                                             },
                                             {}});
  send_observable_table(session);
  session.pick("phi p nothing");
  EXPECT_EQ(session.plot().traces().size(), 2u);
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes.back().find("no observable \"nothing\""), std::string::npos);
  EXPECT_EQ(session.cost_text(50), "2 x 200 Hz = 400 samples/s: 1200 of 8370 B/s");

  session.on_answer(wire::MessageType::stream_request, wire::NackReason::none, 50);  // nothing asked: ignored
  LinkSession link(0, 1);
  session.tick(link, 0);  // asks
  session.on_answer(wire::MessageType::stream_request, wire::NackReason::none, 50);
  EXPECT_EQ(session.state(), "streaming");
  wire::SamplePacker packer;
  packer.start(0, 2);
  for (int s = 0; s < 10; ++s) {
    const int16_t values[2] = {static_cast<int16_t>(s * 100), -500};
    wire::ObservableSamples frame;
    if (packer.add(values, frame)) session.on(frame, 1.0 + s * 0.005);
  }
  EXPECT_EQ(session.samples_received(), 10u);
  const Trace& phi = session.plot().traces()[0];
  ASSERT_EQ(phi.points.size(), 10u);
  EXPECT_NEAR(phi.points.back().value, 0.09, 1e-12);
  EXPECT_NEAR(session.plot().traces()[1].points.back().value, -0.5, 1e-12) << "p in rad/s";
  ASSERT_EQ(files.opened.size(), 1u);
  EXPECT_EQ(files.opened[0].first, "observables_1.csv");
  const std::string csv = files.opened[0].second->str();
  EXPECT_EQ(csv.substr(0, csv.find('\r')), "time_s,qr_time_s,phi_rad,p_rad_per_s");
}

// Tab on an ambiguous prefix did nothing: as a shell, it now completes as far as the candidates
// agree, and the row above the prompt lists them, saying how many more when they do not fit.
TEST(Completion, AnAmbiguousPrefixGrowsToWhatTheCandidatesShare) {
  EXPECT_EQ(last_word("phi th"), "th");
  const Completion one = complete_last_word("phi th", {"theta"});
  EXPECT_EQ(one.text, "phi theta ");
  EXPECT_TRUE(one.candidates.empty());
  const Completion several = complete_last_word("ph", {"phi", "phi_sp", "phi_acc"});
  EXPECT_EQ(several.text, "phi") << "the start the three share";
  EXPECT_EQ(several.candidates, (std::vector<std::string>{"phi", "phi_sp", "phi_acc"}));
  const Completion shared_only = complete_last_word("phi_", {"phi_sp", "phi_acc"});
  EXPECT_EQ(shared_only.text, "phi_") << "nothing more to add: the list says what may follow";
  EXPECT_EQ(shared_only.candidates.size(), 2u);
  const Completion none = complete_last_word("xyz", {});
  EXPECT_EQ(none.text, "xyz");
  EXPECT_TRUE(none.none);

  EXPECT_EQ(candidates_line({"phi", "phi_sp"}, 80), "phi phi_sp");
  const std::vector<std::string> many(30, "cycles_task");
  const std::string cut = candidates_line(many, 80);
  EXPECT_LE(cut.size(), 80u);
  EXPECT_NE(cut.find("more: type more)"), std::string::npos) << cut;
  EXPECT_EQ(candidates_line({"a_very_long_observable_name"}, 10), "(+1 more: type more)");
}

// With the QR's own table: "ph" is several names, and Tab gives the start they share.
TEST(Completion, TheQrsTableCompletesAsFarAsItsNamesAgree) {
  ObservableCatalog catalog;
  send_observable_table(catalog);
  const std::vector<std::string> ph = catalog.names_starting("ph");
  ASSERT_GT(ph.size(), 1u) << "the table has several names starting ph";
  const Completion tab = complete_last_word("theta ph", ph);
  EXPECT_EQ(tab.text, "theta phi");
  EXPECT_EQ(tab.candidates, ph);
}

TEST(PlotCanvas, ARisingTraceEndsHigherThanItStartsInBothCellKinds) {
  std::deque<PlotPoint> points;
  for (int i = 0; i <= 100; ++i) points.push_back({i * 0.01, i * 0.01});
  for (bool braille : {false, true}) {
    const PlotFrame frame{0, 1, 0, 1, 20, 8, braille};
    const auto cells = draw_plot(frame, {{&points, 0, '*'}});
    int first_row = -1, last_row = -1;
    for (int r = 0; r < 8; ++r) {
      if (cells[static_cast<size_t>(r)][0].style == 0 && first_row < 0) first_row = r;
      if (cells[static_cast<size_t>(r)][19].style == 0 && last_row < 0) last_row = r;
    }
    EXPECT_EQ(first_row, 7) << "the lowest value on the bottom row, braille " << braille;
    EXPECT_EQ(last_row, 0) << "the highest on the top row, braille " << braille;
    if (braille) EXPECT_EQ(cells[0][19].text.size(), 3u) << "one UTF-8 braille character";
  }
}

// The simulator's truth is drawn under the trace it belongs to, in its own style and dots: the
// true height (m) under `height`, the true roll (rad) under `phi`; nothing under a trace without
// a truth (phi_sp), nor under one whose unit is not the truth's.
TEST(PlotModel, TheTruthIsDrawnUnderHeightAndTheAttitude) {
  PlotModel plot;
  ObservableRow height;
  height.name = "height";
  height.unit = "m";
  ObservableRow phi_sp;
  phi_sp.name = "phi_sp";
  phi_sp.unit = "rad";
  ASSERT_TRUE(plot.add(27, height));
  ASSERT_TRUE(plot.add(6, phi_sp));
  for (int i = 0; i <= 100; ++i) {
    const double t = i * 0.05;
    plot.add_sample(t, {0.7 * t / 5, 0.0});       // the estimate climbs to 0.7 m
    plot.add_truth(t, {0.01, 0, 0, t / 5, 0.2});  // the truth to 1 m, and rolled 0.01 rad
  }
  ASSERT_NE(plot.truth_for(plot.traces()[0]), nullptr);
  EXPECT_DOUBLE_EQ(plot.truth_for(plot.traces()[0])->back().value, 1.0);
  EXPECT_EQ(plot.truth_for(plot.traces()[1]), nullptr) << "a set-point has no truth";

  const std::vector<PlotSeries> series = plot_series(plot);
  ASSERT_EQ(series.size(), 3u);
  EXPECT_EQ(series[0].style, kTruthStyle) << "the truth first, under the traces";
  EXPECT_EQ(series[0].glyph, '.');
  EXPECT_EQ(series[1].style, 1) << "then the set-point";
  EXPECT_EQ(series[2].style, 0) << "and what follows it on top";

  // On the screen: at the right end the truth (1 m) stands above the estimate (0.7 m).
  const PlotFrame frame{0, 5, 0, 1, 40, 10, false};
  const auto cells = draw_plot(frame, series);
  int truth_cells = 0, truth_row = -1, estimate_row = -1;
  for (int r = 0; r < 10; ++r) {
    for (int c = 0; c < 40; ++c) {
      const PlotCell& cell = cells[size_t(r)][size_t(c)];
      if (cell.style == kTruthStyle) {
        ++truth_cells;
        EXPECT_EQ(cell.text, ".");
      }
    }
    if (cells[size_t(r)][39].style == kTruthStyle && truth_row < 0) truth_row = r;
    if (cells[size_t(r)][39].style == 0 && estimate_row < 0) estimate_row = r;
  }
  EXPECT_GT(truth_cells, 10) << "the truth is drawn where the estimate does not cover it";
  EXPECT_EQ(truth_row, 0);
  EXPECT_GT(estimate_row, truth_row);

  // A trace named like a truth but in another unit gets none: the wrong unit would draw nonsense.
  PlotModel other;
  ObservableRow height_mm;
  height_mm.name = "height";
  height_mm.unit = "mm";
  ASSERT_TRUE(other.add(27, height_mm));
  other.add_truth(0, {0, 0, 0, 1.0, 0});
  EXPECT_EQ(other.truth_for(other.traces()[0]), nullptr);
}

TEST(PlotModel, ATruthLineWithoutAFieldLeavesThatSeriesAlone) {
  PlotModel plot;
  ObservableRow climb;
  climb.name = "climb";
  climb.unit = "m/s";
  ASSERT_TRUE(plot.add(28, climb));
  plot.add_truth(0, {0, 0, 0, 1.0, std::nan("")});
  EXPECT_EQ(plot.truth_for(plot.traces()[0]), nullptr) << "no climb in the line: nothing to draw";
  plot.add_truth(0.02, {0, 0, 0, 1.0, -0.5});
  ASSERT_NE(plot.truth_for(plot.traces()[0]), nullptr);
  EXPECT_DOUBLE_EQ(plot.truth_for(plot.traces()[0])->back().value, -0.5);
}

TEST(PlotModel, FreezeHoldsTheViewAndFixedScaleHoldsTheRange) {
  PlotModel plot;
  ObservableRow phi;
  phi.name = "phi";
  phi.unit = "rad";
  ASSERT_TRUE(plot.add(0, phi));
  plot.add_truth(0, {0.1, 0, 0, 0, 0});
  plot.toggle_freeze(5.0);
  EXPECT_EQ(plot.view_end_s(9.0), 5.0);
  plot.toggle_freeze(9.0);
  EXPECT_EQ(plot.view_end_s(9.0), 9.0);
  plot.zoom(2.0, 9.0);
  EXPECT_FALSE(plot.autoscale());
  const auto [low, high] = plot.scale(9.0, "rad");
  EXPECT_DOUBLE_EQ(high - low, 4.0) << "the default band of 2 (no sample in the window), zoomed out twice";
}

ObservableRow row(const char* name, const char* unit) {
  ObservableRow r;
  r.name = name;
  r.unit = unit;
  return r;
}

// Issue 36: phi (rad) beside height (m) on one axis labelled "mixed" drew the roll flat. Each unit
// now has its own panel and scale: the angle's spans tenths of a radian, the height's metres, and
// phi's trace climbs and falls over most of its panel's rows.
TEST(PlotPanels, AnAngleAndAHeightEachGetAPanelWithItsOwnScale) {
  PlotModel plot;
  ASSERT_TRUE(plot.add(0, row("phi", "rad")));
  ASSERT_TRUE(plot.add(27, row("height", "m")));
  ASSERT_TRUE(plot.add(6, row("phi_sp", "rad")));
  for (int i = 0; i <= 500; ++i) {
    const double t = i * 0.01;
    plot.add_sample(t, {0.1 * std::sin(3.14159 * t), 5 + 0.5 * std::sin(1.5708 * t), 0.0});
  }
  EXPECT_EQ(plot.units(), (std::vector<std::string>{"rad", "m"}));

  const PlotLayout layout = plot_layout(plot, 5.0, 13);  // the plot area at 80x24
  ASSERT_EQ(layout.panels.size(), 2u);
  EXPECT_TRUE(layout.separated) << "13 rows hold two panels and a row between";
  const PlotPanel& rad = layout.panels[0];
  const PlotPanel& m = layout.panels[1];
  EXPECT_EQ(rad.unit, "rad");
  EXPECT_EQ(rad.traces, (std::vector<size_t>{0, 2})) << "phi and its set-point share the angle's panel";
  EXPECT_EQ(m.traces, (std::vector<size_t>{1}));
  EXPECT_EQ(rad.top, 0);
  EXPECT_EQ(rad.rows, 6);
  EXPECT_EQ(m.top, 7) << "after the separating row";
  EXPECT_EQ(m.rows, 6);
  EXPECT_GT(rad.low, -0.2);
  EXPECT_LT(rad.high, 0.2) << "the angle's scale is tenths of a radian, not the height's metres";
  EXPECT_GT(m.low, 4.0);
  EXPECT_LT(m.high, 6.0);

  // phi's trace in its panel covers most rows; on the height's scale (the old single axis, about
  // -0.1..5.5) it stayed within one or two.
  const auto rows_touched = [&](double low, double high) {
    const PlotFrame frame{0, 5, low, high, 60, rad.rows, false};
    const auto cells = draw_plot(frame, {{&plot.traces()[0].points, 0, '*'}});
    int touched = 0;
    for (const auto& cells_row : cells) {
      touched += std::any_of(cells_row.begin(), cells_row.end(), [](const PlotCell& c) { return c.style == 0; });
    }
    return touched;
  };
  EXPECT_GE(rows_touched(rad.low, rad.high), 5);
  EXPECT_LE(rows_touched(-0.1, 5.5), 2);
}

// A full selection of four units at 80x24 (13 rows): four panels of three rows or more, touching,
// filling the area; in a taller terminal a row between each two. Nothing picked: one empty panel
// over the whole area.
TEST(PlotPanels, FourUnitsTouchAt80x24AndAreSplitInATallerTerminal) {
  PlotModel plot;
  ASSERT_TRUE(plot.add(0, row("phi", "rad")));
  ASSERT_TRUE(plot.add(27, row("height", "m")));
  ASSERT_TRUE(plot.add(28, row("climb", "m/s")));
  ASSERT_TRUE(plot.add(26, row("battery", "V")));

  const PlotLayout four = plot_layout(plot, 0, 13);
  ASSERT_EQ(four.panels.size(), 4u);
  EXPECT_FALSE(four.separated) << "4 x 3 rows and 3 between do not fit in 13";
  int next = 0;
  for (const PlotPanel& p : four.panels) {
    EXPECT_EQ(p.top, next);
    EXPECT_GE(p.rows, kPanelMinRows);
    next = p.top + p.rows;
  }
  EXPECT_EQ(next, 13) << "the panels fill the area";
  EXPECT_EQ(four.panels[3].unit, "V");
  EXPECT_EQ(four.panels[3].traces, (std::vector<size_t>{3}));

  const PlotLayout tall = plot_layout(plot, 0, 30);
  EXPECT_TRUE(tall.separated);
  EXPECT_EQ(tall.panels[0].rows, 7) << "27 rows for four panels: the 3 left over to the top ones";
  EXPECT_EQ(tall.panels[3].rows, 6);
  EXPECT_EQ(tall.panels[3].top + tall.panels[3].rows, 30);

  const PlotLayout empty = plot_layout(PlotModel{}, 0, 13);
  ASSERT_EQ(empty.panels.size(), 1u);
  EXPECT_EQ(empty.panels[0].unit, "");
  EXPECT_EQ(empty.panels[0].rows, 13);
  EXPECT_DOUBLE_EQ(empty.panels[0].high, 1.0);
}

// A fixed scale holds each unit's own range; zoom scales each about its middle; the truth goes to
// its trace's panel only.
TEST(PlotPanels, FixedScaleAndZoomKeepEachUnitsRangeAndTheTruthStaysInItsPanel) {
  PlotModel plot;
  ASSERT_TRUE(plot.add(0, row("phi", "rad")));
  ASSERT_TRUE(plot.add(27, row("height", "m")));
  plot.add_sample(0, {-0.1, 4.0});
  plot.add_sample(1, {0.1, 6.0});
  plot.add_truth(1, {0.05, 0, 0, 5.5, 0});
  const auto rad = plot.scale(1, "rad");
  const auto m = plot.scale(1, "m");
  plot.toggle_scale(1);
  plot.add_sample(2, {3.0, 60.0});  // far outside: the fixed ranges stay
  EXPECT_EQ(plot.scale(2, "rad"), rad);
  EXPECT_EQ(plot.scale(2, "m"), m);
  plot.zoom(0.5, 2);
  EXPECT_DOUBLE_EQ(plot.scale(2, "m").second - plot.scale(2, "m").first, (m.second - m.first) / 2);
  EXPECT_DOUBLE_EQ(plot.scale(2, "m").first + plot.scale(2, "m").second, m.first + m.second) << "about its middle";
  EXPECT_DOUBLE_EQ(plot.scale(2, "rad").second - plot.scale(2, "rad").first, (rad.second - rad.first) / 2);

  const PlotLayout layout = plot_layout(plot, 2, 13);
  const std::vector<PlotSeries> height = plot_series(plot, layout.panels[1].traces);
  ASSERT_EQ(height.size(), 2u);
  EXPECT_EQ(height[0].style, kTruthStyle) << "the true height under the height";
  EXPECT_EQ(height[1].style, 1);
  EXPECT_EQ(plot_series(plot, layout.panels[0].traces).size(), 2u) << "the true roll under phi, nothing else";
}

}  // namespace
}  // namespace qrterm
