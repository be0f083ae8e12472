#include "tide/surface/particle_spacing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "particle_blocks.hpp"
#include "tide/core/parallel.hpp"

namespace tide::surface {

template <int D>
double median_neighbour_distance(std::span<const double> positions) {
  const std::size_t count = positions.size() / D;
  if (count < 2) throw std::invalid_argument("particle spacing: fewer than two particles");
  const auto [lowest, highest] = bounds_of<D>(positions);
  // Blocks of the spacing particles spread evenly over their bounding box would have (never less
  // than the spacing of a fluid that fills part of its box), one block of margin below.
  double box = 1, extent = 0;
  for (int d = 0; d < D; ++d) {
    box *= highest[d] - lowest[d];
    extent = std::max(extent, highest[d] - lowest[d]);
  }
  if (!(extent > 0) || !std::isfinite(extent))
    throw std::invalid_argument("particle spacing: the particles do not span a finite region");
  const double even_spacing =
      box > 0 ? std::pow(box / static_cast<double>(count), 1.0 / D) : extent / static_cast<double>(count);
  const double block_size = std::max(even_spacing, extent / double(max_points_per_axis / 4));
  Point<D> origin;
  for (int d = 0; d < D; ++d) origin[d] = lowest[d] - block_size;
  const ParticlesByBlock<D> particles = sort_into_blocks<D>(positions, origin, block_size);

  // A particle with no neighbour within its 3^D blocks (a lone drop) counts as infinitely far.
  std::vector<double> nearest(count);
  for_each_particle(count, [&](std::size_t i) {
    const Point<D>& x = particles.positions[i];
    GridPoint<D> block{};
    for (int d = 0; d < D; ++d) block[d] = static_cast<std::int64_t>(std::floor((x[d] - origin[d]) / block_size));
    double closest_squared = std::numeric_limits<double>::infinity();
    for_each_neighbour_offset<D>([&](const GridPoint<D>& offset) {
      GridPoint<D> neighbour{};
      for (int d = 0; d < D; ++d) neighbour[d] = block[d] + offset[d];
      const auto range = particles_in_block(particles, pack<D>(neighbour));
      for (std::size_t j = range.first; j < range.second; ++j) {
        if (j == i) continue;
        double distance_squared = 0;
        for (int d = 0; d < D; ++d)
          distance_squared += (x[d] - particles.positions[j][d]) * (x[d] - particles.positions[j][d]);
        closest_squared = std::min(closest_squared, distance_squared);
      }
    });
    nearest[i] = std::sqrt(closest_squared);
  });
  const auto median = nearest.begin() + static_cast<std::ptrdiff_t>(count / 2);
  std::nth_element(nearest.begin(), median, nearest.end());
  if (!std::isfinite(*median) || !(*median > 0))
    throw std::invalid_argument("particle spacing: most particles have no neighbour at a positive distance");
  return *median;
}

template double median_neighbour_distance<2>(std::span<const double>);
template double median_neighbour_distance<3>(std::span<const double>);

}  // namespace tide::surface
