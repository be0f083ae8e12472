#pragma once

// Wall-particle pressure, density and velocity from the adjacent fluid (Adami, Hu & Adams 2012).

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/equation_of_state.hpp"
#include "tide/solvers/interactions.hpp"
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

namespace detail {

// What wall_state gives one wall particle, and where it stores it.
template <int D>
struct WallState {
  Vector<D> velocity;
  Real pressure = 0;
  Real density = 0;
};
template <int D, bool WithVelocity>
struct WallStateOutput {
  VectorView<D> velocity;
  std::span<Real> pressure;
  std::span<Real> density;  // empty: the density is left as it is
  bool with_pressure = true;
  void set(std::size_t b, const WallState<D>& state) const {
    if constexpr (WithVelocity) velocity.set(b, state.velocity);
    if (!with_pressure) return;
    pressure[b] = state.pressure;
    if (!density.empty()) density[b] = state.density;
  }
};

}  // namespace detail

/// Adami, Hu & Adams 2012, eq. 27: p_w = (Σ_f p_f W_wf + (g − a_w)·Σ_f ρ_f x_wf W_wf) / Σ_f W_wf,
/// with a_w the wall's acceleration where it has a prescribed motion (zero otherwise), and ρ_w
/// from the equation of state (eq. 28). The velocity a no-slip wall shows the fluid mirrors the
/// Shepard-averaged fluid velocity about the wall's own velocity v_s,
/// v_w = 2 v_s − Σ_f v_f W_wf / Σ_f W_wf (eq. 22–23). Walls with no fluid neighbour get p = 0
/// (plus the background pressure), ρ = ρ0, v = v_s. The fluid's pressure clamp applies to walls
/// too: a wall particle beside the free surface can extrapolate to p < 0. Without
/// `pressure_rule`, the velocity only (p and ρ of the walls are left as they are); the velocity
/// only where the walls have that field (no-slip walls). For one wall contact.
template <int D>
void wall_state(const RuntimeKernel<D>& kernel, Contact<D>& contact, const ParticleSet<D>& fluid,
                const FluidFields<D>& f, const WallPressureExtrapolation<D>* pressure_rule) {
  const WallFields<D>& w = contact.fields();
  ParticleSet<D>& particles = contact.particles();
  const auto x = fluid[f.position];
  const auto v = fluid[f.velocity];
  const auto density = fluid[f.density];
  const auto pressure = fluid[f.pressure];
  const ConstVectorView<D> surface_velocity =
      w.surface_velocity ? std::as_const(particles)[*w.surface_velocity] : ConstVectorView<D>{};
  const ConstVectorView<D> acceleration =
      w.acceleration ? std::as_const(particles)[*w.acceleration] : ConstVectorView<D>{};
  const EquationOfState* eos = pressure_rule ? pressure_rule->eos : nullptr;
  // Compiled with and without the velocity, chosen once: free-slip walls neither sum nor store it;
  // and per kernel (`concrete`), so that the pair loop computes its value inline.
  const auto run = [&]<bool WithVelocity>(const auto& concrete) {
    const detail::WallStateOutput<D, WithVelocity> output{
        // Free-slip walls have no velocity field: no pass reads a wall velocity there.
        w.velocity ? particles[*w.velocity] : VectorView<D>{}, particles[w.pressure],
        eos ? particles[w.density] : std::span<Real>{}, pressure_rule != nullptr};
    for_each_contact_particle<D>(contact, x, output, [&](std::size_t b, const FluidNeighborsOf<D>& fluid_neighbors) {
      detail::WallState<D> state;
      const Vector<D> own_velocity = w.surface_velocity ? surface_velocity[b] : Vector<D>::Zero();
      Real weight_sum = 0;
      Real pressure_sum = 0;
      Vector<D> hydrostatic_sum = Vector<D>::Zero();
      Vector<D> velocity_sum = Vector<D>::Zero();
      // The sums pair by pair in the list's order.
      fluid_neighbors.pairs([&](Index j, const Vector<D>& x_bj, Real r2) {
        const Real weight = concrete.value(std::sqrt(r2));
        weight_sum += weight;
        pressure_sum += pressure[j] * weight;
        hydrostatic_sum += (density[j] * weight) * x_bj;
        if constexpr (WithVelocity) velocity_sum += weight * v[j];
      });
      if constexpr (WithVelocity)
        state.velocity = weight_sum > 0 ? Vector<D>(2 * own_velocity - velocity_sum / weight_sum) : own_velocity;
      if (!pressure_rule) return state;
      if (weight_sum > 0) {
        // A wall that accelerates at a_w feels g − a_w (eq. 27).
        const Vector<D> felt =
            w.acceleration ? Vector<D>(pressure_rule->gravity - acceleration[b]) : pressure_rule->gravity;
        const Real extrapolated = (pressure_sum + felt.dot(hydrostatic_sum)) / weight_sum;
        state.pressure = pressure_rule->clamp_negative_pressure ? std::max(extrapolated, Real(0)) : extrapolated;
        if (eos) state.density = eos->density(state.pressure);
      } else {
        state.pressure = eos ? eos->pressure(eos->rest_density()) : Real(0);
        if (eos) state.density = eos->rest_density();
      }
      return state;
    });
  };
  kernel.visit([&](const auto& concrete) {
    if (w.velocity) {
      run.template operator()<true>(concrete);
    } else {
      run.template operator()<false>(concrete);
    }
  });
}

/// wall_state for every contact of `interactions` that is a wall, but (without `pressure_rule`,
/// the velocity only) not for the walls without a velocity, which it would not change.
template <int D>
void wall_states(const RuntimeKernel<D>& kernel, Interactions<D>& interactions, const ParticleSet<D>& fluid,
                 const FluidFields<D>& f, const WallPressureExtrapolation<D>* pressure_rule) {
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    Contact<D>& contact = interactions.contact(k);
    if (contact.role() != ContactRole::wall || (!pressure_rule && !contact.viscous())) continue;
    wall_state<D>(kernel, contact, fluid, f, pressure_rule);
  }
}

}  // namespace tide::passes
