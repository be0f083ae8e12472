#include "tide/solvers/incompressible_scheme.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <variant>
#include <vector>

namespace tide {

IncompressibleScheme incompressible_scheme(scene::Scheme scheme) {
  switch (scheme) {
    case scene::Scheme::dfsph:
      // Bender & Koschier 2017, Alg. 1–3: the constant-density solve before the drift and the
      // divergence-free solve after it, each a Jacobi sweep with the full factor α_i (ω = 1),
      // warm-started from the pressure the same solve found in the previous step.
      return {scheme, Real(1), Real(1), true, Real(1)};
    case scene::Scheme::iisph:
      // Ihmsen et al. 2014, Sec. 3: relaxed Jacobi with ω = 0.5 and no divergence solve. Started
      // from the whole previous pressure, not half of it as in the paper: with half, a column at
      // rest must rebuild half its weight every step, ~100 sweeps at 25 particles deep.
      return {scheme, Real(0.5), Real(1), false, Real(0)};
    case scene::Scheme::wcsph:
    case scene::Scheme::crowd:
      break;
  }
  throw std::invalid_argument("incompressible_scheme: only dfsph and iisph are incompressible schemes");
}

template <int D>
Real jacobi_spectral_bound(const AnyKernel<D>& any_kernel, Real spacing) {
  return std::visit(
      [&](const auto& kernel) {
        // The lattice offsets inside the support, with ∇W there (the kernel is symmetric, so the
        // cosine part of the symbol vanishes and only the sines remain).
        const int reach = static_cast<int>(std::ceil(kernel.support_radius() / spacing));
        std::vector<std::array<Real, D>> offsets;
        std::vector<Vector<D>> gradients;
        Real squares = 0;
        std::array<int, D> k;
        k.fill(-reach);
        for (bool more = true; more;) {
          Vector<D> x;
          for (int d = 0; d < D; ++d) x[d] = Real(k[d]);
          const Real r = spacing * x.norm();
          if (r > 0 && r < kernel.support_radius()) {
            std::array<Real, D> offset;
            for (int d = 0; d < D; ++d) offset[d] = x[d];
            offsets.push_back(offset);
            gradients.push_back(kernel.gradient(Vector<D>(spacing * x), r));
            squares += squared_norm<D>(gradients.back());
          }
          int d = 0;
          for (; d < D; ++d) {
            if (++k[d] <= reach) break;
            k[d] = -reach;
          }
          more = d < D;
        }
        if (!(squares > 0)) return Real(0);
        // Wave vectors on a grid over the Brillouin zone [−π, π)^D (in units of 1/Δx).
        const int samples = D == 2 ? 48 : 16;
        Real bound = 0;
        std::array<int, D> m;
        m.fill(0);
        for (bool more = true; more;) {
          Vector<D> symbol = Vector<D>::Zero();
          for (std::size_t j = 0; j < offsets.size(); ++j) {
            Real phase = 0;
            for (int d = 0; d < D; ++d)
              phase += (-std::numbers::pi_v<Real> + 2 * std::numbers::pi_v<Real> * Real(m[d]) / Real(samples)) *
                       offsets[j][d];
            symbol += std::sin(phase) * gradients[j];
          }
          bound = std::max(bound, squared_norm<D>(symbol) / squares);
          int d = 0;
          for (; d < D; ++d) {
            if (++m[d] < samples) break;
            m[d] = 0;
          }
          more = d < D;
        }
        return bound;
      },
      any_kernel);
}

Real effective_relaxation(const IncompressibleScheme& scheme, Real spectral_bound) {
  return scheme.relaxation * Real(1.5) / std::max(spectral_bound, Real(1.5));
}

template Real jacobi_spectral_bound<2>(const AnyKernel<2>&, Real);
template Real jacobi_spectral_bound<3>(const AnyKernel<3>&, Real);

}  // namespace tide
