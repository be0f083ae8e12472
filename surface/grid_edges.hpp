#pragma once

// The edges of a sparse grid where the iso-level crosses, as marching squares and cubes name
// them: the edge from point g one cell along `axis` is the key pack(g) · 4 + axis, the same in every
// cell that shares the edge, so cells agree on the vertex there without talking to each other.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tide/surface/sparse_grid.hpp"

namespace tide::surface {

template <int D>
std::uint64_t edge_key(const GridPoint<D>& start, int axis) {
  return pack<D>(start) << 2 | static_cast<std::uint64_t>(axis);
}

/// Where the iso-level crosses the edge `key`, by linear interpolation between its two ends
/// (Lorensen & Cline 1987); the edge must be crossed (its ends on either side of the level).
template <int D>
std::array<double, D> crossing_point(const SparseGrid<D>& grid, std::uint64_t key, double iso_level) {
  const GridPoint<D> start = unpack<D>(key >> 2);
  const int axis = static_cast<int>(key & 3);
  GridPoint<D> end = start;
  ++end[axis];
  const double first = grid.value(start), second = grid.value(end);
  std::array<double, D> point = grid.position(start);
  point[axis] += (iso_level - first) / (second - first) * grid.cell_size;
  return point;
}

/// The values at the (block_points + 1)^D corner points of a block's cells: its own points and
/// the first layer of the blocks above it along each axis (zero where a block is not stored).
template <int D>
class BlockCorners {
 public:
  BlockCorners(const SparseGrid<D>& grid, std::uint64_t block_key) : side_(grid.block_points + 1) {
    const GridPoint<D> block = unpack<D>(block_key);
    for (unsigned above = 0; above < (1u << D); ++above) {
      GridPoint<D> neighbour = block;
      for (int d = 0; d < D; ++d) neighbour[d] += (above >> d) & 1;
      neighbours_[above] = grid.block_values(pack<D>(neighbour));
    }
    std::size_t count = 1;
    for (int d = 0; d < D; ++d) count *= static_cast<std::size_t>(side_);
    values_.resize(count);
    // Row by row along the first axis: block_points values from the block the row lies in (along
    // the other axes, coordinate block_points is the first layer of the block above), the last
    // from the block above that one along the first axis.
    const int n = grid.block_points;
    std::size_t at = 0;
    std::array<int, D> row{};
    while (true) {
      unsigned above = 0;
      std::size_t offset = 0;
      for (int d = D - 1; d >= 1; --d) {
        const bool up = row[d] == n;
        above |= static_cast<unsigned>(up) << d;
        offset = (offset + static_cast<std::size_t>(up ? 0 : row[d])) * static_cast<std::size_t>(n);
      }
      const double* source = neighbours_[above];
      const double* next = neighbours_[above | 1u];
      for (int x = 0; x < n; ++x)
        values_[at++] = source == nullptr ? 0.0 : source[offset + static_cast<std::size_t>(x)];
      values_[at++] = next == nullptr ? 0.0 : next[offset];
      int d = 1;
      for (; d < D && row[d] == n; ++d) row[d] = 0;
      if (d == D) break;
      ++row[d];
    }
  }

  /// Whether `level` lies between two of the values: some above it, some not; otherwise no cell
  /// of the block is crossed.
  bool crossed(double level) const {
    const auto [lowest, highest] = std::minmax_element(values_.begin(), values_.end());
    return *lowest <= level && *highest > level;
  }

  /// The value at `local`, each coordinate in [0, block_points].
  double operator()(const std::array<int, D>& local) const {
    std::size_t offset = 0;
    for (int d = D - 1; d >= 0; --d)
      offset = offset * static_cast<std::size_t>(side_) + static_cast<std::size_t>(local[d]);
    return values_[offset];
  }

 private:
  int side_;
  std::array<const double*, (1u << D)> neighbours_{};
  std::vector<double> values_;
};

}  // namespace tide::surface
