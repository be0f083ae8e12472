#pragma once

#include <array>
#include <type_traits>

#include "tide/core/types.hpp"

namespace tide {

/// Up to `capacity` neighbours of one query particle: their indices, x_ij = x_i − x_j (minimum
/// image) by component and r² = |x_ij|², in the neighbour list's order.
template <int D>
struct NeighborRun {
  static constexpr int capacity = 64;
  int count = 0;
  std::array<Index, capacity> index;
  std::array<std::array<Real, capacity>, D> x_ij;
  std::array<Real, capacity> r2;

  Vector<D> offset(int k) const {
    Vector<D> x;
    for (int d = 0; d < D; ++d) x[d] = x_ij[d].data()[k];
    return x;
  }
};

/// total += term(k) for every k of a run, in order, for a scalar or a Vector<D> term: the terms
/// are computed in a loop of their own, which the compiler vectorises when term has no branch
/// (gathering the neighbours' fields by index), and added one by one afterwards, so the total
/// is bitwise that of a neighbour-by-neighbour walk.
template <int D, class Total, class Term>
void accumulate(const NeighborRun<D>& run, Total& total, Term&& term) {
  constexpr int capacity = NeighborRun<D>::capacity;
  if constexpr (std::is_same_v<Total, Real>) {
    std::array<Real, capacity> terms;
    for (int k = 0; k < run.count; ++k) terms[k] = term(k);
    for (int k = 0; k < run.count; ++k) total += terms[k];
  } else {
    std::array<std::array<Real, capacity>, D> terms;
    for (int k = 0; k < run.count; ++k) {
      const Vector<D> t = term(k);
      for (int d = 0; d < D; ++d) terms[d][k] = t[d];
    }
    for (int k = 0; k < run.count; ++k)
      for (int d = 0; d < D; ++d) total[d] += terms[d][k];
  }
}

}  // namespace tide
