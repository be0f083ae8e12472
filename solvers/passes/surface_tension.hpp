#pragma once

// Surface tension and wetting, added to the acceleration the momentum pass wrote. Three models
// (scene key solver.surface_tension.model, docs/multiphase.md); each is one or two gather passes.

#include <cmath>
#include <numbers>
#include <span>
#include <string_view>
#include <vector>

#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/parallel.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// The constants of the tension passes, fixed when the pipeline is built.
struct SurfaceTensionSettings {
  Real coefficient = 0;     // σ (akinci: γ)
  Real support_radius = 0;  // R, the kernel support: the reach of the akinci and pairwise forces
  // csf
  Index colour_phase = 0;     // particles of this phase have colour 1, the others 0
  Real normal_threshold = 0;  // |∇c| below this is no interface (Morris 2000: 0.01 / h)
  Real density_scale = 0;     // 2 / (ρ_a + ρ_b): Brackbill et al. 1992's density-scaled force
  // akinci
  Real adhesion = 0;               // β
  Real cohesion_scale = 0;         // the normalisation of C(r)
  Real adhesion_scale = 0;         // the normalisation of A(r)
  Real wall_volume = 0;            // of one wall particle (Akinci et al. 2012's boundary volume)
  std::vector<Real> rest_density;  // by phase
  // pairwise
  std::size_t phase_count = 1;
  std::vector<Real> pair_strength;  // s_ab for phases a, b: [a * phase_count + b]
  std::vector<Real> wall_strength;  // s_aw by phase
};

namespace detail {

// A particle's phase; a single-fluid scene has no phase field and one phase, 0.
inline Index phase_of(std::span<const Index> phase, std::size_t i) { return phase.empty() ? Index(0) : phase[i]; }

// Akinci, Akinci & Teschner 2013, eq. 2: the cohesion spline over the support R, attracting
// beyond R/2 and repelling closer in. The normalisation (32/(π R^9) in 3D) is in `scale`.
inline Real akinci_cohesion(Real r, Real support, Real scale) {
  const Real a = (support - r) * (support - r) * (support - r) * r * r * r;
  if (2 * r > support) return scale * a;
  const Real r3 = support * support * support;
  return scale * (2 * a - r3 * r3 / 64);
}

// Akinci, Akinci & Teschner 2013, eq. 7: the adhesion spline, non-zero for R/2 < r ≤ R.
inline Real akinci_adhesion(Real r, Real support, Real scale) {
  if (!(2 * r > support) || r > support) return 0;
  return scale * std::pow(-4 * r * r / support + 6 * r - 2 * support, Real(0.25));
}

}  // namespace detail

/// Colour gradient n_i = Σ_j V_j (c_j − c_i) ∇W_ij over fluid neighbours (Morris 2000, eq. 18,
/// the SPH form of Brackbill et al. 1992), c = 1 in the colour phase and 0 elsewhere. Walls
/// are left out: they carry no colour, so they neither add to nor bend the interface normal.
template <int D>
void colour_gradient(const RuntimeKernel<D>& kernel, const SurfaceTensionSettings& s, ParticleSet<D>& fluid,
                     const FluidFields<D>& f, std::span<const Index> phase, const Interactions<D>& interactions) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  for_each_fluid_particle<D>(interactions, x, VectorOutput<D>{fluid[f.colour_gradient]},
                             [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
                               const Real c_i = phase[i] == s.colour_phase ? 1 : 0;
                               Vector<D> n = Vector<D>::Zero();
                               neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
                                 const Real c_j = phase[j] == s.colour_phase ? 1 : 0;
                                 if (c_j == c_i) return;
                                 n += (mass[j] / density[j] * (c_j - c_i)) * kernel.gradient(x_ij, std::sqrt(r2));
                               });
                               return n;
                             });
}

