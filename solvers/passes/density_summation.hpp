#pragma once

// Density by kernel summation over fluid and wall particles, fused with what a scheme derives
// from it per particle (WCSPH: the equation of state).

#include <array>
#include <cmath>
#include <span>

#include "tide/core/parallel.hpp"
#include "tide/solvers/fluid_wall_neighbors.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// ρ_i = Σ_j m_j W_ij over fluid and wall neighbours (Monaghan 1992, eq. 2.7), then
/// then_each(i, ρ_i), which may write particle i's other fields.
template <int D, class Kernel, class ThenEach>
void density_summation(const Kernel& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                       const FluidWallNeighbors<D>& neighbors, const ParticleSet<D>& walls, const WallFields<D>& w,
                       ThenEach&& then_each) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto wall_x = walls[w.position];
  const auto wall_mass = walls[w.mass];
  auto density = fluid[f.density];
  // Kernel values of a batch in a loop the compiler vectorises, then summed in neighbour order.
  const auto add = [&](const NeighborBatch<D>& b, std::span<const Real> m, Real& sum) {
    std::array<Real, batch_size> terms;
    for (Index k = 0; k < b.count; ++k) terms[k] = m[b.j[k]] * kernel.value(std::sqrt(b.r2[k]));
    for (Index k = 0; k < b.count; ++k) sum += terms[k];
  };
  for_each_particle(fluid.size(), [&](std::size_t i) {
    Real sum = 0;
    neighbors.for_each_fluid_batch(i, x, [&](const NeighborBatch<D>& b) { add(b, mass, sum); });
    neighbors.for_each_wall_batch(i, x, wall_x, [&](const NeighborBatch<D>& b) { add(b, wall_mass, sum); });
    density[i] = sum;
    then_each(i, sum);
  });
}

}  // namespace tide::passes
