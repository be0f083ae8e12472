#pragma once

// The two passes of an implicit pressure solve (DFSPH, IISPH), over fluid and contact neighbours.
//
// The pressure acceleration is the symmetric one of WCSPH (Monaghan 1992, eq. 3.3), and the walls
// are those of WCSPH too: wall particles on the fluid's lattice whose pressure is extrapolated
// from the fluid's, p_b = (Σ_f p_f W_bf + g·Σ_f ρ_f x_bf W_bf) / Σ_f W_bf (Adami, Hu & Adams
// 2012, eq. 27; passes/wall_state.hpp), recomputed before every sweep from the pressure of the
// sweep before. Measured on a 2D tank at rest this was the only one of three choices that let the
// fluid settle: the pressure mirroring of Akinci et al. 2012 and Bender & Koschier 2017
// (p_b/ρ_b² = p_i/ρ_i², or the wall term p_i/ρ_i² alone) pulls a fluid under load towards the
// wall or pumps energy into the particles beside it. The walls' density volumes are their masses
// over ρ0: Akinci's ψ_b = ρ0 / Σ_b' W_bb' is that mass for walls sampled, as here, on the fluid's
// lattice with layers across the whole kernel support.

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "neighbor_masses.hpp"
#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/incompressible_sph.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// The Jacobi factor α_i = ρ_i² / (|Σ_j m_j ∇W_ij + Σ_b m_b ∇W_ib|² + m_i Σ_j m_j |∇W_ij|²), so that
/// ∂ρ*_i/∂p_i = −Δt²/α_i with the wall pressures held fixed: the factor α_i of Bender & Koschier
/// 2017 (there per Δt², in the units of their stiffness κ = p/ρ) and the diagonal a_ii of Ihmsen
/// et al. 2014 (Sec. 3.2). 0 for a particle without neighbours, which no pressure can compress.
/// With `NumberDensity` (several fluids: ρ_i = m_i Σ_j W_ij, the pressure force of Hu & Adams
/// 2006 in pressure_velocity), the same derivative of that density,
/// α_i = ρ_i² / (m_i² |Σ_j ∇W_ij + Σ_b ∇W_ib|² + m_i³ Σ_j |∇W_ij|² / m_j); for one mass both agree.
template <int D, bool NumberDensity = false>
void pressure_factor(const RuntimeKernel<D>& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                     const PressureSolveFields<D>& s, const Interactions<D>& interactions) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  std::vector<std::span<const Real>> contact_mass;
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    contact_mass.push_back(contact.particles()[contact.fields().mass]);
  }
  for_each_fluid_particle<D>(
      interactions, x, ScalarOutput{fluid[s.factor]}, [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        Vector<D> fluid_sum = Vector<D>::Zero();
        Vector<D> contact_sum = Vector<D>::Zero();
        Real squares = 0;
        // The terms of a run in a loop without branches, then added in the list's order; the pair
        // i–i gives exact zeros.
        neighbors.template fluid_runs<false>([&](const NeighborRun<D>& run) {
          with_gradients(kernel, run, [&](const auto& gradient) {
            std::array<std::array<Real, NeighborRun<D>::capacity>, D> sum_terms;
            std::array<Real, NeighborRun<D>::capacity> square_terms;
            for (int k = 0; k < run.count; ++k) {
              const std::array<Real, D> grad_w = gradient(k);
              const Real m_j = mass[run.index[k]];
              Real grad_w2 = 0;
              for (int d = 0; d < D; ++d) {
                grad_w2 += grad_w[d] * grad_w[d];
                sum_terms[d][k] = NumberDensity ? grad_w[d] : m_j * grad_w[d];
              }
              square_terms[k] = NumberDensity ? grad_w2 / m_j : m_j * grad_w2;
            }
            for (int k = 0; k < run.count; ++k) {
              for (int d = 0; d < D; ++d) fluid_sum[d] += sum_terms[d][k];
              squares += square_terms[k];
            }
          });
        });
        neighbors.contacts([&](const ContactNeighbors<D>& contact) {
          const std::span<const Real> masses = contact_mass[contact.number()];
          contact.template runs<false>([&](const NeighborRun<D>& run) {
            with_gradients(kernel, run, [&](const auto& gradient) {
              std::array<std::array<Real, NeighborRun<D>::capacity>, D> sum_terms;
              for (int k = 0; k < run.count; ++k) {
                const std::array<Real, D> grad_w = gradient(k);
                const Real m_b = NumberDensity ? Real(1) : masses[run.index[k]];
                for (int d = 0; d < D; ++d) sum_terms[d][k] = NumberDensity ? grad_w[d] : m_b * grad_w[d];
              }
              for (int k = 0; k < run.count; ++k)
                for (int d = 0; d < D; ++d) contact_sum[d] += sum_terms[d][k];
            });
          });
        });
        const Real m_i = mass[i];
        const Real gradient_norm2 = (fluid_sum + contact_sum).squaredNorm();
        const Real denominator =
            NumberDensity ? m_i * m_i * (gradient_norm2 + m_i * squares) : gradient_norm2 + m_i * squares;
        return denominator > 0 ? density[i] * density[i] / denominator : Real(0);
      });
}