/// Continuum surface force a_i += σ κ_i n_i · 2/(ρ_a + ρ_b) (Brackbill et al. 1992, eq. 41 with
/// their density scaling, which puts the force where the mass is, so a light phase is not
/// flung off the interface). Curvature κ_i = −∇·n̂_i, renormalised over the neighbours with a
/// reliable normal as in the reproducing divergence of Adami, Hu & Adams 2010 (eq. 20), but with
/// the kernel moment taken in the tangent plane only: n̂ varies along the interface, and the band
/// of reliable normals is truncated across it, so the isotropic moment Σ_j V_j r_ij |∇W_ij| / D
/// undercounts (κ came out 17% high for R = 8 Δx). With T_t = Σ_j V_j |W'_ij| (r_ij² −
/// (x_ij·n̂_i)²) / r_ij, ∇·n̂_i = (D − 1) Σ_j V_j (n̂_j − n̂_i)·∇W_ij / T_t, which in a full support
/// is the plain SPH divergence (T_t = D − 1).
template <int D>
void continuum_surface_force(const RuntimeKernel<D>& kernel, const SurfaceTensionSettings& s, ParticleSet<D>& fluid,
                             const FluidFields<D>& f, const Interactions<D>& interactions) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  const auto gradient = std::as_const(fluid)[f.colour_gradient];
  const auto acceleration = std::as_const(fluid)[f.acceleration];
  const Real threshold2 = s.normal_threshold * s.normal_threshold;
  for_each_fluid_particle<D>(interactions, x, VectorOutput<D>{fluid[f.acceleration]},
                             [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
                               const Vector<D> n_i = gradient[i];
                               const Real norm2_i = squared_norm<D>(n_i);
                               if (!(norm2_i > threshold2)) return acceleration[i];
                               const Vector<D> unit_i = n_i / std::sqrt(norm2_i);
                               Real divergence = 0;
                               Real normalisation = 0;
                               neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
                                 if (j == i) return;
                                 const Vector<D> n_j = gradient[j];
                                 const Real norm2_j = squared_norm<D>(n_j);
                                 if (!(norm2_j > threshold2)) return;
                                 const Real r = std::sqrt(r2);
                                 const Vector<D> grad_w = kernel.gradient(x_ij, r);
                                 const Real volume_j = mass[j] / density[j];
                                 const Real along_normal = x_ij.dot(unit_i);
                                 divergence += volume_j * (n_j / std::sqrt(norm2_j) - unit_i).dot(grad_w);
                                 normalisation += volume_j * grad_w.norm() * (r2 - along_normal * along_normal) / r;
                               });
                               if (!(normalisation > 0)) return acceleration[i];
                               const Real curvature = -Real(D - 1) * divergence / normalisation;
                               return Vector<D>(acceleration[i] + (s.coefficient * curvature * s.density_scale) * n_i);
                             });
}

/// Surface normal of Akinci et al. 2013 (eq. 5): n_i = R Σ_j V_j ∇W_ij over neighbours of i's
/// own phase; large only at the phase's surface.
template <int D>
void akinci_normal(const RuntimeKernel<D>& kernel, const SurfaceTensionSettings& s, ParticleSet<D>& fluid,
                   const FluidFields<D>& f, std::span<const Index> phase, const Interactions<D>& interactions) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  for_each_fluid_particle<D>(interactions, x, VectorOutput<D>{fluid[f.colour_gradient]},
                             [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
                               const Index phase_i = detail::phase_of(phase, i);
                               Vector<D> n = Vector<D>::Zero();
                               neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
                                 if (j == i || detail::phase_of(phase, j) != phase_i) return;
                                 n += (mass[j] / density[j]) * kernel.gradient(x_ij, std::sqrt(r2));
                               });
                               return Vector<D>(s.support_radius * n);
                             });
}

/// Akinci et al. 2013: cohesion −γ m_j C(r_ij) x̂_ij (eq. 1) and surface-area minimisation
/// −γ (n_i − n_j) (eq. 4) from neighbours of i's own phase, each pair scaled by
/// K_ij = 2 ρ0 / (ρ_i + ρ_j) (eq. 6), which strengthens the pull on the thinned-out surface; and
/// adhesion to wall contacts −β Ψ_b A(r_ib) x̂_ib (eq. 7) with Ψ_b = ρ0 V_b (Akinci et al. 2012).
/// All per unit mass of i.
template <int D>
void akinci_surface_force(const RuntimeKernel<D>&, const SurfaceTensionSettings& s, ParticleSet<D>& fluid,
                          const FluidFields<D>& f, std::span<const Index> phase, const Interactions<D>& interactions) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  const auto normal = std::as_const(fluid)[f.colour_gradient];
  const auto acceleration = std::as_const(fluid)[f.acceleration];
  const Real radius = s.support_radius;
  for_each_fluid_particle<D>(
      interactions, x, VectorOutput<D>{fluid[f.acceleration]}, [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        const Index phase_i = detail::phase_of(phase, i);
        const Real rho0 = s.rest_density[phase_i];
        const Vector<D> n_i = normal[i];
        Vector<D> a = Vector<D>::Zero();
        neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
          if (j == i || detail::phase_of(phase, j) != phase_i) return;
          const Real r = std::sqrt(r2);
          const Real k_ij = 2 * rho0 / (density[i] + density[j]);
          const Vector<D> cohesion = (-mass[j] * detail::akinci_cohesion(r, radius, s.cohesion_scale) / r) * x_ij;
          a += (s.coefficient * k_ij) * (cohesion - (n_i - normal[j]));
        });
        if (s.adhesion > 0) {
          const Real psi = rho0 * s.wall_volume;
          neighbors.contacts([&](const ContactNeighbors<D>& contact) {
            if (contact.contact().role() != ContactRole::wall) return;
            contact.pairs([&](Index, const Vector<D>& x_ib, Real r2) {
              const Real r = std::sqrt(r2);
              a -= (s.adhesion * psi * detail::akinci_adhesion(r, radius, s.adhesion_scale) / r) * x_ib;
            });
          });
        }
        return Vector<D>(acceleration[i] + a);
      });
}

