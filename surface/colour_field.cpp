#include "tide/surface/colour_field.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "field_tile.hpp"
#include "kernel_table.hpp"
#include "particle_blocks.hpp"
#include "tide/core/kernels/cubic_spline.hpp"
#include "tide/core/parallel.hpp"

namespace tide::surface {
namespace {

void check_settings(const FieldSettings& settings) {
  const auto positive = [](double value) { return std::isfinite(value) && value > 0; };
  if (!positive(settings.particle_spacing) || !positive(settings.smoothing_ratio) || !positive(settings.cell_ratio))
    throw std::invalid_argument(
        "surface reconstruction: particle spacing, smoothing ratio and cell ratio must be "
        "positive and finite");
}

template <int D>
double particle_volume(const FieldSettings& settings) {
  return std::pow(settings.particle_spacing, D);
}

template <int D>
CubicSplineKernel<D> field_kernel(const FieldSettings& settings) {
  return CubicSplineKernel<D>(static_cast<Real>(settings.smoothing_ratio * settings.particle_spacing));
}

/// Every block within one block of an occupied one: where c can be non-zero. Dilated one axis at a
/// time: a step of one block along an axis adds the same amount to every packed key (coordinates
/// stay within their bits: colour_field leaves a block of margin each side), so each shifted copy
/// stays sorted and the union is two merges, not a sort.
template <int D>
std::vector<std::uint64_t> blocks_in_reach(const std::vector<std::uint64_t>& occupied) {
  std::vector<std::uint64_t> reached = occupied, below, above, merged;
  for (int d = 0; d < D; ++d) {
    const std::uint64_t step = std::uint64_t(1) << (d * key_bits_per_axis);
    below.resize(reached.size());
    above.resize(reached.size());
    std::transform(reached.begin(), reached.end(), below.begin(), [&](std::uint64_t key) { return key - step; });
    std::transform(reached.begin(), reached.end(), above.begin(), [&](std::uint64_t key) { return key + step; });
    merged.clear();
    std::merge(below.begin(), below.end(), reached.begin(), reached.end(), std::back_inserter(merged));
    reached.clear();
    std::merge(merged.begin(), merged.end(), above.begin(), above.end(), std::back_inserter(reached));
    reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  }
  return reached;
}

/// The tiles (field_tile.hpp) that hold the stored blocks, ascending.
template <int D>
std::vector<std::uint64_t> tiles_of(const std::vector<std::uint64_t>& block_keys) {
  std::vector<std::uint64_t> tiles;
  tiles.reserve(block_keys.size());
  for (const std::uint64_t key : block_keys) {
    GridPoint<D> block = unpack<D>(key);
    for (int d = 0; d < D; ++d) block[d] /= tile_blocks;
    tiles.push_back(pack<D>(block));
  }
  std::sort(tiles.begin(), tiles.end());
  tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
  return tiles;
}

/// Particle blocks around a tile (local coordinates −1 … tile_blocks along each axis, stored from
/// 0, first axis fastest) and whether each must be added to it.
inline constexpr int nearby_side = tile_blocks + 2;
template <int D>
using NearbyBlocks = std::array<bool, D == 2 ? nearby_side * nearby_side : nearby_side * nearby_side * nearby_side>;

/// The particle blocks whose particles reach a block of the tile that is summed (stored and not
/// taken as inside): within one block of one, since the support is one block.
template <int D>
NearbyBlocks<D> blocks_to_add(const std::array<std::size_t, FieldTile<D>::block_count>& slots,
                              const std::array<bool, FieldTile<D>::block_count>& inside) {
  NearbyBlocks<D> needed{};
  int slot = 0;
  FieldTile<D>::template for_each_index<D>(tile_blocks, [&](const std::array<int, D>& inner) {
    const auto n = static_cast<std::size_t>(slot++);
    if (slots[n] == no_block || inside[n]) return;
    // inner + 1 + offset, offset in {−1, 0, 1}^D, in the padded local coordinates.
    FieldTile<D>::template for_each_index<D>(3, [&](const std::array<int, D>& offset) {
      std::size_t at = 0;
      for (int d = D - 1; d >= 0; --d) at = at * nearby_side + static_cast<std::size_t>(inner[d] + offset[d]);
      needed[at] = true;
    });
  });
  return needed;
}

/// Adds to `tile` the particles of the blocks within one block of it that `needed` marks, in key
/// order (rows of blocks along the first axis are runs of consecutive keys). A particle of a block
/// left out adds exactly zero to every summed block's points, so theirs are the full sums.
template <int D>
void add_particles_near(FieldTile<D>& tile, const GridPoint<D>& tile_coordinates, const ParticlesByBlock<D>& particles,
                        const NearbyBlocks<D>& needed) {
  std::array<int, D> rows{};
  rows[0] = 1;
  for (int d = 1; d < D; ++d) rows[d] = nearby_side;
  std::array<int, D> row{};
  const std::int64_t row_start = tile_coordinates[0] * tile_blocks - 1;
  while (true) {
    GridPoint<D> first{}, last{};
    bool below = false;  // a row below block 0 holds no particles (colour_field leaves a margin)
    std::size_t row_at = 0;
    for (int d = D - 1; d >= 0; --d) {
      first[d] = last[d] = tile_coordinates[d] * tile_blocks - 1 + row[d];
      below = below || (d > 0 && first[d] < 0);
      row_at = row_at * nearby_side + static_cast<std::size_t>(row[d]);
    }
    last[0] = first[0] + tile_blocks + 1;
    first[0] = std::max<std::int64_t>(first[0], 0);
    const auto begin = std::lower_bound(particles.block_keys.begin(), particles.block_keys.end(), pack<D>(first));
    const auto end = std::upper_bound(begin, particles.block_keys.end(), pack<D>(last));
    const auto k_end = static_cast<std::size_t>(end - particles.block_keys.begin());
    for (auto k = static_cast<std::size_t>(begin - particles.block_keys.begin()); !below && k < k_end; ++k) {
      const std::int64_t x = unpack<D>(particles.block_keys[k])[0] - row_start;
      if (!needed[row_at + static_cast<std::size_t>(x)]) continue;
      for (std::size_t j = particles.block_starts[k]; j < particles.block_starts[k + 1]; ++j)
        tile.add(particles.positions[j]);
    }
    int d = 1;
    for (; d < D && row[d] == rows[d] - 1; ++d) row[d] = 0;
    if (d == D) return;
    ++row[d];
  }
}

/// The blocks every block within two blocks of which holds at least `least` particles: the field
/// is taken to exceed the surface level on them and one cell beyond (the support is one block),
/// and they are not summed (docs/rendering.md, "Limits"). Ascending. Eroded one axis at a time: a
/// block stays if the blocks up to two steps each way along the axis stayed at the axis before.
/// Shifting every key by the same step keeps them sorted; a shift that would take a coordinate
/// below zero drops the key (no block is there).
template <int D>
std::vector<std::uint64_t> blocks_inside(const ParticlesByBlock<D>& particles, std::size_t least) {
  constexpr int margin = 2;
  std::vector<std::uint64_t> kept, previous, shifted, common;
  for (std::size_t k = 0; k < particles.block_keys.size(); ++k)
    if (particles.block_starts[k + 1] - particles.block_starts[k] >= least) kept.push_back(particles.block_keys[k]);
  for (int d = 0; d < D; ++d) {
    const std::uint64_t step = std::uint64_t(1) << (d * key_bits_per_axis);
    previous = kept;
    for (int s = -margin; s <= margin; ++s) {
      if (s == 0) continue;
      // Key k stays if k + s · step was kept: the previous keys shifted by −s steps.
      shifted.clear();
      for (const std::uint64_t key : previous) {
        if (s > 0 && unpack<D>(key)[d] < s) continue;
        shifted.push_back(s > 0 ? key - std::uint64_t(s) * step : key + std::uint64_t(-s) * step);
      }
      common.clear();
      std::set_intersection(kept.begin(), kept.end(), shifted.begin(), shifted.end(), std::back_inserter(common));
      kept.swap(common);
    }
  }
  return kept;
}

/// For each stored block of `grid`, whether it is one of `inside` (ascending, all stored).
std::vector<bool> stored_inside(const std::vector<std::uint64_t>& stored, const std::vector<std::uint64_t>& inside) {
  std::vector<bool> flags(stored.size(), false);
  std::size_t b = 0;
  for (const std::uint64_t key : inside) {
    while (stored[b] != key) ++b;
    flags[b] = true;
  }
  return flags;
}

}  // namespace

template <int D>
SparseGrid<D> colour_field(std::span<const double> positions, const FieldSettings& settings) {
  check_settings(settings);
  const CubicSplineKernel<D> kernel = field_kernel<D>(settings);
  const double support = kernel.support_radius();
  SparseGrid<D> grid;
  grid.block_points =
      std::max(1, static_cast<int>(std::lround(support / (settings.cell_ratio * settings.particle_spacing))));
  grid.cell_size = support / grid.block_points;
  const std::size_t count = positions.size() / D;
  if (count == 0) return grid;

  // One empty block of margin below the particles, and a cell more against round-off, keeps every
  // block coordinate of the reach ≥ 0 (points at the same places relative to the particles).
  const auto [lowest, highest] = bounds_of<D>(positions);
  for (int d = 0; d < D; ++d) {
    grid.origin[d] = lowest[d] - support - grid.cell_size;
    if ((highest[d] - grid.origin[d]) / grid.cell_size + 3.0 * grid.block_points >= double(max_points_per_axis))
      throw std::invalid_argument("surface reconstruction: the particles span " +
                                  std::to_string(highest[d] - lowest[d]) + " m along axis " + std::to_string(d) +
                                  ", more than 2^20 grid cells of " + std::to_string(grid.cell_size) + " m");
  }

  const ParticlesByBlock<D> particles = sort_into_blocks<D>(positions, grid.origin, support);
  grid.block_keys = blocks_in_reach<D>(particles.block_keys);
  const std::size_t points_per_block = grid.points_per_block();
  grid.values.assign(grid.block_keys.size() * points_per_block, 0.0);
  const double volume = particle_volume<D>(settings);
  const KernelTable table([&](double r) { return volume * kernel.value(static_cast<Real>(r)); }, support);

  // Tile by tile, each point summing its particles in the order of their blocks' keys and, within
  // a block, of their indices: the same for any thread count. A block deep in the fluid holds the
  // interior value instead: the fewest particles a block of the fluid's lattice holds, with every
  // block within two of it at least that full, marks one; a tile all of whose blocks are such is
  // not summed at all.
  const auto lattice_points_per_axis = static_cast<std::size_t>(std::floor(support / settings.particle_spacing));
  std::size_t least = 1;
  for (int d = 0; d < D; ++d) least *= std::max<std::size_t>(lattice_points_per_axis, 1);
  const double inside = interior_colour<D>(settings);
  const std::vector<bool> inside_flags = stored_inside(grid.block_keys, blocks_inside<D>(particles, least));
  const std::vector<std::uint64_t> tiles = tiles_of<D>(grid.block_keys);
  parallel_blocks(tiles.size(), 1, [&](std::size_t begin, std::size_t end) {
    FieldTile<D> tile(grid, table);
    std::array<std::size_t, FieldTile<D>::block_count> slots{};
    std::array<bool, FieldTile<D>::block_count> inside_blocks{};
    for (std::size_t t = begin; t < end; ++t) {
      const GridPoint<D> coordinates = unpack<D>(tiles[t]);
      bool all_inside = true;
      int slot = 0;
      FieldTile<D>::template for_each_index<D>(tile_blocks, [&](const std::array<int, D>& inner) {
        GridPoint<D> block{};
        for (int d = 0; d < D; ++d) block[d] = coordinates[d] * tile_blocks + inner[d];
        const std::uint64_t key = pack<D>(block);
        const auto found = std::lower_bound(grid.block_keys.begin(), grid.block_keys.end(), key);
        const bool stored = found != grid.block_keys.end() && *found == key;
        const auto n = static_cast<std::size_t>(slot++);
        slots[n] = stored ? static_cast<std::size_t>(found - grid.block_keys.begin()) : no_block;
        inside_blocks[n] = stored && inside_flags[slots[n]];
        all_inside = all_inside && (!stored || inside_blocks[n]);
      });
      if (!all_inside) {
        tile.start(coordinates);
        add_particles_near<D>(tile, coordinates, particles, blocks_to_add<D>(slots, inside_blocks));
      }
      tile.store_into(grid, slots, inside_blocks, inside);
    }
  });
  return grid;
}

template <int D>
double interior_colour(const FieldSettings& settings) {
  check_settings(settings);
  const CubicSplineKernel<D> kernel = field_kernel<D>(settings);
  const auto reach = static_cast<int>(std::ceil(kernel.support_radius() / settings.particle_spacing));
  const int side = 2 * reach + 1;
  int cells = 1;
  for (int d = 0; d < D; ++d) cells *= side;
  double sum = 0;
  for (int n = 0; n < cells; ++n) {
    double distance_squared = 0;
    int rest = n;
    for (int d = 0; d < D; ++d) {
      const double delta = (rest % side - reach) * settings.particle_spacing;
      distance_squared += delta * delta;
      rest /= side;
    }
    sum += kernel.value(static_cast<Real>(std::sqrt(distance_squared)));
  }
  return particle_volume<D>(settings) * sum;
}

template <int D>
double surface_level(const FieldSettings& settings, double iso_fraction) {
  if (!(iso_fraction > 0 && iso_fraction < 1))
    throw std::invalid_argument("surface reconstruction: the iso fraction must lie between 0 and 1");
  return iso_fraction * interior_colour<D>(settings);
}

template SparseGrid<2> colour_field<2>(std::span<const double>, const FieldSettings&);
template SparseGrid<3> colour_field<3>(std::span<const double>, const FieldSettings&);
template double interior_colour<2>(const FieldSettings&);
template double interior_colour<3>(const FieldSettings&);
template double surface_level<2>(const FieldSettings&, double);
template double surface_level<3>(const FieldSettings&, double);

}  // namespace tide::surface
