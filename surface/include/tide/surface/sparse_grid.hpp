#pragma once

// Values on the points of a regular grid, stored only in the blocks of it that are in use: what
// the colour field of a particle set (colour_field.hpp) is sampled on, and what marching squares
// and cubes read. Point g (integer coordinates, all ≥ 0) is at origin + g · cell_size; the grid is
// cut into blocks of block_points^D points, and a point of no stored block holds zero.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tide::surface {

template <int D>
using GridPoint = std::array<std::int64_t, D>;

/// Bits per coordinate in a packed key: a grid spans at most 2^20 points along an axis.
inline constexpr int key_bits_per_axis = 20;
inline constexpr std::int64_t max_points_per_axis = std::int64_t(1) << key_bits_per_axis;

/// Integer coordinates packed into one ordered key (first axis in the lowest bits): sorting keys
/// sorts points by their last coordinate first.
template <int D>
std::uint64_t pack(const GridPoint<D>& g) {
  std::uint64_t key = 0;
  for (int d = D - 1; d >= 0; --d) key = key << key_bits_per_axis | static_cast<std::uint64_t>(g[d]);
  return key;
}

template <int D>
GridPoint<D> unpack(std::uint64_t key) {
  GridPoint<D> g{};
  for (int d = 0; d < D; ++d)
    g[d] = static_cast<std::int64_t>(key >> (d * key_bits_per_axis) & (max_points_per_axis - 1));
  return g;
}

template <int D>
struct SparseGrid {
  std::array<double, D> origin{};
  double cell_size = 1;
  /// Points along each axis of a block.
  int block_points = 1;
  /// The stored blocks' packed block coordinates, ascending.
  std::vector<std::uint64_t> block_keys;
  /// Block b's values from b · points_per_block(), first axis fastest.
  std::vector<double> values;

  std::size_t points_per_block() const {
    std::size_t count = 1;
    for (int d = 0; d < D; ++d) count *= static_cast<std::size_t>(block_points);
    return count;
  }

  /// The values of the block with packed coordinates `block_key`, or nullptr if it is not stored.
  const double* block_values(std::uint64_t block_key) const {
    const auto found = std::lower_bound(block_keys.begin(), block_keys.end(), block_key);
    if (found == block_keys.end() || *found != block_key) return nullptr;
    return values.data() + static_cast<std::size_t>(found - block_keys.begin()) * points_per_block();
  }

  /// Offset of point `local` (coordinates inside its block) in its block's values.
  std::size_t offset_in_block(const GridPoint<D>& local) const {
    std::size_t offset = 0;
    for (int d = D - 1; d >= 0; --d)
      offset = offset * static_cast<std::size_t>(block_points) + static_cast<std::size_t>(local[d]);
    return offset;
  }

  double value(const GridPoint<D>& g) const {
    GridPoint<D> block{}, local{};
    for (int d = 0; d < D; ++d) {
      block[d] = g[d] / block_points;
      local[d] = g[d] % block_points;
    }
    const double* values_of_block = block_values(pack<D>(block));
    return values_of_block == nullptr ? 0.0 : values_of_block[offset_in_block(local)];
  }

  std::array<double, D> position(const GridPoint<D>& g) const {
    std::array<double, D> x{};
    for (int d = 0; d < D; ++d) x[d] = origin[d] + static_cast<double>(g[d]) * cell_size;
    return x;
  }
};

}  // namespace tide::surface
