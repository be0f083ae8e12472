#include "tide/surface/surface_mesh.hpp"

#include <stdexcept>
#include <vector>

#include "grid_edges.hpp"
#include "tide/core/parallel.hpp"
#include "tide/surface/marching_cases.hpp"

namespace tide::surface {
namespace {

using EdgeTriangle = std::array<std::uint64_t, 3>;

/// The triangles of one block's cells, as the grid edges their corners lie on. A cell whose lowest
/// corner lies in a block that is not stored has all its corners at zero (a stored block's points
/// next to an unstored one are beyond the support of every particle), so no cell is missed.
std::vector<EdgeTriangle> block_triangles(const SparseGrid<3>& grid, std::size_t block, double iso_level) {
  const BlockCorners<3> corners(grid, grid.block_keys[block]);
  if (!corners.crossed(iso_level)) return {};
  const GridPoint<3> block_coordinates = unpack<3>(grid.block_keys[block]);
  const int n = grid.block_points;
  std::vector<EdgeTriangle> triangles;
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        unsigned mask = 0;
        for (int c = 0; c < 8; ++c)
          if (corners({x + (c & 1), y + (c >> 1 & 1), z + (c >> 2 & 1)}) > iso_level) mask |= 1u << c;
        const CubeCase& cell = cube_case(mask);
        for (int t = 0; t < cell.triangle_count; ++t) {
          EdgeTriangle triangle{};
          for (int k = 0; k < 3; ++k) {
            const int edge = cell.triangles[t][k];
            const std::array<int, 3> origin = cube_edge_origin(edge);
            const GridPoint<3> start = {block_coordinates[0] * n + x + origin[0],
                                        block_coordinates[1] * n + y + origin[1],
                                        block_coordinates[2] * n + z + origin[2]};
            triangle[k] = edge_key<3>(start, edge / 4);
          }
          triangles.push_back(triangle);
        }
      }
    }
  }
  return triangles;
}

}  // namespace

scene::TriangleMesh marching_cubes(const SparseGrid<3>& grid, double iso_level) {
  if (!(iso_level > 0)) throw std::invalid_argument("marching cubes: the iso-level must be positive");
  std::vector<std::vector<EdgeTriangle>> per_block(grid.block_keys.size());
  for_each_particle(per_block.size(), [&](std::size_t b) { per_block[b] = block_triangles(grid, b, iso_level); });

  std::vector<EdgeTriangle> triangles;
  for (auto& block : per_block) triangles.insert(triangles.end(), block.begin(), block.end());
  if (3 * triangles.size() >= std::size_t(UINT32_MAX))
    throw std::invalid_argument("marching cubes: more than 2^32 triangle corners");

  // One vertex per crossed edge: sort the corners by edge, number the distinct edges in order.
  std::vector<KeyIndex> corners(3 * triangles.size());
  for_each_particle(corners.size(), [&](std::size_t c) {
    corners[c] = {triangles[c / 3][c % 3], static_cast<std::uint32_t>(c)};
  });
  parallel_sort(corners);
  scene::TriangleMesh mesh;
  mesh.triangles.resize(triangles.size());
  std::vector<std::uint64_t> vertex_edges;
  for (std::size_t c = 0; c < corners.size(); ++c) {
    if (c == 0 || corners[c].key != corners[c - 1].key) vertex_edges.push_back(corners[c].key);
    mesh.triangles[corners[c].index / 3][corners[c].index % 3] = static_cast<std::uint32_t>(vertex_edges.size() - 1);
  }
  mesh.vertices.resize(vertex_edges.size());
  for_each_particle(vertex_edges.size(),
                    [&](std::size_t v) { mesh.vertices[v] = crossing_point<3>(grid, vertex_edges[v], iso_level); });
  return mesh;
}

scene::TriangleMesh reconstruct_surface(std::span<const double> positions, const FieldSettings& settings,
                                        double iso_fraction) {
  return marching_cubes(colour_field<3>(positions, settings), surface_level<3>(settings, iso_fraction));
}

}  // namespace tide::surface
