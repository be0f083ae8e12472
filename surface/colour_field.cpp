#include "tide/surface/colour_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

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

template <int D>
GridPoint<D> first_point_of(const GridPoint<D>& block, int block_points) {
  GridPoint<D> g{};
  for (int d = 0; d < D; ++d) g[d] = block[d] * block_points;
  return g;
}

/// Every block within one block of an occupied one: where c can be non-zero.
template <int D>
std::vector<std::uint64_t> blocks_in_reach(const std::vector<std::uint64_t>& occupied) {
  std::vector<std::uint64_t> reached;
  reached.reserve(occupied.size() * (D == 2 ? 9 : 27));
  for (const std::uint64_t key : occupied) {
    const GridPoint<D> block = unpack<D>(key);
    for_each_neighbour_offset<D>([&](const GridPoint<D>& offset) {
      GridPoint<D> neighbour{};
      for (int d = 0; d < D; ++d) neighbour[d] = block[d] + offset[d];
      reached.push_back(pack<D>(neighbour));
    });
  }
  std::sort(reached.begin(), reached.end());
  reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  return reached;
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

  // One empty block of margin below the particles keeps every block coordinate of the reach ≥ 0.
  const auto [lowest, highest] = bounds_of<D>(positions);
  for (int d = 0; d < D; ++d) {
    grid.origin[d] = lowest[d] - support;
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
  const double support_squared = support * support;

  for_each_particle(grid.block_keys.size(), [&](std::size_t b) {
    const GridPoint<D> block = unpack<D>(grid.block_keys[b]);
    std::array<std::pair<std::size_t, std::size_t>, D == 2 ? 9 : 27> ranges{};
    std::size_t range_count = 0;
    for_each_neighbour_offset<D>([&](const GridPoint<D>& offset) {
      GridPoint<D> neighbour{};
      for (int d = 0; d < D; ++d) neighbour[d] = block[d] + offset[d];
      const auto range = particles_in_block(particles, pack<D>(neighbour));
      if (range.first != range.second) ranges[range_count++] = range;
    });
    // Each particle adds to the block's points in the box of its support, so a point sums its
    // particles in the order of the ranges: the same for any thread count.
    double* values = grid.values.data() + b * points_per_block;
    const GridPoint<D> first = first_point_of<D>(block, grid.block_points);
    const Point<D> block_origin = grid.position(first);
    const int last = grid.block_points - 1;
    for (std::size_t r = 0; r < range_count; ++r) {
      for (std::size_t j = ranges[r].first; j < ranges[r].second; ++j) {
        const Point<D>& x = particles.positions[j];
        std::array<int, D> low{}, high{}, local{};
        bool empty = false;
        for (int d = 0; d < D; ++d) {
          low[d] = std::max(0, static_cast<int>(std::ceil((x[d] - support - block_origin[d]) / grid.cell_size)));
          high[d] = std::min(last, static_cast<int>(std::floor((x[d] + support - block_origin[d]) / grid.cell_size)));
          empty = empty || low[d] > high[d];
        }
        if (empty) continue;
        // Row by row along the first axis, the other axes' share of the distance taken once a row.
        const auto coordinate = [&](int d, int index) {
          return grid.origin[d] + static_cast<double>(first[d] + index) * grid.cell_size;
        };
        local = low;
        while (true) {
          double row_squared = 0;
          std::size_t row_offset = 0;
          for (int d = D - 1; d >= 1; --d) {
            const double delta = coordinate(d, local[d]) - x[d];
            row_squared += delta * delta;
            row_offset =
                (row_offset + static_cast<std::size_t>(local[d])) * static_cast<std::size_t>(grid.block_points);
          }
          for (int i = low[0]; row_squared < support_squared && i <= high[0]; ++i) {
            const double delta = coordinate(0, i) - x[0];
            const double distance_squared = row_squared + delta * delta;
            if (distance_squared < support_squared)
              values[row_offset + static_cast<std::size_t>(i)] +=
                  volume * kernel.value(static_cast<Real>(std::sqrt(distance_squared)));
          }
          int d = 1;
          for (; d < D && local[d] == high[d]; ++d) local[d] = low[d];
          if (d == D) break;
          ++local[d];
        }
      }
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
