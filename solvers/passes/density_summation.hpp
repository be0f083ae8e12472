#pragma once

// Density by kernel summation over fluid and wall particles, fused with the equation of state.

#include <algorithm>
#include <cmath>

#include "tide/core/parallel.hpp"
#include "tide/solvers/fluid_wall_neighbors.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide::passes {

/// ρ_i = Σ_j m_j W_ij over fluid and wall neighbours (Monaghan 1992, eq. 2.7), then p_i = p(ρ_i).
/// With `clamp_negative_pressure` a particle near the free surface, whose kernel is only partly
/// filled, gets p = 0 instead of a tension that would pull particles into clumps.
template <int D, class Kernel>
void density_summation(const Kernel& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                       const FluidWallNeighbors<D>& neighbors, const ParticleSet<D>& walls, const WallFields<D>& w,
                       const EquationOfState& eos, bool clamp_negative_pressure) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto wall_x = walls[w.position];
  const auto wall_mass = walls[w.mass];
  auto density = fluid[f.density];
  auto pressure = fluid[f.pressure];
  for_each_particle(fluid.size(), [&](std::size_t i) {
    Real sum = 0;
    neighbors.for_each_fluid_neighbor(
        i, x, [&](Index j, const Vector<D>&, Real r2) { sum += mass[j] * kernel.value(std::sqrt(r2)); });
    neighbors.for_each_wall_neighbor(
        i, x, wall_x, [&](Index b, const Vector<D>&, Real r2) { sum += wall_mass[b] * kernel.value(std::sqrt(r2)); });
    density[i] = sum;
    const Real p = eos.pressure(sum);
    pressure[i] = clamp_negative_pressure ? std::max(p, Real(0)) : p;
  });
}

}  // namespace tide::passes
