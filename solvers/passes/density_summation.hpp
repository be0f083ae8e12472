#pragma once

// Density by kernel summation over fluid and wall particles, fused with what a scheme derives
// from it per particle (WCSPH: the equation of state).

#include <cmath>

#include "tide/core/parallel.hpp"
#include "tide/solvers/fluid_wall_neighbors.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// ρ_i = Σ_j m_j W_ij over fluid and wall neighbours (Monaghan 1992, eq. 2.7), then
/// then_each(i, ρ_i), which may write particle i's other fields. With `NumberDensity` (several
/// fluids of different density): ρ_i = m_i Σ_j W_ij, the particle's own mass times its number
/// density (Hu & Adams 2006, eq. 4), so the density is sharp across an interface instead of
/// smeared over a kernel support.
template <int D, bool NumberDensity = false, class Kernel, class ThenEach>
void density_summation(const Kernel& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                       const FluidWallNeighbors<D>& neighbors, const ParticleSet<D>& walls, const WallFields<D>& w,
                       ThenEach&& then_each) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto wall_x = walls[w.position];
  const auto wall_mass = walls[w.mass];
  auto density = fluid[f.density];
  for_each_particle(fluid.size(), [&](std::size_t i) {
    Real sum = 0;
    if constexpr (NumberDensity) {
      neighbors.for_each_fluid_neighbor(i, x,
                                        [&](Index, const Vector<D>&, Real r2) { sum += kernel.value(std::sqrt(r2)); });
      neighbors.for_each_wall_neighbor(i, x, wall_x,
                                       [&](Index, const Vector<D>&, Real r2) { sum += kernel.value(std::sqrt(r2)); });
      sum *= mass[i];
    } else {
      neighbors.for_each_fluid_run(i, x, [&](const NeighborRun<D>& run) {
        accumulate(run, sum, [&](int k) { return mass[run.index[k]] * kernel.value(std::sqrt(run.r2[k])); });
      });
      neighbors.for_each_wall_run(i, x, wall_x, [&](const NeighborRun<D>& run) {
        accumulate(run, sum, [&](int k) { return wall_mass[run.index[k]] * kernel.value(std::sqrt(run.r2[k])); });
      });
    }
    density[i] = sum;
    then_each(i, sum);
  });
}

}  // namespace tide::passes
