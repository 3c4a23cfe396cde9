#include <qr/sim_runner/sweep.hpp>

#include <cmath>
#include <iterator>

#include <sim/random.hpp>

namespace qrsim {
namespace {

// Stream number of the sweep's draws: apart from the world's own streams of the same seed.
constexpr uint64_t kSweepStream = 0x5eed5eedULL;

// The worse of two values for a band: the larger for < and <=; for == a value off the limit.
// A figure not measured (NaN) is the worst of all.
double worse(const Band& band, double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::nan("");
  if (band.compare == Compare::equal) return a != band.limit ? a : b;
  return std::max(a, b);
}

std::string number_text(double v) {
  if (std::isnan(v)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

}  // namespace

VehicleDraw draw_vehicle(uint64_t seed) {
  sim::Random random = sim::Random(seed).stream(kSweepStream);
  double drawn[std::size(kSweepRanges)];
  for (size_t i = 0; i < std::size(kSweepRanges); ++i)
    drawn[i] = random.uniform(kSweepRanges[i].low, kSweepRanges[i].high);
  return {drawn[0], drawn[1], drawn[2], drawn[3], drawn[4]};
}

std::vector<BandSummary> run_sweep(const ScenarioScript& script, const RunOptions& options, int seeds, bool draw,
                                   FILE* out) {
  std::vector<BandSummary> summary(script.bands.size());
  for (int i = 0; i < seeds; ++i) {
    RunOptions run = options;
    run.seed = options.seed + static_cast<uint64_t>(i);
    if (draw) run.draw = draw_vehicle(run.seed);
    const ScenarioResult r = run_scenario(script, run);
    std::string line = to_json(r);
    line.insert(1, "\"sweep\": \"" + script.name + "\", ");
    std::fprintf(out, "%s\n", line.c_str());
    std::fflush(out);
    for (size_t b = 0; b < script.bands.size(); ++b) {
      const Band& band = script.bands[b];
      BandSummary& s = summary[b];
      const double value = r.figure(band.figure);
      if (b < r.checks.size()) {
        s.band = r.checks[b].band;
        s.passed += r.checks[b].pass ? 1 : 0;
      }
      s.worst = s.of == 0 ? value : worse(band, s.worst, value);
      ++s.of;
    }
  }
  for (size_t b = 0; b < summary.size(); ++b) {
    const BandSummary& s = summary[b];
    std::string worst = number_text(s.worst);
    if (script.bands[b].figure == "final_mode" && !std::isnan(s.worst)) {
      worst = std::string("\"") + mode_name(static_cast<uint8_t>(s.worst)) + "\"";
    }
    std::fprintf(out, "{\"sweep\": \"%s\", \"band\": \"%s\", \"passed\": %d, \"of\": %d, \"worst\": %s}\n",
                 script.name.c_str(), s.band.c_str(), s.passed, s.of, worst.c_str());
  }
  return summary;
}

}  // namespace qrsim
