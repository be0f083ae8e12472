#pragma once

// A triangle surface as the mesh readers (io/include/tide/io/mesh_reader.hpp) give it: vertex
// coordinates and, per triangle, three indices into them (counter-clockwise seen from outside once
// repaired, io/include/tide/io/mesh_repair.hpp).

#include <array>
#include <cstdint>
#include <vector>

namespace tide::scene {

struct TriangleMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace tide::scene
