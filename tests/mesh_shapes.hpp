#pragma once

// Meshes the mesh tests build in code: a box (12 triangles, outward) and an icosphere (an
// icosahedron's faces split in four `levels` times, vertices pushed onto the sphere), and the
// obstacle a scene makes of a placed mesh.

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>

#include "tide/core/scene.hpp"
#include "tide/io/mesh_placement.hpp"

namespace tide::test {

inline scene::TriangleMesh box_mesh(const scene::Vec& lo, const scene::Vec& hi) {
  scene::TriangleMesh mesh;
  for (int k = 0; k < 8; ++k)
    mesh.vertices.push_back({(k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]});
  // Each face as two triangles, counter-clockwise seen from outside.
  mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return mesh;
}

inline scene::TriangleMesh icosphere(const scene::Vec& centre, double radius, int levels) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> unit = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                             {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  const auto project = [](std::array<double, 3> v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return std::array<double, 3>{v[0] / n, v[1] / n, v[2] / n};
  };
  for (auto& v : unit) v = project(v);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = middle.try_emplace(key, static_cast<std::uint32_t>(unit.size()));
      if (added) unit.push_back(project({unit[a][0] + unit[b][0], unit[a][1] + unit[b][1], unit[a][2] + unit[b][2]}));
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    for (const auto& f : faces) {
      const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    faces = std::move(finer);
  }
  scene::TriangleMesh mesh;
  for (const auto& v : unit)
    mesh.vertices.push_back({centre[0] + radius * v[0], centre[1] + radius * v[1], centre[2] + radius * v[2]});
  mesh.triangles = faces;
  return mesh;
}

inline scene::Obstacle mesh_obstacle(scene::TriangleMesh surface) {
  scene::Mesh mesh;
  mesh.bounds = io::mesh_bounds(surface);
  mesh.surface = std::make_shared<const scene::TriangleMesh>(std::move(surface));
  return {mesh, {}, std::nullopt, std::nullopt, std::nullopt};
}

}  // namespace tide::test
