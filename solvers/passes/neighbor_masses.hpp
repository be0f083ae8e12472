#pragma once

// How a pair loop reads its neighbours' masses.

#include <functional>
#include <span>

#include "tide/core/parallel.hpp"
#include "tide/core/types.hpp"

namespace tide::passes {

/// The mass m_j of neighbour j from a set's mass field: gathered per pair, or (`Uniform`, for a
/// set whose particles all have one mass) that mass, read once. Both give the same m_j, so the
/// sums are bitwise the same; the uniform one spares the pair loop a gather (one of three per pair
/// in the 2D pressure sweeps' continuity pass, one of two in their pressure push).
template <bool Uniform>
class NeighborMasses {
 public:
  explicit NeighborMasses(std::span<const Real> masses)
      : masses_(masses), uniform_mass_(masses.empty() ? Real(0) : masses[0]) {}

  Real operator[](Index j) const {
    if constexpr (Uniform) {
      return uniform_mass_;
    } else {
      return masses_[j];
    }
  }

 private:
  std::span<const Real> masses_;
  Real uniform_mass_;
};

/// Whether every particle of a set has the same mass (an empty set: true).
inline bool masses_are_uniform(std::span<const Real> masses) {
  return reduce(
      masses.size(), true, [&](std::size_t i) { return masses[i] == masses[0]; }, std::logical_and<>{});
}

}  // namespace tide::passes
