#pragma once

// Density rate from the continuity equation, with δ-SPH density diffusion.

#include <array>
#include <cmath>
#include <span>
#include <type_traits>
#include <vector>

#include "neighbor_masses.hpp"
#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/equation_of_state.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// The δ-SPH density diffusion of the continuity equation (absent: none).
template <int D>
struct DensityDiffusion {
  const EquationOfState& eos;
  Vector<D> gravity;
  Real delta = 0;
  Real sound_speed = 0;
};

/// Dρ_i/dt = Σ_j m_j v_ij·∇W_ij (Monaghan 1992, eq. 2.9) over fluid and contact neighbours (a
/// wall particle moving with its wall's surface velocity), into f.density_rate; with
/// `diffusion`, plus the density diffusion of Molteni & Colagrossi 2009 (eq. 9),
/// δ h c0 Σ_j 2 (ρ_j − ρ_i − ρ^H_ji) (x_ji·∇W_ij) / (r² + 0.01 h²) · m_j/ρ_j, between fluid
/// particles only. ρ^H_ji, the hydrostatic density difference between j and i, is subtracted as
/// in Fourtakas et al. 2019 (eq. 11): diffusing it would slowly flatten the hydrostatic density
/// profile under gravity. ρ^H_ji = ρ(p = −ρ0 g·x_ij) − ρ0 from the equation of state. With
/// `NumberDensity` (several fluids, ρ_i = m_i Σ_j W_ij: passes/density_summation.hpp), the rate of
/// that density, Dρ_i/dt = m_i Σ_j v_ij·∇W_ij, without diffusion. With `UniformMasses` (every
/// fluid particle has one mass and every particle of a contact one: masses_are_uniform), the
/// pair loops without diffusion read m_j as such (NeighborMasses), with the same results.
template <int D, bool NumberDensity = false, bool UniformMasses = false>
void continuity(const RuntimeKernel<D>& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                const Interactions<D>& interactions, const DensityDiffusion<D>* diffusion) {
  const auto x = std::as_const(fluid)[f.position];
  const auto v = std::as_const(fluid)[f.velocity];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  const Real h = kernel.smoothing_length();
  const Real diffusion_scale = diffusion ? diffusion->delta * h * diffusion->sound_speed : Real(0);
  const Real rest_density = diffusion ? diffusion->eos.rest_density() : Real(0);
  const Real rest_pressure = diffusion ? diffusion->eos.pressure(rest_density) : Real(0);  // the background pressure
  const NeighborMasses<UniformMasses> fluid_masses(mass);
  // Per contact: its masses, and its surface velocity where it moves.
  struct ContactTerms {
    NeighborMasses<UniformMasses> masses;
    ConstVectorView<D> surface_velocity;
    bool moving;
  };
  std::vector<ContactTerms> contacts;
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    const WallFields<D>& w = contact.fields();
    const ParticleSet<D>& set = contact.particles();
    contacts.push_back({NeighborMasses<UniformMasses>(set[w.mass]),
                        w.surface_velocity ? set[*w.surface_velocity] : ConstVectorView<D>{},
                        w.surface_velocity.has_value()});
  }
  // The weight of neighbour j's velocity: its mass, or 1 for the number density.
  const auto weight = [&](const NeighborMasses<UniformMasses>& masses, Index j) {
    if constexpr (NumberDensity) {
      return Real(1);
    } else {
      return masses[j];
    }
  };
  for_each_fluid_particle<D>(
      interactions, x, ScalarOutput{fluid[f.density_rate]}, [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        const Vector<D> v_i = v[i];
        const Real rho_i = density[i];
        Real sum = 0;
        if (!NumberDensity && diffusion) {
          neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
            if (j == i) return;
            const Vector<D> grad_w = kernel.gradient(x_ij, std::sqrt(r2));
            sum += mass[j] * (v_i - v[j]).dot(grad_w);
            const Real rho_j = density[j];
            const Real hydrostatic =
                diffusion->eos.density(rest_pressure - rest_density * diffusion->gravity.dot(x_ij)) - rest_density;
            sum += diffusion_scale * 2 * (rho_j - rho_i - hydrostatic) * (-x_ij.dot(grad_w)) /
                   (r2 + Real(0.01) * h * h) * (mass[j] / rho_j);
          });
        } else {
          // Without a branch, so that accumulate() vectorises it; the pair i–i adds an exact zero.
          neighbors.template fluid_runs<false>([&](const NeighborRun<D>& run) {
            with_gradients(kernel, run, [&](const auto& gradient) {
              accumulate(run, sum, [&](int k) {
                const Index j = run.index[k];
                const std::array<Real, D> grad_w = gradient(k);
                Real v_dot_grad_w = 0;
                for (int d = 0; d < D; ++d) v_dot_grad_w += (v_i[d] - v.component[d][j]) * grad_w[d];
                return weight(fluid_masses, j) * v_dot_grad_w;
              });
            });
          });
        }
        neighbors.contacts([&](const ContactNeighbors<D>& contact) {
          const ContactTerms& terms = contacts[contact.number()];
          // Moving walls or not (a std::bool_constant) is chosen outside the pair loop, which then
          // has no branch.
          const auto add_run = [&](auto moving, const NeighborRun<D>& run) {
            with_gradients(kernel, run, [&](const auto& gradient) {
              accumulate(run, sum, [&](int k) {
                const Index b = run.index[k];
                const std::array<Real, D> grad_w = gradient(k);
                Real v_dot_grad_w = 0;
                for (int d = 0; d < D; ++d) {
                  Real v_ib = v_i[d];
                  if constexpr (decltype(moving)::value) v_ib -= terms.surface_velocity.component[d][b];
                  v_dot_grad_w += v_ib * grad_w[d];
                }
                return weight(terms.masses, b) * v_dot_grad_w;
              });
            });
          };
          contact.template runs<false>([&](const NeighborRun<D>& run) {
            if (terms.moving) {
              add_run(std::true_type{}, run);
            } else {
              add_run(std::false_type{}, run);
            }
          });
        });
        if constexpr (NumberDensity) sum *= mass[i];
        return sum;
      });
}

}  // namespace tide::passes
