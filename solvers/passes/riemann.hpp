#pragma once

// The low-dissipation Riemann-solver WCSPH of Zhang, Hu & Adams 2017 (J. Comput. Phys. 340,
// 439–455): each pair's pressure and velocity in the momentum and continuity equations come from
// a linearised acoustic Riemann problem between the two particles, with a limiter that keeps the
// dissipation only where they approach.

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "kernel_correction.hpp"
#include "momentum.hpp"
#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// What both Riemann passes need: the sound speed of the linearised problem, and, for the
/// continuity equation's hydrostatic correction, ρ0 and gravity.
template <int D>
struct RiemannSettings {
  Real sound_speed = 0;
  Real rest_density = 0;
  Vector<D> gravity = Vector<D>::Zero();
};

namespace detail {

// P* = (p_L + p_R)/2 + ρ̄ β (U_L − U_R)/2 with β = min(3 max(U_L − U_R, 0), c0): Zhang, Hu & Adams
// 2017, eq. 17 with the limiter of eq. 23. U_L − U_R = (v_i − v_j)·e_ij, e_ij the unit vector
// from i to j, i.e. −v_ij·x_ij/r: positive where the pair approaches.
inline Real riemann_pressure(Real p_i, Real p_j, Real rho_i, Real rho_j, Real approach, Real sound_speed) {
  const Real beta = std::clamp(3 * approach, Real(0), sound_speed);
  return Real(0.5) * (p_i + p_j) + Real(0.25) * (rho_i + rho_j) * beta * approach;
}

// One contact's fields as the Riemann passes read them: a wall particle is a right state with its
// extrapolated pressure and density (Adami, Hu & Adams 2012) moving with its wall's surface
// velocity (at rest where the wall does not move).
template <int D>
struct RiemannContact {
  std::span<const Real> mass;
  std::span<const Real> density;
  std::span<const Real> pressure;
  ConstVectorView<D> surface_velocity;
  bool moving;
  // The mirrored no-slip velocity for the viscous terms, where the wall has one.
  ConstVectorView<D> viscous_velocity;
  bool viscous;

  Vector<D> velocity(Index b) const { return moving ? surface_velocity[b] : Vector<D>::Zero(); }
};

// The fluid's fields both passes read.
template <int D>
struct RiemannFluid {
  ConstVectorView<D> x, v;
  std::span<const Real> mass, density, pressure;
};

template <int D>
RiemannFluid<D> riemann_fluid(const ParticleSet<D>& fluid, const FluidFields<D>& f) {
  return {fluid[f.position], fluid[f.velocity], fluid[f.mass], fluid[f.density], fluid[f.pressure]};
}

template <int D>
std::vector<RiemannContact<D>> riemann_contacts(const Interactions<D>& interactions) {
  std::vector<RiemannContact<D>> contacts;
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    const WallFields<D>& w = contact.fields();
    const ParticleSet<D>& set = contact.particles();
    contacts.push_back({set[w.mass], set[w.density], set[w.pressure],
                        w.surface_velocity ? set[*w.surface_velocity] : ConstVectorView<D>{},
                        w.surface_velocity.has_value(), w.velocity ? set[*w.velocity] : ConstVectorView<D>{},
                        contact.viscous()});
  }
  return contacts;
}

}  // namespace detail

