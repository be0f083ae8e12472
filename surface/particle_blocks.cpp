#include "particle_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tide/core/parallel.hpp"

namespace tide::surface {

template <int D>
Bounds<D> bounds_of(std::span<const double> positions) {
  Bounds<D> bounds;
  for (int d = 0; d < D; ++d) bounds.lowest[d] = bounds.highest[d] = positions[d];
  for (std::size_t k = 0; k < positions.size(); ++k) {
    if (!std::isfinite(positions[k])) throw std::invalid_argument("a particle position is not finite");
    const int d = static_cast<int>(k % D);
    bounds.lowest[d] = std::min(bounds.lowest[d], positions[k]);
    bounds.highest[d] = std::max(bounds.highest[d], positions[k]);
  }
  return bounds;
}

template <int D>
ParticlesByBlock<D> sort_into_blocks(std::span<const double> positions, const Point<D>& origin, double block_size) {
  const std::size_t count = positions.size() / D;
  std::vector<KeyIndex> keys(count);
  for_each_particle(count, [&](std::size_t i) {
    GridPoint<D> block{};
    for (int d = 0; d < D; ++d)
      block[d] = static_cast<std::int64_t>(std::floor((positions[i * D + d] - origin[d]) / block_size));
    keys[i] = {pack<D>(block), static_cast<std::uint32_t>(i)};
  });
  parallel_sort(keys);
  ParticlesByBlock<D> sorted;
  sorted.positions.resize(count);
  for_each_particle(count, [&](std::size_t i) {
    for (int d = 0; d < D; ++d) sorted.positions[i][d] = positions[keys[i].index * D + d];
  });
  for (std::size_t i = 0; i < count; ++i) {
    if (i == 0 || keys[i].key != keys[i - 1].key) {
      sorted.block_keys.push_back(keys[i].key);
      sorted.block_starts.push_back(i);
    }
  }
  sorted.block_starts.push_back(count);
  return sorted;
}

template <int D>
std::pair<std::size_t, std::size_t> particles_in_block(const ParticlesByBlock<D>& particles, std::uint64_t block_key) {
  const auto found = std::lower_bound(particles.block_keys.begin(), particles.block_keys.end(), block_key);
  if (found == particles.block_keys.end() || *found != block_key) return {0, 0};
  const auto k = static_cast<std::size_t>(found - particles.block_keys.begin());
  return {particles.block_starts[k], particles.block_starts[k + 1]};
}

template Bounds<2> bounds_of<2>(std::span<const double>);
template Bounds<3> bounds_of<3>(std::span<const double>);
template ParticlesByBlock<2> sort_into_blocks<2>(std::span<const double>, const Point<2>&, double);
template ParticlesByBlock<3> sort_into_blocks<3>(std::span<const double>, const Point<3>&, double);
template std::pair<std::size_t, std::size_t> particles_in_block<2>(const ParticlesByBlock<2>&, std::uint64_t);
template std::pair<std::size_t, std::size_t> particles_in_block<3>(const ParticlesByBlock<3>&, std::uint64_t);

}  // namespace tide::surface