/// v_i = v*_i − Δt [Σ_j m_j (p_i/ρ_i² + p_j/ρ_j²) ∇W_ij + Σ_b m_b (p_i/ρ_i² + p_b/ρ_b²) ∇W_ib]: the
/// velocity that pressure p (and the walls' pressure extrapolated from it) gives after the step.
/// With `NumberDensity`, the form of Hu & Adams 2006 (eq. 8) that the WCSPH momentum pass uses for
/// several fluids: v_i = v*_i − (Δt/m_i) Σ_j (p_i V_i² + p_j V_j²) ∇W_ij with V = m/ρ (walls: m_b/ρ_b).
/// `pressure_term` (one entry per fluid particle) is scratch: one fluid takes p_j/ρ_j² from it,
/// computed once per particle rather than once per pair (a division per pair was ~7% of a 2D
/// DFSPH run, docs/performance.md); the sums are bitwise those of the division per pair. With
/// `UniformMasses` (one fluid mass, one wall mass: masses_are_uniform), m_j is read as such
/// (NeighborMasses), with the same results.
template <int D, bool NumberDensity = false, bool UniformMasses = false>
void pressure_velocity(const RuntimeKernel<D>& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                       const PressureSolveFields<D>& s, std::span<const Real> pressure,
                       const Interactions<D>& interactions, Real dt, std::span<Real> pressure_term) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  const auto predicted = std::as_const(fluid)[s.predicted_velocity];
  const NeighborMasses<UniformMasses> fluid_masses(mass);
  // Per contact: its masses, density and (extrapolated) pressure.
  struct ContactTerms {
    NeighborMasses<UniformMasses> masses;
    std::span<const Real> density;
    std::span<const Real> pressure;
  };
  std::vector<ContactTerms> contacts;
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    const WallFields<D>& w = contact.fields();
    const ParticleSet<D>& set = contact.particles();
    contacts.push_back({NeighborMasses<UniformMasses>(set[w.mass]), set[w.density], set[w.pressure]});
  }
  if constexpr (!NumberDensity)
    for_each_particle(fluid.size(), [&](std::size_t i) { pressure_term[i] = pressure[i] / (density[i] * density[i]); });
  for_each_fluid_particle<D>(
      interactions, x, VectorOutput<D>{fluid[f.velocity]}, [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        const Real rho_i = density[i];
        const Real p_over_rho2_i = pressure[i] / (rho_i * rho_i);
        const Real inverse_mass_i = 1 / mass[i];
        // Without a branch, so that accumulate_along_gradients() vectorises it; the pair i–i adds an exact zero.
        const auto pressure_push = [&](const NeighborRun<D>& run, Vector<D>& a,
                                       const NeighborMasses<UniformMasses>& masses, std::span<const Real> densities,
                                       std::span<const Real> pressures) {
          with_gradients(kernel, run, [&](const auto& gradient) {
            accumulate_along_gradients(run, a, gradient, [&](int k) {
              const Index j = run.index[k];
              const Real rho_j = densities[j];
              const Real m_j = masses[j];
              const Real term =
                  NumberDensity ? mass[i] * p_over_rho2_i + m_j * m_j * inverse_mass_i * pressures[j] / (rho_j * rho_j)
                                : m_j * (p_over_rho2_i + pressures[j] / (rho_j * rho_j));
              return -term;
            });
          });
        };
        Vector<D> a = Vector<D>::Zero();
        if constexpr (NumberDensity) {
          neighbors.template fluid_runs<false>(
              [&](const NeighborRun<D>& run) { pressure_push(run, a, fluid_masses, density, pressure); });
        } else {
          neighbors.template fluid_runs<false>([&](const NeighborRun<D>& run) {
            with_gradients(kernel, run, [&](const auto& gradient) {
              accumulate_along_gradients(run, a, gradient, [&](int k) {
                const Index j = run.index[k];
                return -(fluid_masses[j] * (p_over_rho2_i + pressure_term[j]));
              });
            });
          });
        }
        neighbors.contacts([&](const ContactNeighbors<D>& contact) {
          const ContactTerms& terms = contacts[contact.number()];
          contact.template runs<false>(
              [&](const NeighborRun<D>& run) { pressure_push(run, a, terms.masses, terms.density, terms.pressure); });
        });
        return Vector<D>(predicted[i] + dt * a);
      });
}

