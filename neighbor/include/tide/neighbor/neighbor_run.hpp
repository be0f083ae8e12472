#pragma once

#include <array>
#include <cmath>

#include "tide/core/types.hpp"

namespace tide {

/// Up to `capacity` neighbours of one query particle: their indices, x_ij = x_i − x_j (minimum
/// image) by component and r² = |x_ij|², in the neighbour list's order; and, where the list has
/// them cached (NeighborList::cache_gradient_factors), the kernel's (1/r) dW/dr of each pair.
template <int D>
struct NeighborRun {
  static constexpr int capacity = 64;
  int count = 0;
  std::array<Index, capacity> index;
  std::array<std::array<Real, capacity>, D> x_ij;
  std::array<Real, capacity> r2;
  const Real* gradient_factor = nullptr;  // count entries, or null
};

/// Calls body(factor) with factor(k) the kernel's (1/r) dW/dr of pair k of `run`: the cached
/// value where the run has one (the same number: it was computed from the same r²), else
/// kernel.derivative_over_r(√r²). body is instantiated for each case, so its pair loop keeps
/// no branch. The cache must have been filled with `kernel`.
template <int D, class Kernel, class Body>
void with_gradient_factors(const Kernel& kernel, const NeighborRun<D>& run, Body&& body) {
  if (run.gradient_factor) {
    body([&](int k) { return run.gradient_factor[k]; });
  } else {
    body([&](int k) { return kernel.derivative_over_r(std::sqrt(run.r2[k])); });
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

/// total += coefficient(k) x_ij for every k of a run, in order: accumulate() for a vector term
/// along the pair's offset, as every c ∇W_ij of a radial kernel is.
template <int D, class Coefficient>
void accumulate_along_offsets(const NeighborRun<D>& run, Vector<D>& total, Coefficient&& coefficient) {
  std::array<std::array<Real, NeighborRun<D>::capacity>, D> terms;
  for (int k = 0; k < run.count; ++k) {
    const Real c = coefficient(k);
    for (int d = 0; d < D; ++d) terms[d][k] = c * run.x_ij[d][k];
  }
  for (int k = 0; k < run.count; ++k)
    for (int d = 0; d < D; ++d) total[d] += terms[d][k];
}

}  // namespace tide
