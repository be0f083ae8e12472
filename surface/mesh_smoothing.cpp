#include "tide/surface/mesh_smoothing.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "tide/core/parallel.hpp"

namespace tide::surface {
namespace {

/// Each vertex's neighbours along the mesh's edges, ascending: neighbours of v are
/// targets[starts[v]] .. targets[starts[v + 1] − 1].
struct VertexNeighbours {
  std::vector<std::size_t> starts;
  std::vector<std::uint32_t> targets;
};

VertexNeighbours vertex_neighbours(const scene::TriangleMesh& mesh) {
  std::vector<std::uint64_t> edges;
  edges.reserve(6 * mesh.triangles.size());
  for (const auto& triangle : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = triangle[k], b = triangle[(k + 1) % 3];
      edges.push_back(a << 32 | b);
      edges.push_back(b << 32 | a);
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  VertexNeighbours neighbours;
  neighbours.starts.assign(mesh.vertices.size() + 1, 0);
  neighbours.targets.reserve(edges.size());
  for (const std::uint64_t edge : edges) {
    ++neighbours.starts[(edge >> 32) + 1];
    neighbours.targets.push_back(static_cast<std::uint32_t>(edge & 0xffffffffu));
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) neighbours.starts[v + 1] += neighbours.starts[v];
  return neighbours;
}

/// x_i ← x_i + factor · (mean of the neighbours − x_i) for every vertex at once.
void umbrella_step(const VertexNeighbours& neighbours, double factor, std::vector<std::array<double, 3>>& positions,
                   std::vector<std::array<double, 3>>& scratch) {
  for_each_particle(positions.size(), [&](std::size_t v) {
    const std::size_t first = neighbours.starts[v], last = neighbours.starts[v + 1];
    scratch[v] = positions[v];
    if (first == last) return;
    std::array<double, 3> mean{};
    for (std::size_t n = first; n < last; ++n)
      for (int d = 0; d < 3; ++d) mean[d] += positions[neighbours.targets[n]][d];
    for (int d = 0; d < 3; ++d)
      scratch[v][d] += factor * (mean[d] / static_cast<double>(last - first) - positions[v][d]);
  });
  positions.swap(scratch);
}

}  // namespace

void smooth_taubin(scene::TriangleMesh& mesh, const TaubinSettings& settings) {
  if (settings.iterations <= 0) return;
  const VertexNeighbours neighbours = vertex_neighbours(mesh);
  std::vector<std::array<double, 3>> scratch(mesh.vertices.size());
  for (int iteration = 0; iteration < settings.iterations; ++iteration) {
    umbrella_step(neighbours, settings.lambda, mesh.vertices, scratch);
    umbrella_step(neighbours, settings.mu, mesh.vertices, scratch);
  }
}

}  // namespace tide::surface