/// The adjoint of the walls' extrapolated pressure in the density error, which makes the
/// pressure equation symmetric. The sweep's pressure force on fluid particle i holds
/// Σ_b m_b (p_b/ρ_b²) ∇W_ib with p_b = Σ_f W_bf p_f / Σ_f W_bf (+ the hydrostatic term, a constant
/// of the solve; Adami, Hu & Adams 2012, eq. 27): a coupling C_if = Σ_b m_b W_bf ∇W_ib / (ρ_b² S_b)
/// (S_b = Σ_f W_bf) from the pressure of f to the velocity of i whose transpose the continuity
/// sum does not have. Adding it, ρ*_f − ρ0 gains Δt ρ_f² Σ_b W_fb s_b with
/// s_b = m_b Σ_i (v_i − v_b)·∇W_ib / (ρ_b² S_b), i.e. each wall particle's predicted compression
/// Σ_i m_b (v_i − v_b)·∇W_ib handed back to the fluid particles its pressure comes from, with the
/// weights of that extrapolation (ρ_f² because the unknowns of the symmetric form are p/ρ²). At rest
/// it vanishes, so the fluid at rest is solved for the same pressure. Two gathers: wall particles
/// into `wall_terms` (one vector per contact, empty for a contact that is not a wall), then fluid
/// particles into `adjoint`.
template <int D>
void wall_pressure_adjoint(const RuntimeKernel<D>& kernel, const Interactions<D>& interactions,
                           const ParticleSet<D>& fluid, const FluidFields<D>& f, VectorField velocity,
                           std::vector<std::vector<Real>>& wall_terms, std::span<Real> adjoint) {
  const auto x = fluid[f.position];
  const auto v = fluid[velocity];
  const auto density = fluid[f.density];
  wall_terms.resize(interactions.contact_count());
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    std::vector<Real>& terms = wall_terms[k];
    if (contact.role() != ContactRole::wall) {
      terms.clear();
      continue;
    }
    const WallFields<D>& w = contact.fields();
    const ParticleSet<D>& particles = contact.particles();
    const auto mass = particles[w.mass];
    const auto wall_density = particles[w.density];
    const ConstVectorView<D> surface_velocity =
        w.surface_velocity ? particles[*w.surface_velocity] : ConstVectorView<D>{};
    terms.resize(particles.size());
    kernel.visit([&](const auto& concrete) {
      for_each_contact_particle<D>(
          contact, x, ScalarOutput{terms}, [&](std::size_t b, const FluidNeighborsOf<D>& fluid_neighbors) {
            const Vector<D> own_velocity = w.surface_velocity ? surface_velocity[b] : Vector<D>::Zero();
            Real weight_sum = 0;
            Real compression = 0;
            fluid_neighbors.pairs([&](Index j, const Vector<D>& x_bj, Real r2) {
              const Real r = std::sqrt(r2);
              weight_sum += concrete.value(r);
              compression += (v[j] - own_velocity).dot(concrete.gradient(Vector<D>(-x_bj), r));
            });
            const Real rho_b = wall_density[b];
            return weight_sum > 0 ? mass[b] * compression / (rho_b * rho_b * weight_sum) : Real(0);
          });
    });
  }
  for_each_fluid_particle<D>(
      interactions, x, ScalarOutput{adjoint}, [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        Real sum = 0;
        neighbors.contacts([&](const ContactNeighbors<D>& contact) {
          const std::vector<Real>& terms = wall_terms[contact.number()];
          if (terms.empty()) return;
          kernel.visit([&](const auto& concrete) {
            contact.pairs([&](Index b, const Vector<D>&, Real r2) { sum += concrete.value(std::sqrt(r2)) * terms[b]; });
          });
        });
        return density[i] * density[i] * sum;
      });
}

}  // namespace tide::passes
