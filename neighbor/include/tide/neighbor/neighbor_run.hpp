#pragma once

#include <array>
#include <cmath>

#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// Up to `capacity` neighbours of one query particle: their indices, x_ij = x_i − x_j (minimum
/// image) by component and r² = |x_ij|², in the neighbour list's order; and, where the list has
/// them cached (NeighborList::cache_gradients), each pair's kernel gradient ∇W_ij by component.
/// A walk asked for gradients only (NeighborList::for_each_run<false>) leaves x_ij and r² unset
/// when it has the gradients. The indices are the list's own entries, read in place, except on a
/// periodic domain, whose entries also carry an image shift: there they are unpacked into
/// `unpacked_index`.
template <int D>
struct NeighborRun {
  static constexpr int capacity = 64;
  int count = 0;
  const Index* index = nullptr;  // count entries
  std::array<Index, capacity> unpacked_index;
  std::array<std::array<Real, capacity>, D> x_ij;
  std::array<Real, capacity> r2;
  std::array<const Real*, D> gradient{};  // count entries each, or null
};

/// Calls body(gradient) with gradient(k) the kernel gradient ∇W_ij of pair k of `run` (a
/// std::array of D components): the cached one where the run has it (the same numbers:
/// derivative_over_r(√r²) x_ij from the same x_ij), else computed so from the run's x_ij and r²
/// by the scene's kernel inside body's pair loop. body is instantiated for the cache and for each
/// kernel, so its pair loop keeps no branch, and the kernel's square root and polynomial overlap
/// the loop's gathers (a loop of their own ahead of it cost a 2D WCSPH step ~4%). The cache must
/// have been filled with `kernel`.
template <int D, class Body>
void with_gradients(const RuntimeKernel<D>& kernel, const NeighborRun<D>& run, Body&& body) {
  if (run.gradient[0]) {
    body([&](int k) {
      std::array<Real, D> grad_w;
      for (int d = 0; d < D; ++d) grad_w[d] = run.gradient[d][k];
      return grad_w;
    });
  } else {
    kernel.visit([&](const auto& w) {
      body([&](int k) {
        const Real factor = w.derivative_over_r(std::sqrt(run.r2[k]));
        std::array<Real, D> grad_w;
        for (int d = 0; d < D; ++d) grad_w[d] = factor * run.x_ij[d][k];
        return grad_w;
      });
    });
  }
}

/// total += term(k) for every k of a run, in order: the terms are computed in a loop of their
/// own, which the compiler vectorises when term has no branch and works on scalars (gathering the
/// neighbours' fields by index; Eigen's small-vector temporaries stop the vectoriser), and added
/// one by one afterwards, so the total is bitwise that of a neighbour-by-neighbour walk.
template <int D, class Term>
void accumulate(const NeighborRun<D>& run, Real& total, Term&& term) {
  std::array<Real, NeighborRun<D>::capacity> terms;
  for (int k = 0; k < run.count; ++k) terms[k] = term(k);
  for (int k = 0; k < run.count; ++k) total += terms[k];
}

/// total += coefficient(k) gradient(k) for every k of a run, in order: accumulate() for a vector
/// term along the pair's kernel gradient (gradient as with_gradients hands it out).
template <int D, class Gradient, class Coefficient>
void accumulate_along_gradients(const NeighborRun<D>& run, Vector<D>& total, const Gradient& gradient,
                                Coefficient&& coefficient) {
  std::array<std::array<Real, NeighborRun<D>::capacity>, D> terms;
  for (int k = 0; k < run.count; ++k) {
    const Real c = coefficient(k);
    const std::array<Real, D> grad_w = gradient(k);
    for (int d = 0; d < D; ++d) terms[d][k] = c * grad_w[d];
  }
  for (int k = 0; k < run.count; ++k)
    for (int d = 0; d < D; ++d) total[d] += terms[d][k];
}

}  // namespace tide
