#pragma once

// Acceleration of every fluid particle: pressure, viscosity, artificial stress and body force in
// one gather pass.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <type_traits>
#include <vector>

#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/parallel.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"
#include "tide/solvers/phases.hpp"

namespace tide::passes {

struct ViscositySettings {
  scene::ViscosityModel model = scene::ViscosityModel::artificial;
  Real alpha = 0;
  Real beta = 0;
  Real sound_speed = 0;
  Real kinematic_viscosity = 0;
  Real smoothing_length = 0;
};

/// The viscosity settings of a scene, with the velocity scale c of the artificial viscosity.
inline ViscositySettings viscosity_settings(const scene::Scene& scene, Real sound_speed, Real kinematic_viscosity,
                                            Real smoothing_length) {
  return {scene.solver.viscosity,
          static_cast<Real>(scene.solver.alpha),
          static_cast<Real>(scene.solver.beta),
          sound_speed,
          kinematic_viscosity,
          smoothing_length};
}

/// Monaghan's (2000) artificial stress; `epsilon` = 0 compiles the pass without it.
struct ArtificialStressSettings {
  Real epsilon = 0;
  Real inverse_lattice_kernel = 0;  // 1 / W(Δx), the kernel at one particle spacing
};

namespace detail {

// Viscous acceleration on i from one neighbour j, a scalar coefficient times a vector: times
// ∇W_ij for the artificial viscosity, times v_ij for the laminar one.
// Artificial: Monaghan 1992, eq. 4.1–4.2: −m_j Π_ij ∇W_ij, Π_ij = (−α c μ + β μ²)/ρ̄_ij when
//   v_ij·x_ij < 0, μ = h v_ij·x_ij / (r² + 0.01 h²).
// Laminar: Morris, Fox & Zhu 1997, eq. 8: m_j (μ_i + μ_j) x_ij·∇W_ij / (ρ_i ρ_j (r² + 0.01 h²)) v_ij.
template <scene::ViscosityModel Model>
inline Real viscous_coefficient(const ViscositySettings& s, Real m_j, Real rho_i, Real rho_j, Real v_dot_x,
                                Real x_dot_grad_w, Real r2) {
  const Real h = s.smoothing_length;
  const Real regularised_r2 = r2 + Real(0.01) * h * h;
  if constexpr (Model == scene::ViscosityModel::artificial) {
    // Only approaching pairs (v_ij·x_ij < 0) are damped; μ = 0, hence Π = 0, for the others,
    // taken without a branch: about half the pairs approach, unpredictably.
    const Real mu = h * std::min(v_dot_x, Real(0)) / regularised_r2;
    const Real pi = (-s.alpha * s.sound_speed * mu + s.beta * mu * mu) / (Real(0.5) * (rho_i + rho_j));
    return -m_j * pi;
  } else {
    const Real dynamic_sum = s.kinematic_viscosity * (rho_i + rho_j);
    return m_j * dynamic_sum * x_dot_grad_w / (rho_i * rho_j * regularised_r2);
  }
}

template <int D, scene::ViscosityModel Model>
inline Vector<D> viscous_term(const ViscositySettings& s, Real m_j, Real rho_i, Real rho_j, const Vector<D>& v_ij,
                              const Vector<D>& x_ij, Real r2, const Vector<D>& grad_w) {
  const Real coefficient = viscous_coefficient<Model>(s, m_j, rho_i, rho_j, v_ij.dot(x_ij), x_ij.dot(grad_w), r2);
  if constexpr (Model == scene::ViscosityModel::artificial) return coefficient * grad_w;
  return coefficient * v_ij;
}

// A particle's share R_i of the artificial stress: ε |p_i|/ρ_i² where it is in tension (p_i < 0),
// none under compression. Gray, Monaghan & Swift 2001 take R = −ε σ/ρ² from each principal
// stress σ that is tensile (σ > 0); a fluid's stress is −p I, which gives this scalar form.
inline Real artificial_stress_share(Real epsilon, Real p_over_rho2) {
  return p_over_rho2 < 0 ? -epsilon * p_over_rho2 : Real(0);
}

// (W_ij/W(Δx))^4 from the pair's kernel value W_ij: the artificial stress acts only between
// particles closer than about the initial spacing, and grows fast as they approach (Monaghan
// 2000, n = 4).
inline Real artificial_stress_weight(const ArtificialStressSettings& s, Real w_ij) {
  const Real f = w_ij * s.inverse_lattice_kernel;
  const Real f2 = f * f;
  return f2 * f2;
}

// Laminar viscous acceleration on i from one neighbour j in the number-density formulation
// (Hu & Adams 2006, eq. 11): (1/m_i) η̄_ij (V_i² + V_j²) x_ij·∇W_ij / (r² + 0.01 h²) v_ij, with the
// inter-particle viscosity η̄_ij = 2 η_i η_j / (η_i + η_j) that keeps the shear stress continuous
// across an interface.
template <int D>
inline Vector<D> multiphase_viscous_term(Real smoothing_length, Real inverse_mass_i, Real eta_i, Real eta_j,
                                         Real volume_sum, const Vector<D>& v_ij, const Vector<D>& x_ij, Real r2,
                                         const Vector<D>& grad_w) {
  const Real eta_sum = eta_i + eta_j;
  if (!(eta_sum > 0)) return Vector<D>::Zero();
  const Real eta_ij = 2 * eta_i * eta_j / eta_sum;
  const Real regularised_r2 = r2 + Real(0.01) * smoothing_length * smoothing_length;
  return (inverse_mass_i * eta_ij * volume_sum * x_ij.dot(grad_w) / regularised_r2) * v_ij;
}

}  // namespace detail

/// What the momentum pass needs for several fluids: each particle's phase, the phases (their
/// dynamic viscosity), and the volume of a wall particle (walls fill the lattice: V = Δx^D up to
/// the kernel's discretisation, the same 1/Σ_k W(|k|Δx) every phase's mass is set from).
struct MultiphaseTerms {
  std::span<const Index> phase;
  std::span<const Phase> table;  // Phases::table
  Real wall_volume = 0;
};

/// a_i = −Σ_j m_j (p_i/ρ_i² + p_j/ρ_j²) ∇W_ij (Monaghan 1992, eq. 3.3) + viscous terms + g,
/// summed over fluid and contact neighbours (walls with their extrapolated p, ρ and velocity;
/// the viscous terms only from viscous contacts: Contact::viscous). With `ArtificialStress`,
/// each pair's pressure term gains (R_i + R_j) (W_ij/W(Δx))^4, a repulsion between particles in
/// tension that stops them clumping in pairs (Monaghan 2000, J. Comput. Phys. 159, the artificial
/// pressure added to the equation of motion). Without `WithPressure`, the non-pressure part
/// only: what an incompressible scheme integrates before its pressure solve. With `Multiphase`,
/// the number-density form of Hu & Adams 2006 (eq. 8): a_i = −(1/m_i) Σ_j (p_i V_i² + p_j V_j²)
/// ∇W_ij with V = m/ρ, which stays free of spurious interface forces at any density ratio, and
/// the laminar viscosity of detail::multiphase_viscous_term; for particles of one mass it is the
/// single-phase form. With one fluid and `WithPressure`, `scratch` (at least one entry per fluid
/// and contact particle) takes each particle's p/ρ², computed once per particle rather than once
/// per pair (the same numbers).
template <int D, scene::ViscosityModel Model, bool WithPressure, bool ArtificialStress, bool Multiphase = false>
void momentum(const RuntimeKernel<D>& kernel, const ViscositySettings& settings,
              [[maybe_unused]] const ArtificialStressSettings& stress, ParticleSet<D>& fluid, const FluidFields<D>& f,
              const Interactions<D>& interactions, const Vector<D>& gravity, [[maybe_unused]] std::span<Real> scratch,
              [[maybe_unused]] const MultiphaseTerms* phases = nullptr) {
  static_assert(!(Multiphase && ArtificialStress), "the artificial stress is not compiled for several fluids");
  const auto x = std::as_const(fluid)[f.position];
  const auto v = std::as_const(fluid)[f.velocity];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  const auto pressure = std::as_const(fluid)[f.pressure];
  // What the pair loops read of each contact: its masses, density, pressure (as p/ρ² where
  // that is kept) and, for viscous contacts, the velocity it shows the fluid.
  struct ContactTerms {
    std::span<const Real> mass;
    std::span<const Real> density;
    std::span<const Real> pressure;
    std::span<const Real> p_over_rho2;
    ConstVectorView<D> velocity;
    bool viscous;
  };
  std::span<const Real> fluid_p_over_rho2;
  [[maybe_unused]] const auto p_over_rho2 = [](std::span<Real> out, std::span<const Real> p,
                                               std::span<const Real> rho) {
    for_each_particle(out.size(), [&](std::size_t i) { out[i] = p[i] / (rho[i] * rho[i]); });
    return std::span<const Real>(out);
  };
  if constexpr (WithPressure && !Multiphase)
    fluid_p_over_rho2 = p_over_rho2(scratch.first(fluid.size()), pressure, density);
  std::vector<ContactTerms> contacts;
  std::size_t scratch_used = fluid.size();
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    const WallFields<D>& w = contact.fields();
    const ParticleSet<D>& set = contact.particles();
    ContactTerms terms{set[w.mass],
                       set[w.density],
                       set[w.pressure],
                       {},
                       // Read only for viscous (no-slip) walls, the only walls that have a velocity field.
                       w.velocity ? set[*w.velocity] : ConstVectorView<D>{},
                       contact.viscous()};
    if constexpr (WithPressure && !Multiphase) {
      terms.p_over_rho2 = p_over_rho2(scratch.subspan(scratch_used, set.size()), terms.pressure, terms.density);
      scratch_used += set.size();
    }
    contacts.push_back(terms);
  }
  for_each_fluid_particle<D>(
      interactions, x, VectorOutput<D>{fluid[f.acceleration]}, [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        const Vector<D> v_i = v[i];
        const Real rho_i = density[i];
        const Real p_over_rho2_i = pressure[i] / (rho_i * rho_i);
        [[maybe_unused]] Real stress_i = 0;
        if constexpr (ArtificialStress) stress_i = detail::artificial_stress_share(stress.epsilon, p_over_rho2_i);
        // The pressure term of one pair, with the artificial stress when it is compiled in (w_ij:
        // the pair's kernel value, read only then).
        const auto pressure_term = [&](Real p_over_rho2_j, [[maybe_unused]] Real w_ij) {
          Real term = p_over_rho2_i + p_over_rho2_j;
          if constexpr (ArtificialStress) {
            const Real stress_j = detail::artificial_stress_share(stress.epsilon, p_over_rho2_j);
            term += (stress_i + stress_j) * detail::artificial_stress_weight(stress, w_ij);
          }
          return term;
        };
        Vector<D> a = gravity;
        [[maybe_unused]] Real inverse_mass_i = 0, volume_i = 0, eta_i = 0;
        if constexpr (Multiphase) {
          inverse_mass_i = 1 / mass[i];
          volume_i = mass[i] / rho_i;
          eta_i = phases->table[phases->phase[i]].dynamic_viscosity;
          neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
            if (j == i) return;
            const Real rho_j = density[j];
            const Real r = std::sqrt(r2);
            const Vector<D> grad_w = kernel.gradient(x_ij, r);
            const Real volume_j = mass[j] / rho_j;
            const Real vi2 = volume_i * volume_i, vj2 = volume_j * volume_j;
            if constexpr (WithPressure) a -= (inverse_mass_i * (pressure[i] * vi2 + pressure[j] * vj2)) * grad_w;
            if constexpr (Model == scene::ViscosityModel::laminar) {
              a += detail::multiphase_viscous_term<D>(settings.smoothing_length, inverse_mass_i, eta_i,
                                                      phases->table[phases->phase[j]].dynamic_viscosity, vi2 + vj2,
                                                      v_i - v[j], x_ij, r2, grad_w);
            } else {
              a += detail::viscous_term<D, Model>(settings, mass[j], rho_i, rho_j, v_i - v[j], x_ij, r2, grad_w);
            }
          });
          neighbors.contacts([&](const ContactNeighbors<D>& contact) {
            const ContactTerms& terms = contacts[contact.number()];
            if (!WithPressure && !terms.viscous) return;
            contact.pairs([&](Index b, const Vector<D>& x_ib, Real r2) {
              const Real rho_b = terms.density[b];
              const Real r = std::sqrt(r2);
              const Vector<D> grad_w = kernel.gradient(x_ib, r);
              // The wall takes the viscosity of the fluid particle beside it.
              const Real vb2 = phases->wall_volume * phases->wall_volume;
              const Real vi2 = volume_i * volume_i;
              if constexpr (WithPressure)
                a -= (inverse_mass_i * (pressure[i] * vi2 + terms.pressure[b] * vb2)) * grad_w;
              if (!terms.viscous) return;
              if constexpr (Model == scene::ViscosityModel::laminar) {
                a += detail::multiphase_viscous_term<D>(settings.smoothing_length, inverse_mass_i, eta_i, eta_i,
                                                        vi2 + vb2, v_i - terms.velocity[b], x_ib, r2, grad_w);
              } else {
                a += detail::viscous_term<D, Model>(settings, terms.mass[b], rho_i, rho_b, v_i - terms.velocity[b],
                                                    x_ib, r2, grad_w);
              }
            });
          });
        } else {
          // The pressure and viscous terms of a run's pairs in a loop of scalars without branches
          // (vectorised, the neighbours' fields gathered) into arrays of the run's own, which no
          // other pointer can alias, then applied pair by pair in the list's order, as a walk would:
          // a −= pressure term, a += viscous term. The pair i–i gives zeros. One run of fluid or
          // contact neighbours (walls with their extrapolated p and ρ), viscous or not (a
          // std::bool_constant).
          const auto add_run = [&](auto viscous, const NeighborRun<D>& run, std::span<const Real> masses,
                                   std::span<const Real> densities, std::span<const Real> p_over_rho2_j,
                                   const ConstVectorView<D>& velocities) {
            constexpr bool viscous_run = decltype(viscous)::value;
            std::array<std::array<Real, NeighborRun<D>::capacity>, D> pressure_terms, viscous_terms;
            // The kernel values the artificial stress weighs with, for the whole run in one call.
            std::array<Real, ArtificialStress ? NeighborRun<D>::capacity : 1> w{};
            if constexpr (ArtificialStress) kernel.values(run.r2.data(), run.count, w.data());
            with_gradients(kernel, run, [&](const auto& gradient) {
              for (int k = 0; k < run.count; ++k) {
                const Index j = run.index[k];
                const Real rho_j = densities[j];
                const std::array<Real, D> grad_w = gradient(k);
                if constexpr (WithPressure) {
                  const Real scale = masses[j] * pressure_term(p_over_rho2_j[j], w[ArtificialStress ? k : 0]);
                  for (int d = 0; d < D; ++d) pressure_terms[d][k] = scale * grad_w[d];
                }
                if constexpr (viscous_run) {
                  std::array<Real, D> v_ij;
                  Real v_dot_x = 0, x_dot_grad_w = 0;
                  for (int d = 0; d < D; ++d) {
                    v_ij[d] = v_i[d] - velocities.component[d][j];
                    v_dot_x += v_ij[d] * run.x_ij[d][k];
                    x_dot_grad_w += run.x_ij[d][k] * grad_w[d];
                  }
                  const Real coefficient = detail::viscous_coefficient<Model>(settings, masses[j], rho_i, rho_j,
                                                                              v_dot_x, x_dot_grad_w, run.r2[k]);
                  const std::array<Real, D>& direction = Model == scene::ViscosityModel::artificial ? grad_w : v_ij;
                  for (int d = 0; d < D; ++d) viscous_terms[d][k] = coefficient * direction[d];
                }
              }
            });
            for (int k = 0; k < run.count; ++k) {
              if constexpr (WithPressure) {
                for (int d = 0; d < D; ++d) a[d] -= pressure_terms[d][k];
              }
              if constexpr (viscous_run) {
                for (int d = 0; d < D; ++d) a[d] += viscous_terms[d][k];
              }
            }
          };
          neighbors.fluid_runs(
              [&](const NeighborRun<D>& run) { add_run(std::true_type{}, run, mass, density, fluid_p_over_rho2, v); });
          neighbors.contacts([&](const ContactNeighbors<D>& contact) {
            const ContactTerms& terms = contacts[contact.number()];
            if (!WithPressure && !terms.viscous) return;
            contact.runs([&](const NeighborRun<D>& run) {
              if (terms.viscous) {
                add_run(std::true_type{}, run, terms.mass, terms.density, terms.p_over_rho2, terms.velocity);
              } else {
                add_run(std::false_type{}, run, terms.mass, terms.density, terms.p_over_rho2, terms.velocity);
              }
            });
          });
        }
        return a;
      });
}

