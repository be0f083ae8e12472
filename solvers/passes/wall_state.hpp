#pragma once

// Wall-particle pressure, density and velocity from the adjacent fluid (Adami, Hu & Adams 2012).

#include <algorithm>

#include "tide/core/parallel.hpp"
#include "tide/solvers/fluid_wall_neighbors.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide::passes {

/// Adami, Hu & Adams 2012, eq. 27 for a wall that does not accelerate: p_w = (Σ_f p_f W_wf +
/// g·Σ_f ρ_f x_wf W_wf) / Σ_f W_wf, and ρ_w from the equation of state (eq. 28). The velocity a
/// no-slip wall shows the fluid mirrors the Shepard-averaged fluid velocity about the wall's
/// own velocity v_s, v_w = 2 v_s − Σ_f v_f W_wf / Σ_f W_wf (eq. 22–23). Walls with no fluid
/// neighbour get p = 0 (plus the background pressure), ρ = ρ0, v = v_s. The fluid's pressure
/// clamp applies to walls too: a wall particle beside the free surface can extrapolate to p < 0.
template <int D, class Kernel>
void wall_state(const Kernel& kernel, ParticleSet<D>& walls, const WallFields<D>& w, const ParticleSet<D>& fluid,
                const FluidFields<D>& f, const FluidWallNeighbors<D>& neighbors, const EquationOfState& eos,
                const Vector<D>& gravity, bool clamp_negative_pressure) {
  const auto wall_x = std::as_const(walls)[w.position];
  auto wall_pressure = walls[w.pressure];
  auto wall_density = walls[w.density];
  auto wall_velocity = walls[w.velocity];
  const auto x = fluid[f.position];
  const auto v = fluid[f.velocity];
  const auto density = fluid[f.density];
  const auto pressure = fluid[f.pressure];
  const ConstVectorView<D> surface_velocity =
      w.surface_velocity ? std::as_const(walls)[*w.surface_velocity] : ConstVectorView<D>{};
  for_each_particle(walls.size(), [&](std::size_t b) {
    const Vector<D> own_velocity = w.surface_velocity ? surface_velocity[b] : Vector<D>::Zero();
    Real weight_sum = 0;
    Real pressure_sum = 0;
    Vector<D> hydrostatic_sum = Vector<D>::Zero();
    Vector<D> velocity_sum = Vector<D>::Zero();
    neighbors.for_each_fluid_neighbor_of_wall(b, wall_x, x, [&](Index j, const Vector<D>& x_wf, Real r2) {
      const Real weight = kernel.value(std::sqrt(r2));
      weight_sum += weight;
      pressure_sum += pressure[j] * weight;
      hydrostatic_sum += (density[j] * weight) * x_wf;
      velocity_sum += weight * v[j];
    });
    if (weight_sum > 0) {
      const Real extrapolated = (pressure_sum + gravity.dot(hydrostatic_sum)) / weight_sum;
      const Real p = clamp_negative_pressure ? std::max(extrapolated, Real(0)) : extrapolated;
      wall_pressure[b] = p;
      wall_density[b] = eos.density(p);
      wall_velocity.set(b, 2 * own_velocity - velocity_sum / weight_sum);
    } else {
      wall_pressure[b] = eos.pressure(eos.rest_density());
      wall_density[b] = eos.rest_density();
      wall_velocity.set(b, own_velocity);
    }
  });
}

}  // namespace tide::passes
