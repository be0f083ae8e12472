// WCSPH step benchmarks (issue 3, point 8): one full time step of the weakly compressible solver
// (tide::Wcsph<D>::step) on the dam-break set-up, at 10^4, 10^5 and 10^6 fluid particles in 2D
// and 3D, with 1 and 2 threads.
//
// Names carry everything a number depends on, e.g.
//   BM_WcsphStep/3D/N:1000000/threads:2/double
// N is the nominal fluid particle count; the column holds a lattice whose side counts are the
// integers nearest to N (2D: k × 2k with 2k² ≈ N; 3D: k³ ≈ N), the exact count is the `fluid`
// counter. The thread count is imposed with tide::ThreadLimit inside the benchmark, the
// precision is tide::Real (TIDE_REAL_NAME). All times are wall-clock (UseRealTime): the work runs
// on TBB worker threads, whose CPU time the main thread's clock would not see.
//
// The scenes (see dam_break()) are those shipped in scenes/, with only the spacing changed:
//   2D  scenes/dam_break_2d.json: Martin & Moyce, a column a wide and 2a high (a = 0.05715 m) in a
//       tank 5a × 3a, open top, free-slip walls of 3 layers, Wendland C2 with h = 1.3 dx (support
//       2.6 dx), Tait EOS, c0 = 10 × 1.5 m/s, artificial viscosity α = 0.02, density summation.
//   3D  scenes/dam_break_3d.json: a 1 m cube of water in the corner of a 4 × 1.5 × 3 m tank (z up),
//       open top, free-slip walls of 2 layers, cubic spline with h = dx (support 2 dx, the
//       SPlisHSPlasH reference set-up), c0 = 10 × 4.5 m/s, α = 0.02, density summation.
//   The domain is the container with room for its wall layers and, above the open top, as much
//   again as the container is high (what io/ derives when a scene has no "domain" key).
// The wall particles are part of every step (wall state pass, fluid–wall terms) but are not
// counted in particle-steps/s; their number per fluid particle falls as N grows (walls ∝ N^(1-1/D)
// against the fluid's N): the `walls/fluid` counter gives it.
//
// Warm-up: the simulation is constructed (sampling, first sort, first density and forces) and
// runs `warmup_steps` steps outside timing, so that the measured steps start from a relaxed flow
// (density and pressure fields settled off the initial lattice, the particle order that of a
// previous sort) rather than from the constructor's state. The timed loop then calls step() once
// per iteration; the flow keeps evolving during the timed steps (the column starts to collapse),
// which is what a run does and is fine for a per-step cost. Each benchmark function constructs its
// simulation once; iteration counts are fixed (see iterations()) so that the 10^6 cases, whose
// construction and warm-up take tens of seconds, run their function only once.
//
// Counters (all per iteration of the timed loop = per step):
//   particle-steps/s  fluid particles / wall seconds per step              (kIsIterationInvariantRate)
//   B/particle        Wcsph::bytes_per_particle(): fluid and wall fields plus every neighbour
//                     table (fluid grid, wall grid, fluid→wall and wall→fluid ranges), per fluid
//                     particle
//   f_nbr, f_density, f_wall, f_momentum, f_integr
//                     share of the step in each part, from the differences of Wcsph::pass_times()
//                     across the timed loop divided by the wall time of that loop:
//                     neighbour search (sort, reorder, cell tables, fluid↔wall ranges), density
//                     summation + EOS, wall state (Adami extrapolation), momentum (pressure,
//                     viscosity, gravity), integration (kick, drift, kick, stability check). The
//                     five add up to the step minus the time-step choice and the clock reads
//                     (f_other = 1 − their sum).
//   neighbors         fluid neighbours per fluid particle (itself included, r < support), counted
//                     once after the timed loop (fluid–wall pairs are not included)
//   fluid, walls/fluid   exact fluid particle count, wall particles per fluid particle
//   threads           tide::thread_count() inside the benchmark, to check the name
//   cpu_util          CPU seconds of the whole process during the timed loop / (wall seconds ×
//                     threads). Near 1 when every thread had a core to itself the whole time;
//                     clearly below 1 with 2 threads means the threads waited (serial sections,
//                     imbalance) or another process took a core: a row to re-run on an idle
//                     machine before quoting it.
//
// Reproduce: cmake -S . -B build-bench -DTIDE_BUILD_TESTS=OFF &&
//            cmake --build build-bench -j2 --target wcsph_bench && build-bench/bench/wcsph_bench

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <optional>
#include <string>

#include "tide/core/config.hpp"
#include "tide/core/parallel.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/wcsph.hpp"

