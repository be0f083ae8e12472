#pragma once

// Wall-particle pressure, density and velocity from the adjacent fluid (Adami, Hu & Adams 2012).

#include <algorithm>

#include "tide/core/parallel.hpp"
#include "tide/solvers/equation_of_state.hpp"
#include "tide/solvers/fluid_wall_neighbors.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// How wall pressure follows the fluid's. Without an equation of state (the incompressible
/// schemes, whose pressure is not a function of density) the walls keep their density ρ0.
template <int D>
struct WallPressureExtrapolation {
  const EquationOfState* eos = nullptr;
  Vector<D> gravity;
  bool clamp_negative_pressure = true;
};

/// Adami, Hu & Adams 2012, eq. 27 for a wall that does not accelerate: p_w = (Σ_f p_f W_wf +
/// g·Σ_f ρ_f x_wf W_wf) / Σ_f W_wf, and ρ_w from the equation of state (eq. 28). The velocity a
/// no-slip wall shows the fluid mirrors the Shepard-averaged fluid velocity about the wall's
/// own velocity v_s, v_w = 2 v_s − Σ_f v_f W_wf / Σ_f W_wf (eq. 22–23). Walls with no fluid
/// neighbour get p = 0 (plus the background pressure), ρ = ρ0, v = v_s. The fluid's pressure
/// clamp applies to walls too: a wall particle beside the free surface can extrapolate to p < 0.
/// Without `pressure_rule`, the velocity only (p and ρ of the walls are left as they are); the
/// velocity only where the walls have that field (no-slip walls).
template <int D, class Kernel>
void wall_state(const Kernel& kernel, ParticleSet<D>& walls, const WallFields<D>& w, const ParticleSet<D>& fluid,
                const FluidFields<D>& f, const FluidWallNeighbors<D>& neighbors,
                const WallPressureExtrapolation<D>* pressure_rule) {
  const auto wall_x = std::as_const(walls)[w.position];
  auto wall_pressure = walls[w.pressure];
  auto wall_density = walls[w.density];
  // Free-slip walls have no velocity field: no pass reads a wall velocity there.
  const VectorView<D> wall_velocity = w.velocity ? walls[*w.velocity] : VectorView<D>{};
  const auto x = fluid[f.position];
  const auto v = fluid[f.velocity];
  const auto density = fluid[f.density];
  const auto pressure = fluid[f.pressure];
  const ConstVectorView<D> surface_velocity =
      w.surface_velocity ? std::as_const(walls)[*w.surface_velocity] : ConstVectorView<D>{};
  // Compiled with and without the velocity, chosen once: free-slip walls neither sum nor store it.
  const auto run = [&]<bool WithVelocity>() {
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
        if constexpr (WithVelocity) velocity_sum += weight * v[j];
      });
      if constexpr (WithVelocity)
        wall_velocity.set(b, weight_sum > 0 ? Vector<D>(2 * own_velocity - velocity_sum / weight_sum) : own_velocity);
      if (!pressure_rule) return;
      const EquationOfState* eos = pressure_rule->eos;
      if (weight_sum > 0) {
        const Real extrapolated = (pressure_sum + pressure_rule->gravity.dot(hydrostatic_sum)) / weight_sum;
        const Real p = pressure_rule->clamp_negative_pressure ? std::max(extrapolated, Real(0)) : extrapolated;
        wall_pressure[b] = p;
        if (eos) wall_density[b] = eos->density(p);
      } else {
        wall_pressure[b] = eos ? eos->pressure(eos->rest_density()) : Real(0);
        if (eos) wall_density[b] = eos->rest_density();
      }
    });
  };
  if (w.velocity) {
    run.template operator()<true>();
  } else {
    run.template operator()<false>();
  }
}

}  // namespace tide::passes
