#include "tide/surface/surface_outline.hpp"

#include <algorithm>
#include <stdexcept>

#include "grid_edges.hpp"
#include "tide/core/parallel.hpp"
#include "tide/surface/marching_cases.hpp"

namespace tide::surface {
namespace {

/// A directed piece of the outline, from one crossed grid edge to another.
struct Segment {
  std::uint64_t from;
  std::uint64_t to;
};

std::vector<Segment> block_segments(const SparseGrid<2>& grid, std::size_t block, double iso_level) {
  const BlockCorners<2> corners(grid, grid.block_keys[block]);
  if (!corners.crossed(iso_level)) return {};
  const GridPoint<2> block_coordinates = unpack<2>(grid.block_keys[block]);
  const int n = grid.block_points;
  const auto key_of = [&](int x, int y, int edge) {
    const std::array<int, 2> origin = square_edge_origin(edge);
    const GridPoint<2> start = {block_coordinates[0] * n + x + origin[0], block_coordinates[1] * n + y + origin[1]};
    return edge_key<2>(start, square_edge_axis(edge));
  };
  std::vector<Segment> segments;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      unsigned mask = 0;
      for (int c = 0; c < 4; ++c) {
        const std::array<int, 2> corner = square_corner(c);
        if (corners({x + corner[0], y + corner[1]}) > iso_level) mask |= 1u << c;
      }
      const SquareCase& cell = square_case(mask);
      for (int s = 0; s < cell.segment_count; ++s)
        segments.push_back({key_of(x, y, cell.segments[s][0]), key_of(x, y, cell.segments[s][1])});
    }
  }
  return segments;
}

}  // namespace

Outline marching_squares(const SparseGrid<2>& grid, double iso_level) {
  if (!(iso_level > 0)) throw std::invalid_argument("marching squares: the iso-level must be positive");
  std::vector<std::vector<Segment>> per_block(grid.block_keys.size());
  for_each_particle(per_block.size(), [&](std::size_t b) { per_block[b] = block_segments(grid, b, iso_level); });
  std::vector<Segment> segments;
  for (auto& block : per_block) segments.insert(segments.end(), block.begin(), block.end());
  // Every crossed edge starts exactly one segment and ends one, so sorted by start they chain.
  std::sort(segments.begin(), segments.end(), [](const Segment& a, const Segment& b) { return a.from < b.from; });
  const auto starting_at = [&](std::uint64_t key) {
    const auto found = std::lower_bound(segments.begin(), segments.end(), key,
                                        [](const Segment& s, std::uint64_t k) { return s.from < k; });
    if (found == segments.end() || found->from != key)
      throw std::logic_error("marching squares: an outline does not close");
    return static_cast<std::size_t>(found - segments.begin());
  };
  Outline outline;
  std::vector<bool> used(segments.size(), false);
  for (std::size_t first = 0; first < segments.size(); ++first) {
    if (used[first]) continue;
    std::vector<std::array<double, 2>> loop;
    for (std::size_t s = first; !used[s]; s = starting_at(segments[s].to)) {
      used[s] = true;
      loop.push_back(crossing_point<2>(grid, segments[s].from, iso_level));
    }
    outline.loops.push_back(std::move(loop));
  }
  return outline;
}

Outline reconstruct_outline(std::span<const double> positions, const FieldSettings& settings, double iso_fraction) {
  return marching_squares(colour_field<2>(positions, settings), surface_level<2>(settings, iso_fraction));
}

double enclosed_area(const Outline& outline) {
  double twice_area = 0;
  for (const auto& loop : outline.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const auto& a = loop[k];
      const auto& b = loop[(k + 1) % loop.size()];
      twice_area += a[0] * b[1] - b[0] * a[1];
    }
  return twice_area / 2;
}

}  // namespace tide::surface