/// a_i = g − 2 Σ_j m_j P*_ij/(ρ_i ρ_j) ∇W_ij (Zhang, Hu & Adams 2017, eq. 10) + the viscous terms of
/// momentum() (`Model`; the viscous terms only from viscous contacts), over fluid and contact
/// neighbours, P* from detail::riemann_pressure. With `Corrected`, the pressure term's gradient
/// is the corrected one, ½ (L_i + L_j) ∇W_ij between fluid particles, symmetric in i and j so that
/// the pair's forces still balance, and L_i ∇W_ib against a wall (L from
/// kernel_gradient_correction(), in `correction`).
template <int D, scene::ViscosityModel Model, bool Corrected>
void riemann_momentum(const RuntimeKernel<D>& kernel, const ViscositySettings& viscosity,
                      const RiemannSettings<D>& riemann, ParticleSet<D>& fluid, const FluidFields<D>& f,
                      const Interactions<D>& interactions, [[maybe_unused]] std::span<const Real> correction) {
  const detail::RiemannFluid<D> in = detail::riemann_fluid<D>(fluid, f);
  const std::vector<detail::RiemannContact<D>> contacts = detail::riemann_contacts(interactions);
  const Real c0 = riemann.sound_speed;
  for_each_fluid_particle<D>(
      interactions, in.x, VectorOutput<D>{fluid[f.acceleration]},
      [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        const Vector<D> v_i = in.v[i];
        const Real rho_i = in.density[i];
        const Real p_i = in.pressure[i];
        Vector<D> a = riemann.gravity;
        [[maybe_unused]] CorrectionMatrix<D> l_i;
        if constexpr (Corrected) l_i = correction_at<D>(correction, static_cast<Index>(i));
        neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
          if (j == i) return;
          const Real r = std::sqrt(r2);
          const Vector<D> grad_w = kernel.gradient(x_ij, r);
          const Real rho_j = in.density[j];
          const Vector<D> v_ij = v_i - in.v[j];
          const Real p_star = detail::riemann_pressure(p_i, in.pressure[j], rho_i, rho_j, -v_ij.dot(x_ij) / r, c0);
          const Real scale = 2 * in.mass[j] * p_star / (rho_i * rho_j);
          if constexpr (Corrected) {
            a -= (Real(0.5) * scale) * ((l_i + correction_at<D>(correction, j)) * grad_w);
          } else {
            a -= scale * grad_w;
          }
          a += detail::viscous_term<D, Model>(viscosity, in.mass[j], rho_i, rho_j, v_ij, x_ij, r2, grad_w);
        });
        neighbors.contacts([&](const ContactNeighbors<D>& contact) {
          const detail::RiemannContact<D>& wall = contacts[contact.number()];
          contact.pairs([&](Index b, const Vector<D>& x_ib, Real r2) {
            const Real r = std::sqrt(r2);
            const Vector<D> grad_w = kernel.gradient(x_ib, r);
            const Real rho_b = wall.density[b];
            const Real approach = -(v_i - wall.velocity(b)).dot(x_ib) / r;
            const Real p_star = detail::riemann_pressure(p_i, wall.pressure[b], rho_i, rho_b, approach, c0);
            const Real scale = 2 * wall.mass[b] * p_star / (rho_i * rho_b);
            if constexpr (Corrected) {
              a -= scale * (l_i * grad_w);
            } else {
              a -= scale * grad_w;
            }
            if (wall.viscous)
              a += detail::viscous_term<D, Model>(viscosity, wall.mass[b], rho_i, rho_b, v_i - wall.viscous_velocity[b],
                                                  x_ib, r2, grad_w);
          });
        });
        return a;
      });
}

/// Dρ_i/dt = 2 ρ_i Σ_j (m_j/ρ_j)(v_i − v*_ij)·∇W_ij (Zhang, Hu & Adams 2017, eq. 9) with the
/// Riemann velocity v*_ij = v̄_ij + (p_i − p_j)/(2 ρ̄ c0) e_ij (eq. 15, without the limiter,
/// as the paper keeps it), i.e. ρ_i Σ_j (m_j/ρ_j)[v_ij·∇W_ij + (p_i − p_j − p^H_ij)/(ρ̄ c0)
/// x_ij·∇W_ij/r]: the pressure difference diffuses the density as δ-SPH does. p^H_ij = ρ0 g·x_ij,
/// the hydrostatic part of p_i − p_j, is taken out as Fourtakas et al. 2019 (eq. 11) take ρ^H
/// out of δ-SPH's term, so that the diffusion does not flatten the hydrostatic profile; it is
/// linear in the pressure, so it costs no equation-of-state inverse per pair. Contacts: the wall
/// particle moves with its surface velocity and carries its extrapolated pressure.
template <int D>
void riemann_continuity(const RuntimeKernel<D>& kernel, const RiemannSettings<D>& riemann, ParticleSet<D>& fluid,
                        const FluidFields<D>& f, const Interactions<D>& interactions) {
  const detail::RiemannFluid<D> in = detail::riemann_fluid<D>(fluid, f);
  const std::vector<detail::RiemannContact<D>> contacts = detail::riemann_contacts(interactions);
  const Real inverse_c0 = 1 / riemann.sound_speed;
  const Vector<D> rho0_g = riemann.rest_density * riemann.gravity;
  for_each_fluid_particle<D>(
      interactions, in.x, ScalarOutput{fluid[f.density_rate]}, [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        const Vector<D> v_i = in.v[i];
        const Real rho_i = in.density[i];
        const Real p_i = in.pressure[i];
        // One pair's m_j/ρ_j [v_ij·∇W + (p_i − p_j − p^H_ij)/(ρ̄ c0) x_ij·∇W/r].
        const auto pair = [&](Real m_j, Real rho_j, Real p_j, const Vector<D>& v_ij, const Vector<D>& x_ij, Real r2) {
          const Real r = std::sqrt(r2);
          const Vector<D> grad_w = kernel.gradient(x_ij, r);
          const Real jump = (p_i - p_j - rho0_g.dot(x_ij)) * 2 * inverse_c0 / (rho_i + rho_j);
          return m_j / rho_j * (v_ij.dot(grad_w) + jump * x_ij.dot(grad_w) / r);
        };
        Real sum = 0;
        neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
          if (j == i) return;
          sum += pair(in.mass[j], in.density[j], in.pressure[j], v_i - in.v[j], x_ij, r2);
        });
        neighbors.contacts([&](const ContactNeighbors<D>& contact) {
          const detail::RiemannContact<D>& wall = contacts[contact.number()];
          contact.pairs([&](Index b, const Vector<D>& x_ib, Real r2) {
            sum += pair(wall.mass[b], wall.density[b], wall.pressure[b], v_i - wall.velocity(b), x_ib, r2);
          });
        });
        return rho_i * sum;
      });
}

}  // namespace tide::passes
