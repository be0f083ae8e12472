// Crowd step benchmarks (issue 36, point 6): one time step of the crowd scheme (solver.scheme
// "crowd", docs/crowds.md) at 10^4 and 10^5 agents, with 1 and 2 threads.
//
//   BM_CrowdStep/N:<n>/threads:<t>/<real>
//
// The scene: a corridor periodic along x, 40 m wide between walls 0.3 m thick (wall particles
// 0.1 m apart, Wendland C2 with h = 0.5 m, as scenes/crowd_corridor_periodic.json), n agents on
// the start lattice at 1.5 persons/m² of its length × width, all walking along +x with the
// default parameters (desired speeds N(1.34, 0.26) m/s, seed 1). Warm-up: 20 untimed steps;
// then every iteration is one step(). Times are wall-clock (UseRealTime).
//
// Counters: agent-steps/s (agents / wall seconds per step), sim_s/step (mean simulated seconds
// per step), wall_per_sim_s (wall seconds per simulated second: below 1 is faster than real time),
// cpu_util (process CPU time / (wall time × threads): near 1 when every thread had a core; a row
// well below it was disturbed, re-run it).
//
// Reproduce: cmake --build build --target crowd_bench && build/bench/crowd_bench

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <cstddef>
#include <sstream>
#include <string>

#include "tide/core/config.hpp"
#include "tide/core/parallel.hpp"
#include "tide/io/scene_reader.hpp"
#include "tide/solvers/crowd_sph.hpp"

namespace {

constexpr int warmup_steps = 20;

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}
constexpr double corridor_width = 40;  // m
constexpr double density = 1.5;        // persons/m²

tide::scene::Scene corridor(std::size_t agents) {
  const double length = static_cast<double>(agents) / (density * corridor_width);
  std::ostringstream json;
  json << R"({"dimension": 2, "particle_spacing": 0.1, "kernel": {"type": "wendland_c2", "smoothing_ratio": 5},)"
       << R"("crowd": {"agents": [{"region": {"min": [0, 0.3], "max": [)" << length << ", " << corridor_width - 0.3
       << R"(]}, "count": )" << agents << R"(, "heading": [1, 0]}]}, )"
       << R"("walls": {"obstacles": [{"box": {"min": [0, -0.3], "max": [)" << length << R"(, 0]}}, )"
       << R"({"box": {"min": [0, )" << corridor_width << R"(], "max": [)" << length << ", " << corridor_width + 0.3
       << "]}}]}, "
       << R"("domain": {"min": [0, -0.5], "max": [)" << length << ", " << corridor_width + 0.5
       << R"(], "periodic": [true, false]}, "gravity": [0, 0], "solver": {"scheme": "crowd"}, "time": {"end": 1e6}})";
  return tide::io::parse_scene(json.str(), "crowd_bench_corridor");
}

void crowd_steps(benchmark::State& state, std::size_t agents, int threads) {
  tide::ThreadLimit limit(threads);
  tide::CrowdSph crowd(corridor(agents));
  for (int step = 0; step < warmup_steps; ++step) crowd.step();
  const double time_before = crowd.time();
  const double cpu_start = process_cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    crowd.step();
    benchmark::ClobberMemory();
  }
  const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  const double steps = static_cast<double>(state.iterations());
  const double simulated = crowd.time() - time_before;
  using benchmark::Counter;
  state.counters["agent-steps/s"] =
      Counter(static_cast<double>(crowd.fluid().size()), Counter::kIsIterationInvariantRate);
  state.counters["sim_s/step"] = Counter(simulated / steps);
  state.counters["wall_per_sim_s"] = Counter(wall_seconds / simulated);
  state.counters["agents"] = Counter(static_cast<double>(crowd.fluid().size()));
  state.counters["threads"] = Counter(threads);
  state.counters["cpu_util"] = Counter(cpu_seconds / (wall_seconds * threads));
}

}  // namespace

int main(int argc, char** argv) {
  for (const std::size_t agents : {10'000, 100'000, 1'000'000}) {
    for (const int threads : {1, 2}) {
      const std::string name =
          "BM_CrowdStep/N:" + std::to_string(agents) + "/threads:" + std::to_string(threads) + "/" + TIDE_REAL_NAME;
      benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) { crowd_steps(state, agents, threads); })
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond)
          ->Iterations(agents >= 1'000'000 ? 5
                       : agents >= 100'000 ? 20
                                           : 200);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
