// Neighbour-search benchmarks (issue 2, point 5): the per-step rebuild of the Morton-sorted
// grid and a full kernel-sum sweep over it, at 10^4, 10^5 and 10^6 particles in 2D and 3D.
//
// Names carry everything a number depends on, e.g.
//   BM_NeighborBuild/3D/N:1000000/radix/hash/threads:2/double
//   BM_KernelSumSweep/3D/N:1000000/list/threads:2/double   (or cell_walk)
//   BM_NeighborList/3D/N:1000000/threads:2/double      (building the per-step neighbour list)
//   BM_NeighborRefine/3D/N:1000000/threads:2/double    (refining it from candidates with a skin)
//   BM_CellRanges/3D/N:1000000/hash/threads:2/double   (one part of the build, 2 threads only)
// The thread count is imposed with tide::ThreadLimit inside the benchmark (1 and 2 threads are
// registered), the precision is tide::Real (TIDE_REAL_NAME). All times are wall-clock
// (UseRealTime): the work runs on TBB worker threads, whose CPU time the main thread's clock
// would not see.
//
// The particle cloud (see cloud()): a block of fluid in a tank, as in a dam break. A lattice
// of spacing dx, ⌈N^(1/D)⌉ particles wide on every axis but the last, filled in lattice
// order up to exactly N particles (so the top layer may be partial, like a free surface), every
// particle displaced by a uniform jitter of ±0.1 dx. The domain box leaves 4 dx around the block
// on every side and is twice the fluid height on the last axis (the fluid fills about half the
// tank); no axis is periodic. Support radius 2 dx = the cubic spline with h = dx, as usual in SPH,
// so a particle has about 30 neighbours in 3D and 11 in 2D (lattice points closer than 2 dx,
// itself included; fewer at the free surfaces).
//
// Particle order: the lattice is shuffled once (fixed seed) before the first update, so the
// first sort starts from a random order, as after reading an unordered initial condition. That
// first update is not measured. What is measured is the steady state of a simulation: every
// iteration moves each particle by a small random displacement (uniform in ±0.01 dx per axis,
// from a hash of its id and the step, so it does not depend on the order or the thread count),
// then calls grid.update(). The input of each sort is therefore the previous step's order with
// under 1% of the particles in another cell, as in a time step. Displacements alternate in sign
// (step 2k moves by +δ_k, step 2k+1 by −δ_k), so the cloud does not diffuse out of its block over
// the thousands of iterations a small case runs.
//
// The displacement is applied with the timer paused. PauseTiming + ResumeTiming cost about
// 0.3 µs per iteration (BM_PauseResumeOverhead below measures it on the machine at hand), under
// 0.1% of the smallest update measured here (10^4 particles in 2D, about 0.35 ms); timing the
// displacement instead would add a pass over all positions (several % of an update) that is no
// part of the neighbour search.
//
// Counters (all per iteration of the timed loop):
//   particles/s      N / time per update or sweep            (kIsIterationInvariantRate)
//   pair_time        (sweep only) seconds per particle–neighbour pair, printed with an SI prefix ("16.6ns");
//                    pairs = Σ_i |{j : |x_i − x_j| < 2 dx}|, i itself included, counted once
//                    before timing; it is time per iteration / pairs   (Rate | kInvert)
//   neighbors        pairs / N, average neighbours per particle (itself included)
//   grid_B/particle  grid.bytes() / N: memory the neighbour structure holds per particle
//                    (cell codes, sort workspace, cell table, lookup table, neighbour ranges)
//   set_B/particle   particles.field_bytes() / N: the particle set of the benchmark (id,
//                    position, and in the sweep the density field)
//   threads          tide::thread_count() inside the benchmark, to check the name
//
// Reproduce: cmake -S . -B build-bench -DTIDE_BUILD_TESTS=OFF &&
//            cmake --build build-bench -j2 --target neighbor_bench && build-bench/bench/neighbor_bench

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "tide/core/config.hpp"
#include "tide/core/kernels/cubic_spline.hpp"
#include "tide/core/parallel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/types.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/neighbor/neighbor_list.hpp"

