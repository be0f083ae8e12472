#include "tide/io/mesh_repair.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace tide::io {
namespace {

using Point = std::array<double, 3>;

Point difference(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The file a mesh came from and, per triangle kept, its index in the file (for messages).
struct Origin {
  const std::filesystem::path& file;
  std::vector<std::uint32_t> triangles;
};

[[noreturn]] void refuse(const Origin& origin, std::uint32_t triangle, const std::string& reason) {
  throw scene::SceneError(origin.file.string(), "", "a closed, manifold, orientable triangle mesh",
                          "triangle " + std::to_string(origin.triangles[triangle]) + " " + reason);
}

std::size_t merge_equal_vertices(scene::TriangleMesh& mesh) {
  std::map<Point, std::uint32_t> first_index;
  std::vector<std::uint32_t> merged(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    merged[v] = first_index.try_emplace(mesh.vertices[v], static_cast<std::uint32_t>(v)).first->second;
  for (auto& triangle : mesh.triangles)
    for (std::uint32_t& corner : triangle) corner = merged[corner];
  return mesh.vertices.size() - first_index.size();
}

bool degenerate(const scene::TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return true;
  const Point& a = mesh.vertices[t[0]];
  return cross(difference(mesh.vertices[t[1]], a), difference(mesh.vertices[t[2]], a)) == Point{};
}

// Keeps the vertices some triangle uses, in their order.
void drop_unused_vertices(scene::TriangleMesh& mesh) {
  std::vector<std::uint32_t> renumbered(mesh.vertices.size(), 0);
  for (const auto& triangle : mesh.triangles)
    for (const std::uint32_t corner : triangle) renumbered[corner] = 1;
  std::vector<Point> kept;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (renumbered[v] == 0) continue;
    renumbered[v] = static_cast<std::uint32_t>(kept.size());
    kept.push_back(mesh.vertices[v]);
  }
  for (auto& triangle : mesh.triangles)
    for (std::uint32_t& corner : triangle) corner = renumbered[corner];
  mesh.vertices = std::move(kept);
}

// Across each edge of each triangle: the triangle on the other side, and whether it walks the
// edge in the same direction (then the two disagree in orientation).
struct Neighbours {
  std::vector<std::array<std::uint32_t, 3>> triangle;
  std::vector<std::array<bool, 3>> same_direction;
};

Neighbours find_neighbours(const scene::TriangleMesh& mesh, const Origin& origin) {
  struct Side {
    std::uint32_t low, high, triangle, edge;
    bool forward;  // walked low → high
  };
  std::vector<Side> sides;
  sides.reserve(3 * mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t a = mesh.triangles[t][e], b = mesh.triangles[t][(e + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), t, e, a < b});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return std::tie(x.low, x.high, x.triangle, x.edge) < std::tie(y.low, y.high, y.triangle, y.edge);
  });
  Neighbours neighbours{std::vector<std::array<std::uint32_t, 3>>(mesh.triangles.size()),
                        std::vector<std::array<bool, 3>>(mesh.triangles.size())};
  for (std::size_t first = 0; first < sides.size();) {
    std::size_t last = first + 1;
    while (last < sides.size() && sides[last].low == sides[first].low && sides[last].high == sides[first].high) ++last;
    const Side& s = sides[first];
    const std::string edge = "(vertices " + std::to_string(s.low) + " and " + std::to_string(s.high) + ")";
    if (last - first == 1) refuse(origin, s.triangle, "has an open edge " + edge + " that no other triangle shares");
    if (last - first > 2) {
      refuse(
          origin, s.triangle,
          "shares an edge " + edge + " with " + std::to_string(last - first - 1) + " other triangles (non-manifold)");
    }
    const Side& o = sides[first + 1];
    neighbours.triangle[s.triangle][s.edge] = o.triangle;
    neighbours.triangle[o.triangle][o.edge] = s.triangle;
    neighbours.same_direction[s.triangle][s.edge] = neighbours.same_direction[o.triangle][o.edge] =
        s.forward == o.forward;
    first = last;
  }
  return neighbours;
}

double triangle_volume(const scene::TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t) {
  return dot(mesh.vertices[t[0]], cross(mesh.vertices[t[1]], mesh.vertices[t[2]])) / 6;
}

// Turns triangles to agree with their neighbours (breadth first from the lowest unvisited index),
// then each component outward; returns how many were turned.
std::size_t orient(scene::TriangleMesh& mesh, const Neighbours& neighbours, const Origin& origin) {
  const std::size_t n = mesh.triangles.size();
  std::vector<int> turn(n, -1);  // -1 unvisited, else 0 or 1
  std::vector<std::uint32_t> component;
  for (std::uint32_t seed = 0; seed < n; ++seed) {
    if (turn[seed] >= 0) continue;
    component.assign(1, seed);
    turn[seed] = 0;
    for (std::size_t next = 0; next < component.size(); ++next) {
      const std::uint32_t t = component[next];
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t u = neighbours.triangle[t][e];
        const int wanted = turn[t] ^ static_cast<int>(neighbours.same_direction[t][e]);
        if (turn[u] < 0) {
          turn[u] = wanted;
          component.push_back(u);
        } else if (turn[u] != wanted) {
          refuse(origin, u, "cannot be oriented consistently with its neighbours (a non-orientable surface)");
        }
      }
    }
    double volume = 0;
    for (const std::uint32_t t : component) volume += (turn[t] ? -1 : 1) * triangle_volume(mesh, mesh.triangles[t]);
    if (volume < 0)
      for (const std::uint32_t t : component) turn[t] ^= 1;
  }
  std::size_t turned = 0;
  for (std::size_t t = 0; t < n; ++t) {
    if (turn[t] == 0) continue;
    std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
    ++turned;
  }
  return turned;
}

}  // namespace

double signed_volume(const scene::TriangleMesh& mesh) {
  double volume = 0;
  for (const auto& triangle : mesh.triangles) volume += triangle_volume(mesh, triangle);
  return volume;
}

MeshRepairs repair_mesh(scene::TriangleMesh& mesh, const std::filesystem::path& file) {
  MeshRepairs repairs;
  repairs.merged_vertices = merge_equal_vertices(mesh);
  Origin origin{file, {}};
  std::vector<std::array<std::uint32_t, 3>> kept;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (degenerate(mesh, mesh.triangles[t])) continue;
    kept.push_back(mesh.triangles[t]);
    origin.triangles.push_back(t);
  }
  repairs.removed_triangles = mesh.triangles.size() - kept.size();
  mesh.triangles = std::move(kept);
  if (mesh.triangles.empty())
    throw scene::SceneError(file.string(), "", "a mesh with a triangle of non-zero area", "none");
  drop_unused_vertices(mesh);
  repairs.turned_triangles = orient(mesh, find_neighbours(mesh, origin), origin);
  return repairs;
}

}  // namespace tide::io
