#pragma once

// Particles sorted into the cubic blocks of a grid, each block's particles contiguous: what the
// colour field and the spacing estimate gather neighbours from.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tide/surface/sparse_grid.hpp"

namespace tide::surface {

template <int D>
using Point = std::array<double, D>;

/// Particles sorted by block, with each occupied block's range in that order.
template <int D>
struct ParticlesByBlock {
  std::vector<Point<D>> positions;
  std::vector<std::uint64_t> block_keys;  // ascending
  std::vector<std::size_t> block_starts;  // block b's particles are [block_starts[b], block_starts[b + 1])
};

/// The lowest and highest coordinate along each axis of at least one particle.
template <int D>
struct Bounds {
  Point<D> lowest;
  Point<D> highest;
};

/// The bounds of `positions` (D coordinates per particle, at least one particle);
/// std::invalid_argument if a coordinate is not finite.
template <int D>
Bounds<D> bounds_of(std::span<const double> positions);

/// `positions` (D coordinates per particle) into blocks of `block_size` from `origin`, which
/// must lie below every particle; blocks in key order, particles in index order within a block.
template <int D>
ParticlesByBlock<D> sort_into_blocks(std::span<const double> positions, const Point<D>& origin, double block_size);

/// The block range of `particles` with key `block_key`, or an empty range if none.
template <int D>
std::pair<std::size_t, std::size_t> particles_in_block(const ParticlesByBlock<D>& particles, std::uint64_t block_key);

/// Calls f(offset) for every offset in {-1, 0, 1}^D, in a fixed order.
template <int D, class F>
void for_each_neighbour_offset(F&& f) {
  constexpr int count = D == 2 ? 9 : 27;
  for (int n = 0; n < count; ++n) {
    GridPoint<D> offset{};
    int rest = n;
    for (int d = 0; d < D; ++d) {
      offset[d] = rest % 3 - 1;
      rest /= 3;
    }
    f(offset);
  }
}

}  // namespace tide::surface
