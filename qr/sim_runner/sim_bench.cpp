// sim-bench: how much faster than real time the simulator flies the default vehicle's hover
// (the built-in `hover` scenario, 30 s scored, its preflight included), as one JSON line:
//
//   {"sim_bench": "hover-30s", "build": "optimised", "runs": 5, "sim_seconds": 36.22, "speedup": ..., "speedup_cpu": ...,
//    "speedup_cpu_median": ..., "cpu_seconds_min": ..., "wall_seconds_min": ..., "att_rms_deg_truth": ...}
//
// `speedup` is simulated over wall-clock seconds, the best of the runs; `speedup_cpu` is simulated
// over the process's CPU seconds, the best of the runs: on a machine shared with other work the
// wall clock counts the time others had the core, the CPU time does not, so this is the figure
// that repeats. The flight figure shows it is the same flight each time (same seed, same flight).
// It prints; it asserts nothing about speed (docs/simulator.md section 8).
//
// usage: sim-bench [--runs N]   (default 5)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <qr/sim_runner/scenario.hpp>

namespace {

// Which build this is: the sanitised host build runs 5-10 times slower, and its line must not
// be read as the simulator's speed.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr const char* kBuild = "sanitized";
#else
constexpr const char* kBuild = "optimised";
#endif
#else
constexpr const char* kBuild = "optimised";
#endif

struct Run {
  double sim_seconds, wall_seconds, cpu_seconds, att_rms_deg;
};

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
      runs = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: sim-bench [--runs N]\n");
      return 2;
    }
  }
  if (runs < 1 || runs > 1000) {
    std::fprintf(stderr, "sim-bench: --runs must be 1..1000\n");
    return 2;
  }

  qrsim::ScenarioScript hover;
  std::string error;
  if (!qrsim::find_scenario("hover", hover, error)) {
    std::fprintf(stderr, "sim-bench: %s\n", error.c_str());
    return 1;
  }
  std::vector<Run> done;
  for (int i = 0; i < runs; ++i) {
    const qrsim::ScenarioResult r = qrsim::run_scenario(hover, qrsim::RunOptions{});
    if (!r.error.empty()) {
      std::fprintf(stderr, "sim-bench: the hover did not fly: %s\n", r.error.c_str());
      return 1;
    }
    done.push_back(
        {r.figure("sim_seconds"), r.figure("wall_seconds"), r.figure("cpu_seconds"), r.figure("att_rms_deg_truth")});
  }

  std::vector<double> wall, cpu;
  for (const Run& r : done) {
    wall.push_back(r.wall_seconds);
    cpu.push_back(r.cpu_seconds);
  }
  const double sim = done.front().sim_seconds;
  const double wall_min = *std::min_element(wall.begin(), wall.end());
  // std::clock() ticks in microseconds; a run shorter than one tick would divide by zero.
  const double cpu_min = std::max(*std::min_element(cpu.begin(), cpu.end()), 1e-6);
  std::printf(
      "{\"sim_bench\": \"hover-30s\", \"build\": \"%s\", \"runs\": %d, \"sim_seconds\": %.2f, \"speedup\": %.0f, "
      "\"speedup_median\": %.0f, "
      "\"speedup_cpu\": %.0f, \"speedup_cpu_median\": %.0f, \"wall_seconds_min\": %.4f, \"cpu_seconds_min\": %.4f, "
      "\"att_rms_deg_truth\": %.4g}\n",
      kBuild, runs, sim, sim / std::max(wall_min, 1e-6), sim / std::max(median(wall), 1e-6), sim / cpu_min,
      sim / std::max(median(cpu), 1e-6), wall_min, cpu_min, done.front().att_rms_deg);
  return 0;
}
