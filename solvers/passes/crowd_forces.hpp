#pragma once

// The accelerations of a crowd's agents (docs/crowds.md, "Model"): relaxation toward each
// agent's desired velocity at the speed the space ahead allows, the SPH force of the
// uneasiness pressure, and the short-range body repulsion between agents and from walls. One
// agent's sum gathers from its neighbours only.

#include <cmath>
#include <limits>
#include <utility>

#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// The model's constants in the particles' precision.
struct CrowdForceSettings {
  Real relaxation_time;     // τ
  Real agent_mass;          // m
  Real body_radius;         // r
  Real repulsion_strength;  // A
  Real repulsion_range;     // B
  Real body_stiffness;      // k
  Real wall_offset;         // Δx/2: from a wall's outermost particle to its surface
  Real time_gap;            // T of the speed from the space ahead
  Real agent_length;        // ℓ: the headway at which that speed is zero
  Real steering_strength;   // a of the direction model
  Real steering_range;      // D of the direction model

  static CrowdForceSettings of(const scene::Scene& scene) {
    const scene::Crowd& c = *scene.crowd;
    return {static_cast<Real>(c.relaxation_time),
            static_cast<Real>(c.agent_mass),
            static_cast<Real>(c.body_radius),
            static_cast<Real>(c.repulsion_strength),
            static_cast<Real>(c.repulsion_range),
            static_cast<Real>(c.body_stiffness),
            static_cast<Real>(scene.particle_spacing / 2),
            static_cast<Real>(c.time_gap),
            static_cast<Real>(c.agent_length),
            static_cast<Real>(c.steering_strength),
            static_cast<Real>(c.steering_range)};
  }

  /// The speed an agent whose nearest agent ahead stands `headway` away walks at most:
  /// V(s) = min(v0, max(0, (s − ℓ)/T)), the optimal speed function of the collision-free speed
  /// model (Tordeux, Chraibi & Seyfried 2016, eq. 3), the required length ℓ + T v of Seyfried et
  /// al. 2005 (eq. 3, d = a + b v) solved for v.
  Real headway_speed(Real desired, Real headway) const {
    return std::min(desired, std::max((headway - agent_length) / time_gap, Real(0)));
  }

  /// How strongly an agent `distance` away turns one's walking direction away from it:
  /// R(s) = a exp((ℓ − s)/D) (Tordeux, Chraibi & Seyfried 2016, eq. 5).
  Real steering(Real distance) const {
    return steering_strength * std::exp((agent_length - distance) / steering_range);
  }

  /// The distance within which an agent ahead can slow one of desired speed at most
  /// `fastest`: V(s) = v0 needs s ≥ ℓ + T v0.
  Real headway_range(Real fastest) const { return agent_length + time_gap * fastest; }

  /// The magnitude of the repulsion between bodies whose surfaces are `gap` apart (negative:
  /// overlapping): A exp(−gap/B) + k max(−gap, 0), Helbing, Farkas & Vicsek 2000, eq. 2 (its
  /// sliding friction left out), per unit of the agent's mass.
  Real repulsion(Real gap) const {
    return (repulsion_strength * std::exp(-gap / repulsion_range) + body_stiffness * std::max(-gap, Real(0))) /
           agent_mass;
  }
};

/// a_i = (V(s_i) e_i − v_i)/τ (Helbing & Molnár 1995, eq. 2, with the speed V(s_i) ≤ v0_i that
///       the headway s_i allows, Tordeux, Chraibi & Seyfried 2016, eqs. 3-4)
///       − Σ_j (p_i/ρ_i² + p_j/ρ_j²) ∇W_ij (Monaghan 1992, eq. 3.3, with m_j = 1 person)
///       + Σ_j f(|x_ij| − 2r) x_ij/|x_ij| + f(d_iW − r) n_iW (Helbing, Farkas & Vicsek 2000, eqs. 2, 3)
/// with e_i the walking direction: the desired direction e0_i = direction(i, x_i) turned away from
/// the agents close by, e_i ∝ e0_i + Σ_j R(|x_ij|) x_ij/|x_ij| (Tordeux, Chraibi & Seyfried 2016,
/// eq. 5), and d_iW, n_iW the distance to and the normal from the nearest wall surface, taken
/// from the nearest wall particle of each wall contact.
template <class Direction>
void crowd_acceleration(const RuntimeKernel<2>& kernel, const CrowdForceSettings& settings, const Direction& direction,
                        const ParticleSet<2>& agents, const FluidFields<2>& f, ScalarField desired_speed,
                        const Interactions<2>& interactions, VectorView<2> acceleration) {
  const auto x = agents[f.position];
  const auto v = agents[f.velocity];
  const auto rho = agents[f.density];
  const auto p = agents[f.pressure];
  const auto v0 = agents[desired_speed];
  const Real contact_distance = 2 * settings.body_radius;
  const Real support = kernel.support_radius();
  for_each_fluid_particle<2>(interactions, x, VectorOutput<2>{acceleration}, [&](std::size_t i, const auto& neighbors) {
    Vector<2> a = Vector<2>::Zero();
    const Vector<2> desired = direction(i, x[i]);
    Vector<2> turned = desired;
    const Real p_over_rho2 = p[i] / (rho[i] * rho[i]);
    const bool uneasy = p[i] > 0;
    neighbors.fluid_pairs([&](std::size_t j, const Vector<2>& x_ij, Real r2) {
      if (!(r2 > 0)) return;
      const Real r = std::sqrt(r2);
      // Most pairs of the list (reach 2.5 m) lie beyond the kernel's support, and below the
      // comfortable density both pressures are zero: the pressure term is then exactly zero, and
      // neither the kernel nor the division is evaluated.
      if (r < support && (uneasy || p[j] > 0))
        a -= (p_over_rho2 + p[j] / (rho[j] * rho[j])) * kernel.derivative_over_r(r) * x_ij;
      a += settings.repulsion(r - contact_distance) / r * x_ij;
      turned += settings.steering(r) / r * x_ij;
    });
    const Real turned_norm = turned.norm();
    const Vector<2> e = turned_norm > 0 ? Vector<2>(turned / turned_norm) : desired;
    const Vector<2> across(-e[1], e[0]);
    // The agents ahead of i in its walking direction whose bodies are in its way (closer to its
    // line of walking than a body diameter): the neighbours of Tordeux, Chraibi & Seyfried 2016,
    // eq. 4, the nearest of which sets the headway s_i.
    Real headway2 = std::numeric_limits<Real>::infinity();
    neighbors.fluid_pairs([&](std::size_t, const Vector<2>& x_ij, Real r2) {
      if (r2 > 0 && e.dot(x_ij) < 0 && std::abs(across.dot(x_ij)) <= contact_distance)
        headway2 = std::min(headway2, r2);
    });
    a += (settings.headway_speed(v0[i], std::sqrt(headway2)) * e - v[i]) / settings.relaxation_time;
    neighbors.contacts([&](const auto& contact) {
      Real nearest2 = std::numeric_limits<Real>::infinity();
      Vector<2> nearest = Vector<2>::Zero();
      contact.pairs([&](std::size_t, const Vector<2>& x_ib, Real r2) {
        if (r2 < nearest2) {
          nearest2 = r2;
          nearest = x_ib;
        }
      });
      if (!(nearest2 > 0) || nearest2 == std::numeric_limits<Real>::infinity()) return;
      const Real r = std::sqrt(nearest2);
      a += settings.repulsion(r - settings.wall_offset - settings.body_radius) / r * nearest;
    });
    return a;
  });
}

}  // namespace tide::passes