/// momentum() compiled for the viscosity model of `settings`, for artificial stress on or off and
/// for one fluid or several (`phases` set), picked once per pass outside the particle loop: a
/// scene without artificial stress or a second fluid runs a pass without them. `scratch` as for
/// momentum().
template <int D, bool WithPressure = true>
void fluid_acceleration(const RuntimeKernel<D>& kernel, const ViscositySettings& settings,
                        const ArtificialStressSettings& stress, ParticleSet<D>& fluid, const FluidFields<D>& f,
                        const Interactions<D>& interactions, const Vector<D>& gravity, std::span<Real> scratch,
                        const MultiphaseTerms* phases = nullptr) {
  const auto run = [&]<scene::ViscosityModel Model, bool Stress>() {
    momentum<D, Model, WithPressure, Stress>(kernel, settings, stress, fluid, f, interactions, gravity, scratch);
  };
  if (phases) {
    if (settings.model == scene::ViscosityModel::artificial) {
      momentum<D, scene::ViscosityModel::artificial, WithPressure, false, true>(kernel, settings, stress, fluid, f,
                                                                                interactions, gravity, {}, phases);
    } else {
      momentum<D, scene::ViscosityModel::laminar, WithPressure, false, true>(kernel, settings, stress, fluid, f,
                                                                             interactions, gravity, {}, phases);
    }
    return;
  }
  const bool with_stress = WithPressure && stress.epsilon > 0;
  if (settings.model == scene::ViscosityModel::artificial) {
    with_stress ? run.template operator()<scene::ViscosityModel::artificial, WithPressure>()
                : run.template operator()<scene::ViscosityModel::artificial, false>();
  } else {
    with_stress ? run.template operator()<scene::ViscosityModel::laminar, WithPressure>()
                : run.template operator()<scene::ViscosityModel::laminar, false>();
  }
}

}  // namespace tide::passes