namespace {

using tide::Real;

constexpr Real dx = Real(0.01);  // particle spacing; h = dx, support 2 dx
constexpr Real jitter = Real(0.1);
constexpr Real step_displacement = Real(0.01);
constexpr std::uint64_t shuffle_seed = 20240601;
constexpr Real rest_density = Real(1000);

template <int D>
struct Cloud {
  std::vector<tide::Vector<D>> positions;  // shuffled
  tide::GridDomain<D> domain;
};

// Built once per (D, N) and kept: every run of a benchmark copies it into a fresh set.
template <int D>
const Cloud<D>& cloud(std::size_t n) {
  static std::map<std::size_t, Cloud<D>> cache;
  auto found = cache.find(n);
  if (found != cache.end()) return found->second;

  std::size_t width = static_cast<std::size_t>(std::llround(std::pow(double(n), 1.0 / D)));
  auto power = [](std::size_t base, int exponent) {
    std::size_t p = 1;
    for (int e = 0; e < exponent; ++e) p *= base;
    return p;
  };
  while (power(width, D) < n) ++width;
  const std::size_t layers = (n + power(width, D - 1) - 1) / power(width, D - 1);

  Cloud<D> c;
  std::mt19937_64 random(shuffle_seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  c.positions.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t rest = k;
    for (int d = 0; d < D; ++d) {
      const std::size_t cell = d < D - 1 ? rest % width : rest;
      rest /= width;
      c.positions[k][d] = (Real(cell) + Real(0.5) + jitter * Real(unit(random))) * dx;
    }
  }
  std::shuffle(c.positions.begin(), c.positions.end(), random);
  for (int d = 0; d < D; ++d) {
    c.domain.lower[d] = -4 * dx;
    c.domain.upper[d] = (d < D - 1 ? Real(width) : Real(2 * layers)) * dx + 4 * dx;
    c.domain.periodic[d] = false;
  }
  return cache.emplace(n, std::move(c)).first->second;
}

template <int D>
tide::ParticleSet<D> make_particles(const Cloud<D>& c) {
  tide::ParticleSet<D> particles;
  particles.append(c.positions.size());
  auto x = particles[particles.position()];
  for (std::size_t i = 0; i < c.positions.size(); ++i) x.set(i, c.positions[i]);
  return particles;
}

std::uint64_t splitmix64(std::uint64_t s) {
  s += 0x9e3779b97f4a7c15ULL;
  s = (s ^ (s >> 30)) * 0xbf58476d1ce4e5b9ULL;
  s = (s ^ (s >> 27)) * 0x94d049bb133111ebULL;
  return s ^ (s >> 31);
}

// Moves particle i by ±step_displacement·dx·u(id_i, step / 2), u uniform in [-1, 1)^D, + on even
// steps and − on odd ones.
template <int D>
void perturb(tide::ParticleSet<D>& particles, std::uint64_t step) {
  auto x = particles[particles.position()];
  const auto id = particles[particles.id()];
  const Real amplitude = (step % 2 == 0 ? 1 : -1) * step_displacement * dx;
  const std::uint64_t round = step / 2;
  tide::for_each_particle(particles.size(), [&](std::size_t i) {
    std::uint64_t s = splitmix64((std::uint64_t(id[i]) << 32) ^ round);
    tide::Vector<D> xi = x[i];
    for (int d = 0; d < D; ++d) {
      s = splitmix64(s);
      xi[d] += amplitude * Real(double(s >> 11) * 0x1.0p-52 - 1.0);
    }
    x.set(i, xi);
  });
}

template <int D>
std::size_t count_pairs(const tide::NeighborGrid<D>& grid, const tide::ParticleSet<D>& particles) {
  const tide::ConstVectorView<D> x = particles[particles.position()];
  return tide::reduce(
      particles.size(), std::size_t(0),
      [&](std::size_t i) {
        std::size_t count = 0;
        grid.for_each_neighbor(i, x, [&](tide::Index, const tide::Vector<D>&, Real) { ++count; });
        return count;
      },
      [](std::size_t a, std::size_t b) { return a + b; });
}

template <int D>
void set_common_counters(benchmark::State& state, std::size_t n, std::size_t pairs, const tide::NeighborGrid<D>& grid,
                         const tide::ParticleSet<D>& particles, bool per_pair) {
  using benchmark::Counter;
  state.counters["particles/s"] = Counter(double(n), Counter::kIsIterationInvariantRate);
  if (per_pair)
    state.counters["pair_time"] = Counter(double(pairs), Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["neighbors"] = Counter(double(pairs) / double(n));
  state.counters["grid_B/particle"] = Counter(double(grid.bytes()) / double(n));
  state.counters["set_B/particle"] = Counter(double(particles.field_bytes()) / double(n));
  state.counters["threads"] = Counter(double(tide::thread_count()));  // what ThreadLimit gave
}

// One grid.update(): cell codes, sort, one gather per field, cell table, lookup table and the
// merged neighbour ranges of every occupied cell.
template <int D>
void neighbor_build(benchmark::State& state, std::size_t n, tide::SortAlgorithm sort, tide::CellLookup lookup,
                    int threads) {
  tide::ThreadLimit limit(threads);
  const Cloud<D>& c = cloud<D>(n);
  tide::ParticleSet<D> particles = make_particles(c);
  tide::NeighborGrid<D> grid(c.domain, 2 * dx, sort, lookup);
  if (grid.update(particles) != 0) state.SkipWithError("particles left the domain");
  // Two unmeasured steps, so that every workspace has its steady-state size.
  std::uint64_t step = 0;
  for (; step < 2; ++step) {
    perturb(particles, step);
    grid.update(particles);
  }
  for (auto _ : state) {
    state.PauseTiming();
    perturb(particles, step++);
    state.ResumeTiming();
    benchmark::DoNotOptimize(grid.update(particles));
    benchmark::ClobberMemory();
  }
  if (grid.removed_total() != 0) state.SkipWithError("particles left the domain");
  set_common_counters(state, particles.size(), count_pairs(grid, particles), grid, particles, false);
}

// The part of update() that builds every occupied cell's merged neighbour ranges (the grid's
// CrossNeighbors table over itself), timed alone on the grid of a steady-state update, to show
// its share of BM_NeighborBuild.
template <int D>
void cell_ranges(benchmark::State& state, std::size_t n, tide::CellLookup lookup, int threads) {
  tide::ThreadLimit limit(threads);
  const Cloud<D>& c = cloud<D>(n);
  tide::ParticleSet<D> particles = make_particles(c);
  tide::NeighborGrid<D> grid(c.domain, 2 * dx, tide::SortAlgorithm::radix, lookup);
  if (grid.update(particles) != 0) state.SkipWithError("particles left the domain");
  perturb(particles, 0);
  grid.update(particles);
  tide::CrossNeighbors<D> ranges;
  ranges.build(grid, grid);
  for (auto _ : state) {
    ranges.build(grid, grid);
    benchmark::ClobberMemory();
  }
  using benchmark::Counter;
  state.counters["particles/s"] = Counter(double(particles.size()), Counter::kIsIterationInvariantRate);
  state.counters["cells/s"] = Counter(double(grid.occupied_cells()), Counter::kIsIterationInvariantRate);
  state.counters["particles/cell"] = Counter(double(particles.size()) / double(grid.occupied_cells()));
  state.counters["threads"] = Counter(double(tide::thread_count()));
}

// The per-step neighbour list (NeighborList over the grid's own ranges) built alone, on the grid
// of a steady-state update: the extra cost a step pays once so that its passes skip the filter.
template <int D>
void neighbor_list_build(benchmark::State& state, std::size_t n, int threads) {
  tide::ThreadLimit limit(threads);
  const Cloud<D>& c = cloud<D>(n);
  tide::ParticleSet<D> particles = make_particles(c);
  tide::NeighborGrid<D> grid(c.domain, 2 * dx);
  if (grid.update(particles) != 0) state.SkipWithError("particles left the domain");
  perturb(particles, 0);
  grid.update(particles);
  const tide::ConstVectorView<D> x = std::as_const(particles)[particles.position()];
  tide::NeighborList<D> list;
  list.build(grid, x, grid.own_neighbors(), x);
  for (auto _ : state) {
    list.build(grid, x, grid.own_neighbors(), x);
    benchmark::ClobberMemory();
  }
  set_common_counters(state, particles.size(), count_pairs(grid, particles), grid, particles, true);
  state.counters["list_B/particle"] = benchmark::Counter(double(list.bytes()) / double(particles.size()));
}

// The per-step refinement of a list with a skin (solver.neighbor_skin 0.3 spacings, the WCSPH
// default): candidates within support + skin built at one update, then the exact list within the
// support refined from them after the particles have moved (less than half the skin), timed.
template <int D>
void neighbor_list_refine(benchmark::State& state, std::size_t n, int threads) {
  tide::ThreadLimit limit(threads);
  const Cloud<D>& c = cloud<D>(n);
  tide::ParticleSet<D> particles = make_particles(c);
  tide::NeighborGrid<D> grid(c.domain, 2 * dx, tide::SortAlgorithm::radix, tide::CellLookup::automatic, Real(0.3) * dx);
  if (grid.update(particles) != 0) state.SkipWithError("particles left the domain");
  const tide::ConstVectorView<D> x = std::as_const(particles)[particles.position()];
  tide::NeighborList<D> candidates;
  candidates.build(grid, x, grid.own_neighbors(), x);
  perturb(particles, 0);
  tide::NeighborList<D> list;
  list.refine(candidates, x, x);
  for (auto _ : state) {
    list.refine(candidates, x, x);
    benchmark::ClobberMemory();
  }
  set_common_counters(state, particles.size(), count_pairs(grid, particles), grid, particles, true);
  state.counters["candidates_B/particle"] = benchmark::Counter(double(candidates.bytes()) / double(particles.size()));
}

// ρ_i = Σ_j m W(|x_i − x_j|) over all neighbours j (i included): the shape of density
// summation and of every other gather pass, after one update; walking the cells' ranges and
// filtering (`listed` false) or walking a NeighborList built beforehand, untimed (true).
template <int D>
void kernel_sum_sweep(benchmark::State& state, std::size_t n, bool listed, int threads) {
  tide::ThreadLimit limit(threads);
  const Cloud<D>& c = cloud<D>(n);
  tide::ParticleSet<D> particles = make_particles(c);
  const tide::CubicSplineKernel<D> kernel(dx);
  tide::NeighborGrid<D> grid(c.domain, kernel.support_radius());
  if (grid.update(particles) != 0) state.SkipWithError("particles left the domain");
  const auto density_field = particles.add_scalar("density");
  const tide::ConstVectorView<D> x = particles[particles.position()];
  const auto density = particles[density_field];
  const Real mass = rest_density * std::pow(dx, Real(D));
  tide::NeighborList<D> list;
  list.build(grid, x, grid.own_neighbors(), x);
  auto sweep = [&] {
    tide::for_each_particle(particles.size(), [&](std::size_t i) {
      Real sum = 0;
      const auto add = [&](tide::Index, const tide::Vector<D>&, Real r2) { sum += kernel.value(std::sqrt(r2)); };
      if (listed) {
        list.for_each(i, x, x, add);
      } else {
        grid.for_each_neighbor(i, x, add);
      }
      density[i] = mass * sum;
    });
  };
  sweep();
  // Sanity check: most particles are inside the block, where summation gives the rest density
  // (the jitter spreads single values by ±20%, the median stays within a few per cent).
  std::vector<Real> sorted_density(density.begin(), density.end());
  std::nth_element(sorted_density.begin(), sorted_density.begin() + n / 2, sorted_density.end());
  if (std::abs(sorted_density[n / 2] / rest_density - 1) > Real(0.05)) state.SkipWithError("density summation is off");

  for (auto _ : state) {
    sweep();
    benchmark::ClobberMemory();
  }
  set_common_counters(state, particles.size(), count_pairs(grid, particles), grid, particles, true);
}

// What PauseTiming + ResumeTiming cost per iteration (to judge the build benchmarks).
void pause_resume_overhead(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    state.ResumeTiming();
  }
}

std::string size_name(std::size_t n) { return "N:" + std::to_string(n); }
std::string suffix(int threads) { return "/threads:" + std::to_string(threads) + "/" + TIDE_REAL_NAME; }

template <int D>
void register_dimension() {
  const std::string dim = std::to_string(D) + "D";
  for (std::size_t n : {std::size_t(10'000), std::size_t(100'000), std::size_t(1'000'000)}) {
    for (int threads : {1, 2}) {
      for (auto sort : {tide::SortAlgorithm::radix, tide::SortAlgorithm::comparison}) {
        for (auto lookup : {tide::CellLookup::hash, tide::CellLookup::dense}) {
          const std::string name = "BM_NeighborBuild/" + dim + "/" + size_name(n) + "/" +
                                   std::string(tide::sort_algorithm_name(sort)) + "/" +
                                   std::string(tide::cell_lookup_name(lookup)) + suffix(threads);
          auto* b = benchmark::RegisterBenchmark(
              name.c_str(), [=](benchmark::State& state) { neighbor_build<D>(state, n, sort, lookup, threads); });
          b->UseRealTime()->Unit(benchmark::kMillisecond);
          if (n >= 1'000'000) b->Iterations(10);
        }
      }
    }
  }
  for (std::size_t n : {std::size_t(10'000), std::size_t(100'000), std::size_t(1'000'000)}) {
    for (auto lookup : {tide::CellLookup::hash, tide::CellLookup::dense}) {
      const int threads = 2;
      const std::string name = "BM_CellRanges/" + dim + "/" + size_name(n) + "/" +
                               std::string(tide::cell_lookup_name(lookup)) + suffix(threads);
      auto* b = benchmark::RegisterBenchmark(
          name.c_str(), [=](benchmark::State& state) { cell_ranges<D>(state, n, lookup, threads); });
      b->UseRealTime()->Unit(benchmark::kMillisecond);
      if (n >= 1'000'000) b->Iterations(10);
    }
  }
  for (std::size_t n : {std::size_t(10'000), std::size_t(100'000), std::size_t(1'000'000)}) {
    for (int threads : {1, 2}) {
      for (bool listed : {false, true}) {
        const std::string name =
            "BM_KernelSumSweep/" + dim + "/" + size_name(n) + (listed ? "/list" : "/cell_walk") + suffix(threads);
        auto* b = benchmark::RegisterBenchmark(
            name.c_str(), [=](benchmark::State& state) { kernel_sum_sweep<D>(state, n, listed, threads); });
        b->UseRealTime()->Unit(benchmark::kMillisecond);
        if (n >= 1'000'000) b->Iterations(5);
      }
      const std::string name = "BM_NeighborList/" + dim + "/" + size_name(n) + suffix(threads);
      auto* b = benchmark::RegisterBenchmark(
          name.c_str(), [=](benchmark::State& state) { neighbor_list_build<D>(state, n, threads); });
      b->UseRealTime()->Unit(benchmark::kMillisecond);
      if (n >= 1'000'000) b->Iterations(10);
      const std::string refine_name = "BM_NeighborRefine/" + dim + "/" + size_name(n) + suffix(threads);
      auto* r = benchmark::RegisterBenchmark(
          refine_name.c_str(), [=](benchmark::State& state) { neighbor_list_refine<D>(state, n, threads); });
      r->UseRealTime()->Unit(benchmark::kMillisecond);
      if (n >= 1'000'000) r->Iterations(10);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::RegisterBenchmark("BM_PauseResumeOverhead", pause_resume_overhead)->UseRealTime();
  register_dimension<2>();
  register_dimension<3>();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
