// Surface reconstruction benchmark (issue 38, point 5): particles per second of
// tide::surface::reconstruct_surface (colour field on the sparse grid, marching cubes, vertex
// numbering) for a ball of 10^5 and 10^6 particles on its lattice, each particle displaced by a
// uniform jitter of ±0.1 Δx (a fixed seed), with the default settings (cubic spline h = 1.2 Δx,
// cells of 0.48 Δx), on 1 and 2 threads.
//
//   BM_SurfaceReconstruction/N:1000000/threads:2/double
//
// Counters: particles_per_second (N / wall time of one reconstruction), triangles. Wall-clock
// times (UseRealTime): the work runs on TBB worker threads.

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "tide/core/config.hpp"
#include "tide/core/parallel.hpp"
#include "tide/surface/surface_mesh.hpp"

namespace {

/// About `count` particles: the lattice points of spacing 1 inside the ball of that volume, jittered.
std::vector<double> jittered_ball(std::size_t count) {
  const double radius = std::cbrt(3.0 * static_cast<double>(count) / (4.0 * std::numbers::pi));
  const int reach = static_cast<int>(std::ceil(radius));
  std::mt19937_64 random(38);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<double> positions;
  for (int z = -reach; z < reach; ++z)
    for (int y = -reach; y < reach; ++y)
      for (int x = -reach; x < reach; ++x) {
        const double p[3] = {x + 0.5, y + 0.5, z + 0.5};
        if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] >= radius * radius) continue;
        for (const double coordinate : p) positions.push_back(coordinate + jitter(random));
      }
  return positions;
}

void BM_SurfaceReconstruction(benchmark::State& state, std::size_t count, int threads) {
  const std::vector<double> positions = jittered_ball(count);
  const tide::ThreadLimit limit(threads);
  std::size_t triangles = 0;
  for (auto _ : state) {
    const tide::scene::TriangleMesh mesh = tide::surface::reconstruct_surface(positions, {.particle_spacing = 1.0});
    triangles = mesh.triangles.size();
    benchmark::DoNotOptimize(mesh.vertices.data());
  }
  state.counters["particles_per_second"] = benchmark::Counter(
      static_cast<double>(positions.size() / 3) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(triangles);
}

const bool registered = [] {
  for (const std::size_t count : {std::size_t(100000), std::size_t(1000000)})
    for (const int threads : {1, 2})
      benchmark::RegisterBenchmark(("BM_SurfaceReconstruction/N:" + std::to_string(count) +
                                    "/threads:" + std::to_string(threads) + "/" + TIDE_REAL_NAME)
                                       .c_str(),
                                   BM_SurfaceReconstruction, count, threads)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