/// Pairwise inter-particle forces of Tartakovsky & Meakin 2005 (eq. 9): F_ij = s_ab cos(3π r/(2R))
/// x̂_ij for r ≤ R, repulsive below R/3 and cohesive beyond, with a strength s_ab for each pair of
/// phases and s_aw against the particles of wall contacts; a_i = Σ F_ij / m_i. How the strengths follow from σ
/// and the contact angle: pairwise_strengths (surface_tension_setup.cpp).
template <int D>
void pairwise_surface_force(const RuntimeKernel<D>&, const SurfaceTensionSettings& s, ParticleSet<D>& fluid,
                            const FluidFields<D>& f, std::span<const Index> phase,
                            const Interactions<D>& interactions) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto acceleration = std::as_const(fluid)[f.acceleration];
  const Real wave = Real(1.5) * std::numbers::pi_v<Real> / s.support_radius;
  for_each_fluid_particle<D>(interactions, x, VectorOutput<D>{fluid[f.acceleration]},
                             [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
                               const Index phase_i = detail::phase_of(phase, i);
                               const Real* strength = s.pair_strength.data() + phase_i * s.phase_count;
                               Vector<D> force = Vector<D>::Zero();
                               neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
                                 if (j == i) return;
                                 const Real r = std::sqrt(r2);
                                 force += (strength[detail::phase_of(phase, j)] * std::cos(wave * r) / r) * x_ij;
                               });
                               const Real wall_strength = s.wall_strength[phase_i];
                               if (wall_strength != 0) {
                                 neighbors.contacts([&](const ContactNeighbors<D>& contact) {
                                   if (contact.contact().role() != ContactRole::wall) return;
                                   contact.pairs([&](Index, const Vector<D>& x_ib, Real r2) {
                                     const Real r = std::sqrt(r2);
                                     force += (wall_strength * std::cos(wave * r) / r) * x_ib;
                                   });
                                 });
                               }
                               return Vector<D>(acceleration[i] + force / mass[i]);
                             });
}

/// The passes of `model`, in the order surface_tension runs them: what a scheme's pipeline lists.
inline std::vector<std::string_view> surface_tension_passes(scene::SurfaceTensionModel model) {
  switch (model) {
    case scene::SurfaceTensionModel::csf:
      return {"colour_gradient", "continuum_surface_force"};
    case scene::SurfaceTensionModel::akinci:
      return {"akinci_normal", "akinci_surface_force"};
    case scene::SurfaceTensionModel::pairwise:
      return {"pairwise_surface_force"};
    case scene::SurfaceTensionModel::none:
      break;
  }
  return {};
}

/// Adds the tension of `model` to the acceleration in f (nothing for SurfaceTensionModel::none).
template <int D>
void surface_tension(const RuntimeKernel<D>& kernel, scene::SurfaceTensionModel model, const SurfaceTensionSettings& s,
                     ParticleSet<D>& fluid, const FluidFields<D>& f, std::span<const Index> phase,
                     const Interactions<D>& interactions) {
  switch (model) {
    case scene::SurfaceTensionModel::none:
      break;
    case scene::SurfaceTensionModel::csf:
      colour_gradient<D>(kernel, s, fluid, f, phase, interactions);
      continuum_surface_force<D>(kernel, s, fluid, f, interactions);
      break;
    case scene::SurfaceTensionModel::akinci:
      akinci_normal<D>(kernel, s, fluid, f, phase, interactions);
      akinci_surface_force<D>(kernel, s, fluid, f, phase, interactions);
      break;
    case scene::SurfaceTensionModel::pairwise:
      pairwise_surface_force<D>(kernel, s, fluid, f, phase, interactions);
      break;
  }
}

}  // namespace tide::passes
