#pragma once

// The kernel gradient correction matrix of each fluid particle (Bonet & Lok 1999; Randles &
// Libersky 1996): the renormalised gradient L_i ∇W_ij differentiates a linear field exactly, even
// where the support is cut by a wall or a free surface.

#include <Eigen/LU>
#include <cmath>
#include <span>

#include "neighbor_walk.hpp"
#include "position_divergence.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

template <int D>
using CorrectionMatrix = Eigen::Matrix<Real, D, D>;

/// Where the correction pass stores L_i: D×D numbers per fluid particle, column-major.
template <int D>
struct CorrectionOutput {
  std::span<Real> values;
  void set(std::size_t i, const CorrectionMatrix<D>& l) const {
    Eigen::Map<CorrectionMatrix<D>>(values.data() + i * D * D) = l;
  }
};

/// L_i of a table written by kernel_gradient_correction().
template <int D>
CorrectionMatrix<D> correction_at(std::span<const Real> table, Index i) {
  return Eigen::Map<const CorrectionMatrix<D>>(table.data() + static_cast<std::size_t>(i) * D * D);
}

/// The smallest det M_i that is inverted: below it the support is too empty (a splash, a lone
/// particle) for the moments to say anything, and L_i = I, the uncorrected gradient. A particle on
/// a flat free surface has det M ≈ 0.5 (half its support filled), one at a free corner about 0.25.
inline constexpr Real min_correction_determinant = Real(0.1);

/// L_i = M_i⁻¹, M_i = Σ_j V_j ∇W_ij ⊗ (x_j − x_i) over fluid and contact neighbours (V = m/ρ; a
/// wall particle with its extrapolated density), Bonet & Lok 1999, eq. 44: the identity in a full
/// support. `table` takes D×D numbers per fluid particle.
template <int D>
void kernel_gradient_correction(const RuntimeKernel<D>& kernel, const ParticleSet<D>& fluid, const FluidFields<D>& f,
                                const Interactions<D>& interactions, std::span<Real> table) {
  const auto mass = fluid[f.mass];
  const auto density = fluid[f.density];
  const auto volumes = detail::contact_volumes(interactions);
  for_each_fluid_particle<D>(interactions, fluid[f.position], CorrectionOutput<D>{table},
                             [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
                               CorrectionMatrix<D> m = CorrectionMatrix<D>::Zero();
                               detail::for_each_volume_neighbor<D>(i, neighbors, mass, density, volumes,
                                                                   [&](Real volume, const Vector<D>& x_ij, Real r2) {
                                                                     const Vector<D> grad_w =
                                                                         kernel.gradient(x_ij, std::sqrt(r2));
                                                                     m -= volume * grad_w * x_ij.transpose();
                                                                   });
                               if (!(m.determinant() >= min_correction_determinant))
                                 return CorrectionMatrix<D>::Identity().eval();
                               return m.inverse().eval();
                             });
}

}  // namespace tide::passes
