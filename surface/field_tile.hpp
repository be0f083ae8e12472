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

#include "kernel_row.hpp"
#include "kernel_table.hpp"
#include "tide/surface/sparse_grid.hpp"

namespace tide::surface {

/// Blocks per tile along each axis.
inline constexpr int tile_blocks = 6;

/// A tile's block that the grid does not store.
inline constexpr std::size_t no_block = SIZE_MAX;

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

  /// Starts tile `tile` (tile coordinates) with every value zero.
  void start(const GridPoint<D>& tile) {
    std::fill(values_.begin(), values_.end(), 0.0);
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
      if (row_squared < support_squared)
        add_kernel_row(table_, values_.data() + row_offset + low[0], squared_.data() + low[0], high[0] - low[0] + 1,
                       row_squared);
      int d = 1;
      for (; d < D && local[d] == high[d]; ++d) local[d] = low[d];
      if (d == D) break;
      ++local[d];
    }
  }

  /// Blocks per tile.
  static constexpr int block_count = D == 2 ? tile_blocks * tile_blocks : tile_blocks * tile_blocks * tile_blocks;

  /// Copies the tile's values into its blocks that `grid` stores: block n of the tile (first axis
  /// fastest) is grid block slots[n] (no_block: not stored), and one marked in `inside` gets
  /// `inside_value` at every point instead.
  void store_into(SparseGrid<D>& grid, const std::array<std::size_t, block_count>& slots,
                  const std::array<bool, block_count>& inside, double inside_value) const {
    const int n = grid.block_points;
    const std::size_t points = grid.points_per_block();
    int slot = 0;
    for_each_index<D>(tile_blocks, [&](const std::array<int, D>& inner) {
      const std::size_t b = slots[static_cast<std::size_t>(slot)];
      const bool fill = inside[static_cast<std::size_t>(slot++)];
      if (b == no_block) return;
      double* target = grid.values.data() + b * points;
      if (fill) {
        std::fill(target, target + points, inside_value);
        return;
      }
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

 private:
  std::size_t index(int d, int i) const { return static_cast<std::size_t>(d * side_ + i); }

  const SparseGrid<D>& grid_;
  const KernelTable& table_;
  int side_;
  int reach_;
  std::vector<double> coordinates_;
  std::vector<double> squared_;
  std::vector<double> values_;
};

}  // namespace tide::surface
