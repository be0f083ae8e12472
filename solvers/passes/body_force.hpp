#pragma once

// The force the fluid exerts on each particle of a rigid body: the reaction to what the momentum
// pass (momentum.hpp) gives the fluid from that particle, so that fluid and body exchange
// momentum in equal and opposite amounts.

#include <array>
#include <utility>

#include "momentum.hpp"
#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// F_b = −Σ_j m_j a_jb for every particle b of `body`, where a_jb is the acceleration the
/// momentum pass gives fluid particle j from b. With one fluid: a_jb = −m_b (p_j/ρ_j² + p_b/ρ_b²)
/// ∇W_jb plus, for a no-slip body, the viscous term of detail::viscous_coefficient with b's
/// mirrored velocity. With several fluids (`phases`), the number-density form of Hu & Adams 2006
/// (eq. 8): a_jb = −(1/m_j) (p_j V_j² + p_b V_b²) ∇W_jb, V_b the wall volume, plus the laminar
/// term of detail::multiphase_viscous_term with j's viscosity (the wall takes the viscosity of the
/// fluid beside it), or the artificial one as with one fluid. A gather over b's fluid neighbours
/// (∇W_jb = −∇W_bj), stored in `force`. The scene checks refuse bodies with the artificial stress.
template <int D>
void body_force(const RuntimeKernel<D>& kernel, const ViscositySettings& settings, const Contact<D>& body,
                const ParticleSet<D>& fluid, const FluidFields<D>& f, VectorView<D> force,
                const MultiphaseTerms* phases = nullptr) {
  const auto x = fluid[f.position];
  const auto v = fluid[f.velocity];
  const auto mass = fluid[f.mass];
  const auto density = fluid[f.density];
  const auto pressure = fluid[f.pressure];
  const WallFields<D>& w = body.fields();
  const ParticleSet<D>& set = body.particles();
  const auto body_mass = set[w.mass];
  const auto body_density = set[w.density];
  const auto body_pressure = set[w.pressure];
  const ConstVectorView<D> body_velocity = body.viscous() ? set[*w.velocity] : ConstVectorView<D>{};
  const auto run = [&]<scene::ViscosityModel Model, bool Viscous, bool Multiphase>() {
    for_each_contact_particle<D>(
        body, x, VectorOutput<D>{force}, [&](std::size_t b, const FluidNeighborsOf<D>& fluid_neighbors) {
          const Real m_b = body_mass[b];
          const Real rho_b = body_density[b];
          const Real p_over_rho2_b = body_pressure[b] / (rho_b * rho_b);
          Vector<D> total = Vector<D>::Zero();
          fluid_neighbors.runs([&](const NeighborRun<D>& run) {
            with_gradients(kernel, run, [&](const auto& gradient) {
              for (int k = 0; k < run.count; ++k) {
                const Index j = run.index[k];
                const Real r2 = run.r2[k];
                const Real rho_j = density[j];
                const std::array<Real, D> grad_w_bj = gradient(k);
                Vector<D> x_jb, grad_w;  // x_jb = −x_bj, ∇W_jb = −∇W_bj
                for (int d = 0; d < D; ++d) {
                  x_jb[d] = -run.x_ij[d][k];
                  grad_w[d] = -grad_w_bj[d];
                }
                [[maybe_unused]] Real inverse_mass_j = 0, vj2 = 0, vb2 = 0;
                Vector<D> a_jb;
                if constexpr (Multiphase) {
                  inverse_mass_j = 1 / mass[j];
                  const Real volume_j = mass[j] / rho_j;
                  vj2 = volume_j * volume_j;
                  vb2 = phases->wall_volume * phases->wall_volume;
                  a_jb = -(inverse_mass_j * (pressure[j] * vj2 + body_pressure[b] * vb2)) * grad_w;
                } else {
                  a_jb = -(m_b * (pressure[j] / (rho_j * rho_j) + p_over_rho2_b)) * grad_w;
                }
                if constexpr (Viscous) {
                  const Vector<D> v_jb = v[j] - body_velocity[b];
                  if constexpr (Multiphase && Model == scene::ViscosityModel::laminar) {
                    const Real eta_j = phases->table[phases->phase[j]].dynamic_viscosity;
                    a_jb += detail::multiphase_viscous_term<D>(settings.smoothing_length, inverse_mass_j, eta_j, eta_j,
                                                               vj2 + vb2, v_jb, x_jb, r2, grad_w);
                  } else {
                    const Real coefficient = detail::viscous_coefficient<Model>(settings, m_b, rho_j, rho_b,
                                                                                v_jb.dot(x_jb), x_jb.dot(grad_w), r2);
                    a_jb += coefficient * (Model == scene::ViscosityModel::artificial ? grad_w : v_jb);
                  }
                }
                total -= mass[j] * a_jb;
              }
            });
          });
          return total;
        });
  };
  const auto run_for_fluids = [&]<scene::ViscosityModel Model, bool Viscous>() {
    if (phases != nullptr) {
      run.template operator()<Model, Viscous, true>();
    } else {
      run.template operator()<Model, Viscous, false>();
    }
  };
  const bool artificial = settings.model == scene::ViscosityModel::artificial;
  if (!body.viscous()) {
    run_for_fluids.template operator()<scene::ViscosityModel::artificial, false>();
  } else if (artificial) {
    run_for_fluids.template operator()<scene::ViscosityModel::artificial, true>();
  } else {
    run_for_fluids.template operator()<scene::ViscosityModel::laminar, true>();
  }
}

}  // namespace tide::passes
