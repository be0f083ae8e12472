#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "tide/core/config.hpp"

namespace tide {

/// Index of a particle inside a ParticleSet (the set holds at most 2^32 - 1 particles).
using Index = std::uint32_t;

/// Small fixed-size vector for the math inside a pass; never the storage layout.
template <int D>
using Vector = Eigen::Matrix<Real, D, 1>;

/// |v|² summed in component order. The neighbour search and every reference it is checked
/// against use this one definition, so a pair at exactly the support radius is decided the same
/// way everywhere (Eigen's squaredNorm may sum in another order and round differently).
template <int D>
Real squared_norm(const Vector<D>& v) {
  Real sum = 0;
  for (int d = 0; d < D; ++d) sum += v[d] * v[d];
  return sum;
}

/// Integer cell coordinate on a neighbour grid.
template <int D>
using CellCoord = Eigen::Matrix<std::int64_t, D, 1>;

}  // namespace tide
