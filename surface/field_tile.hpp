#pragma once

// One tile of the colour field's sparse grid, summed densely: tile_blocks^D blocks, each particle
// within reach adding V W(r) to every point of its support box, whole rows along the first axis at
// a time, then copied into the tile's stored blocks (colour_field.cpp). A tile is wide enough that
// a particle's support box seldom crosses its border, so the rows are long and a particle is
// visited about (1 + 2 / tile_blocks)^D times instead of 3^D times, once per block it reaches.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "kernel_table.hpp"
#include "tide/surface/sparse_grid.hpp"

namespace tide::surface {

/// Blocks per tile along each axis.
inline constexpr int tile_blocks = 4;

template <int D>
class FieldTile {
 public:
  FieldTile(const SparseGrid<D>& grid, const KernelTable& table)
      : grid_(grid),
        table_(table),
        side_(tile_blocks * grid.block_points),
        reach_(static_cast<int>(std::ceil(std::sqrt(table.support_squared()) / grid.cell_size))),
        coordinates_(static_cast<std::size_t>(D * side_)),
        squared_(static_cast<std::size_t>(D * side_)) {
    std::size_t points = 1;
    for (int d = 0; d < D; ++d) points *= static_cast<std::size_t>(side_);
    values_.resize(points);
  }

  /// Starts tile `tile` (tile coordinates) with every value `value`.
  void start(const GridPoint<D>& tile, double value) {
    tile_ = tile;
    std::fill(values_.begin(), values_.end(), value);
    for (int d = 0; d < D; ++d)
      for (int i = 0; i < side_; ++i)
        coordinates_[index(d, i)] = grid_.origin[d] + static_cast<double>(tile[d] * side_ + i) * grid_.cell_size;
  }

  /// Adds V W(|x − p|) at every point p of the tile within the support of x.
  void add(const std::array<double, D>& x) {
    std::array<int, D> low{}, high{};
    for (int d = 0; d < D; ++d) {
      // One point of slack each side: the table gives exactly zero from the support on.
      const auto nearest = static_cast<int>(std::floor((x[d] - coordinates_[index(d, 0)]) / grid_.cell_size));
      low[d] = std::max(0, nearest - reach_);
      high[d] = std::min(side_ - 1, nearest + reach_ + 1);
      if (low[d] > high[d]) return;
      for (int i = low[d]; i <= high[d]; ++i) {
        const double delta = coordinates_[index(d, i)] - x[d];
        squared_[index(d, i)] = delta * delta;
      }
    }
    const double support_squared = table_.support_squared();
    std::array<int, D> local = low;
    while (true) {
      double row_squared = 0;
      std::size_t row_offset = 0;
      for (int d = D - 1; d >= 1; --d) {
        row_squared += squared_[index(d, local[d])];
        row_offset = (row_offset + static_cast<std::size_t>(local[d])) * static_cast<std::size_t>(side_);
      }
      if (row_squared < support_squared) {
        double* row = values_.data() + row_offset;
        const double* along = squared_.data();
        for (int i = low[0]; i <= high[0]; ++i) row[i] += table_(row_squared + along[i]);
      }
      int d = 1;
      for (; d < D && local[d] == high[d]; ++d) local[d] = low[d];
      if (d == D) break;
      ++local[d];
    }
  }

  /// Copies the tile's values into those of its blocks that `grid` stores.
  void store_into(SparseGrid<D>& grid) const {
    const int n = grid.block_points;
    for_each_index<D>(tile_blocks, [&](const std::array<int, D>& inner) {
      GridPoint<D> block{};
      for (int d = 0; d < D; ++d) block[d] = tile_[d] * tile_blocks + inner[d];
      const std::uint64_t key = pack<D>(block);
      const auto found = std::lower_bound(grid.block_keys.begin(), grid.block_keys.end(), key);
      if (found == grid.block_keys.end() || *found != key) return;
      double* target =
          grid.values.data() + static_cast<std::size_t>(found - grid.block_keys.begin()) * grid.points_per_block();
      // Row by row along the first axis: n values from the tile's row at the block's place.
      std::array<int, D> rows_of_block{};
      rows_of_block[0] = 1;
      for (int d = 1; d < D; ++d) rows_of_block[d] = n;
      for_each_index<D>(rows_of_block, [&](const std::array<int, D>& row) {
        std::size_t source = 0;
        for (int d = D - 1; d >= 0; --d)
          source = source * static_cast<std::size_t>(side_) + static_cast<std::size_t>(inner[d] * n + row[d]);
        std::memcpy(target, values_.data() + source, static_cast<std::size_t>(n) * sizeof(double));
        target += n;
      });
    });
  }

 private:
  /// Calls f(index) for every index with 0 ≤ index[d] < extent[d], the first axis fastest.
  template <int Dim, class F>
  static void for_each_index(const std::array<int, Dim>& extent, F&& f) {
    std::array<int, Dim> at{};
    while (true) {
      f(at);
      int d = 0;
      for (; d < Dim && at[d] == extent[d] - 1; ++d) at[d] = 0;
      if (d == Dim) return;
      ++at[d];
    }
  }
  template <int Dim, class F>
  static void for_each_index(int extent, F&& f) {
    std::array<int, Dim> extents{};
    extents.fill(extent);
    for_each_index<Dim>(extents, f);
  }

  std::size_t index(int d, int i) const { return static_cast<std::size_t>(d * side_ + i); }

  const SparseGrid<D>& grid_;
  const KernelTable& table_;
  int side_;
  int reach_;
  GridPoint<D> tile_{};
  std::vector<double> coordinates_;
  std::vector<double> squared_;
  std::vector<double> values_;
};

}  // namespace tide::surface