namespace {

using tide::Real;

constexpr int warmup_steps = 20;

// The shipped dam-break scene of dimension D with the spacing chosen so that the column holds
// about n fluid particles.
tide::scene::Scene dam_break(int dimension, std::size_t n) {
  namespace scene = tide::scene;
  scene::Scene s;
  s.source = "wcsph_bench dam break " + std::to_string(dimension) + "D";
  s.dimension = dimension;
  s.walls.slip = scene::WallSlip::free_slip;
  s.solver.alpha = 0.02;
  scene::Vec tank{};
  if (dimension == 2) {
    // a/dx = k, column k × 2k particles.
    const double a = 0.05715;
    const double k = std::round(std::sqrt(double(n) / 2));
    s.particle_spacing = a / k;
    s.kernel = tide::KernelType::wendland_c2;
    s.smoothing_ratio = 1.3;
    s.walls.layers = 3;
    s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 1.5});
    s.fluid.push_back({0, scene::Box{{0, 0, 0}, {a, 2 * a, 0}}});
    tank = {5 * a, 3 * a, 0};
    s.gravity = {0, -9.81, 0};
  } else {
    // 1 m cube, k³ particles.
    const double k = std::round(std::cbrt(double(n)));
    s.particle_spacing = 1.0 / k;
    s.kernel = tide::KernelType::cubic_spline;
    s.smoothing_ratio = 1.0;
    s.walls.layers = 2;
    s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 4.5});
    s.fluid.push_back({0, scene::Box{{0, 0, 0}, {1, 1, 1}}});
    tank = {4, 1.5, 3};
    s.gravity = {0, 0, -9.81};
  }
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, tank}, true};
  // The domain io/ derives: the container plus its wall thickness, and above the open top as much
  // again as the container is high.
  const double wall = s.walls.layers * s.particle_spacing;
  for (int d = 0; d < dimension; ++d) {
    s.domain.box.min[d] = -wall;
    s.domain.box.max[d] = tank[d] + wall;
  }
  s.domain.box.max[dimension - 1] += tank[dimension - 1];
  return s;
}

// User + system CPU seconds of the whole process (all threads) so far.
double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

template <int D>
std::size_t count_fluid_pairs(const tide::Wcsph<D>& simulation) {
  const tide::ConstVectorView<D> x = simulation.fluid()[simulation.fluid_fields().position];
  const tide::NeighborGrid<D>& grid = simulation.fluid_grid();
  return tide::reduce(
      simulation.fluid().size(), std::size_t(0),
      [&](std::size_t i) {
        std::size_t count = 0;
        grid.for_each_neighbor(i, x, [&](tide::Index, const tide::Vector<D>&, Real) { ++count; });
        return count;
      },
      [](std::size_t a, std::size_t b) { return a + b; });
}

template <int D>
void wcsph_step(benchmark::State& state, std::size_t n, int threads) {
  tide::ThreadLimit limit(threads);
  try {
    tide::Wcsph<D> simulation(dam_break(D, n));
    for (int s = 0; s < warmup_steps; ++s) simulation.step();

    const tide::PassTimes before = simulation.pass_times();
    const double cpu_start = process_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
      benchmark::DoNotOptimize(simulation.step());
      benchmark::ClobberMemory();
    }
    const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu_seconds = process_cpu_seconds() - cpu_start;
    const tide::PassTimes after = simulation.pass_times();

    if (simulation.removed_total() != 0) {
      state.SkipWithError("particles left the domain");
      return;
    }
    const double fluid = double(simulation.fluid().size());
    using benchmark::Counter;
    state.counters["particle-steps/s"] = Counter(fluid, Counter::kIsIterationInvariantRate);
    state.counters["B/particle"] = Counter(simulation.bytes_per_particle());
    const double f_nbr = (after.neighbor_search - before.neighbor_search) / wall_seconds;
    const double f_density = (after.density - before.density) / wall_seconds;
    const double f_wall = (after.wall_state - before.wall_state) / wall_seconds;
    const double f_momentum = (after.momentum - before.momentum) / wall_seconds;
    const double f_integr = (after.integration - before.integration) / wall_seconds;
    state.counters["f_nbr"] = Counter(f_nbr);
    state.counters["f_density"] = Counter(f_density);
    state.counters["f_wall"] = Counter(f_wall);
    state.counters["f_momentum"] = Counter(f_momentum);
    state.counters["f_integr"] = Counter(f_integr);
    state.counters["f_other"] = Counter(1 - (f_nbr + f_density + f_wall + f_momentum + f_integr));
    state.counters["neighbors"] = Counter(double(count_fluid_pairs(simulation)) / fluid);
    state.counters["fluid"] = Counter(fluid);
    state.counters["walls/fluid"] = Counter(double(simulation.walls().size()) / fluid);
    state.counters["threads"] = Counter(double(tide::thread_count()));  // what ThreadLimit gave
    state.counters["cpu_util"] = Counter(cpu_seconds / (wall_seconds * threads));
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
  }
}

// Fixed per size: 0.6 to 8 seconds of timed steps per row on the 2-core reference machine, about
// 2 minutes for the whole binary (docs/performance.md).
benchmark::IterationCount iterations(std::size_t n) {
  if (n >= 1'000'000) return 5;
  if (n >= 100'000) return 20;
  return 200;
}

std::string size_name(std::size_t n) { return "N:" + std::to_string(n); }
std::string suffix(int threads) { return "/threads:" + std::to_string(threads) + "/" + TIDE_REAL_NAME; }

template <int D>
void register_dimension() {
  const std::string dim = std::to_string(D) + "D";
  for (std::size_t n : {std::size_t(10'000), std::size_t(100'000), std::size_t(1'000'000)}) {
    for (int threads : {1, 2}) {
      const std::string name = "BM_WcsphStep/" + dim + "/" + size_name(n) + suffix(threads);
      auto* b = benchmark::RegisterBenchmark(name.c_str(),
                                             [=](benchmark::State& state) { wcsph_step<D>(state, n, threads); });
      b->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(iterations(n));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_dimension<2>();
  register_dimension<3>();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
