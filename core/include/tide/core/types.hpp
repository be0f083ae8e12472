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

/// Integer cell coordinate on a neighbour grid.
template <int D>
using CellCoord = Eigen::Matrix<std::int64_t, D, 1>;

}  // namespace tide
