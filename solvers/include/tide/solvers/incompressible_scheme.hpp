#pragma once

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/scene.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// What tells the incompressible schemes apart. Both solve the same pressure equation (the
/// density of every particle after the step equals ρ0, with the same discretisation, walls and
/// threshold) by Jacobi sweeps of the same two passes; they differ only in these choices.
struct IncompressibleScheme {
  scene::Scheme scheme = scene::Scheme::dfsph;
  Real relaxation = 1;             // ω of the Jacobi sweep on a compact kernel: p_i += ω α_i (ρ*_i − ρ0)/Δt²
  Real warm_start = 1;             // share of the previous step's pressure the density solve starts from
  bool divergence_solve = false;   // after the drift, also make the velocity field divergence-free
  Real divergence_warm_start = 0;  // the same share for the divergence solve's pressure
};

/// The choices of DFSPH (Bender & Koschier 2015, 2017) or IISPH (Ihmsen et al. 2014);
/// std::invalid_argument for WCSPH.
IncompressibleScheme incompressible_scheme(scene::Scheme scheme);

/// λ_max, the largest eigenvalue of D⁻¹A for the pressure matrix A of a uniform lattice of
/// spacing Δx and its diagonal D: max over wave vectors k of |Σ_j sin(k·x_j) ∇W(x_j)|² / Σ_j |∇W(x_j)|²
/// (the lattice Fourier symbol of the pressure matrix, passes/pressure_solve.hpp). A Jacobi sweep
/// converges only for ω λ_max < 2. λ_max grows with the kernel's support in spacings: 2.1 for
/// support 2Δx (the cubic spline at h = Δx of both papers), 4.2 for Wendland C2 at h = 1.7Δx in 2D,
/// 6.2 at h = 1.5Δx in 3D.
template <int D>
Real jacobi_spectral_bound(const AnyKernel<D>& kernel, Real spacing);

/// The relaxation used: the papers' ω (IncompressibleScheme::relaxation) times 1.5/λ_max (when
/// λ_max > 1.5). DFSPH's ω = 1 then gives ω λ_max = 1.5, inside the Jacobi limit 2 for any kernel,
/// and IISPH keeps half of it, as in the papers; unscaled, ω = 1 diverges for Wendland C2 at
/// h = 1.7Δx (measured: the error doubles every sweep) and ω = 0.5 slowly too.
Real effective_relaxation(const IncompressibleScheme& scheme, Real spectral_bound);

}  // namespace tide
