#include "tide/surface/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tide::surface {

MeshTopology mesh_topology(const scene::TriangleMesh& mesh) {
  // Each triangle side as (lower vertex, higher vertex, walked from lower to higher?).
  struct Side {
    std::uint64_t edge;
    bool forward;
  };
  std::vector<Side> sides;
  sides.reserve(3 * mesh.triangles.size());
  for (const auto& triangle : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t from = triangle[k], to = triangle[(k + 1) % 3];
      sides.push_back({std::min(from, to) << 32 | std::max(from, to), from < to});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return a.edge < b.edge || (a.edge == b.edge && a.forward < b.forward);
  });
  MeshTopology topology;
  topology.vertices = mesh.vertices.size();
  topology.triangles = mesh.triangles.size();
  for (std::size_t first = 0; first < sides.size();) {
    std::size_t last = first;
    while (last < sides.size() && sides[last].edge == sides[first].edge) ++last;
    ++topology.edges;
    const std::size_t uses = last - first;
    if (uses == 1) ++topology.open_edges;
    if (uses > 2) ++topology.crowded_edges;
    if (uses == 2 && sides[first].forward == sides[first + 1].forward) ++topology.misoriented_edges;
    first = last;
  }
  return topology;
}

double surface_area(const scene::TriangleMesh& mesh) {
  double area = 0;
  for (const auto& triangle : mesh.triangles) {
    const auto& a = mesh.vertices[triangle[0]];
    const auto& b = mesh.vertices[triangle[1]];
    const auto& c = mesh.vertices[triangle[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

}  // namespace tide::surface
