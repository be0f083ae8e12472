// Mesh repair and placement: what is unambiguous is repaired (an inside-out or partly turned
// surface is oriented outward, degenerate triangles go), what is not is refused with the
// triangle's index and the reason; placement scales, then rotates, then translates.

#include "tide/io/mesh_repair.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "mesh_shapes.hpp"
#include "tide/io/mesh_placement.hpp"

namespace tide {
namespace {

std::string refusal(scene::TriangleMesh mesh) {
  try {
    io::repair_mesh(mesh, "part.stl");
  } catch (const scene::SceneError& error) {
    return error.what();
  }
  return "no error";
}

// A box 2 × 3 × 4: volume 24 (the sum's terms, integers over 6, round within a few ulps).
const scene::TriangleMesh box = test::box_mesh({0, 0, 0}, {2, 3, 4});

TEST(MeshRepair, InsideOutMeshIsTurnedOutward) {
  scene::TriangleMesh mesh = box;
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  EXPECT_DOUBLE_EQ(io::signed_volume(mesh), -24.0);
  const io::MeshRepairs repairs = io::repair_mesh(mesh, "box.stl");
  EXPECT_EQ(repairs.turned_triangles, 12u);
  EXPECT_DOUBLE_EQ(io::signed_volume(mesh), 24.0);
}

TEST(MeshRepair, OneTurnedTriangleIsTurnedBack) {
  scene::TriangleMesh mesh = box;
  std::swap(mesh.triangles[5][1], mesh.triangles[5][2]);
  const io::MeshRepairs repairs = io::repair_mesh(mesh, "box.stl");
  EXPECT_EQ(repairs.turned_triangles, 1u);
  EXPECT_EQ(mesh.triangles, box.triangles);
}

TEST(MeshRepair, DegenerateTrianglesAndDuplicateVerticesGo) {
  scene::TriangleMesh mesh = box;
  // A copy of vertex 0 used by one triangle, a triangle with a repeated vertex, one of zero area
  // (corners 0, 1 and the midpoint of their edge) and its unused midpoint.
  mesh.vertices.push_back(mesh.vertices[0]);
  mesh.vertices.push_back({1, 0, 0});
  mesh.triangles[0][0] = 8;
  mesh.triangles.push_back({2, 2, 3});
  mesh.triangles.push_back({0, 9, 1});
  const io::MeshRepairs repairs = io::repair_mesh(mesh, "box.stl");
  EXPECT_EQ(repairs.merged_vertices, 1u);
  EXPECT_EQ(repairs.removed_triangles, 2u);
  EXPECT_EQ(repairs.turned_triangles, 0u);
  EXPECT_EQ(mesh.vertices, box.vertices);  // the unused midpoint is dropped
  EXPECT_EQ(mesh.triangles, box.triangles);
}

TEST(MeshRepair, OpenMeshIsRefusedWithTheTriangle) {
  scene::TriangleMesh mesh = box;
  mesh.triangles.erase(mesh.triangles.begin() + 4);  // triangle {0, 1, 5}: its neighbours' edges are open
  const std::string message = refusal(mesh);
  EXPECT_NE(message.find("part.stl"), std::string::npos) << message;
  // Edges sorted by vertex: (0, 1) is the first open one, of triangle 1 ({0, 3, 1}).
  EXPECT_NE(message.find("triangle 1 has an open edge (vertices 0 and 1)"), std::string::npos) << message;
}

TEST(MeshRepair, NonManifoldEdgeIsRefused) {
  scene::TriangleMesh mesh = box;
  // A second box sharing the edge (0, 1)... as one more fin on that edge: a triangle to a new vertex.
  mesh.vertices.push_back({1, -1, -1});
  mesh.triangles.push_back({0, 1, 8});
  mesh.triangles.push_back({1, 0, 8});
  const std::string message = refusal(mesh);
  EXPECT_NE(message.find("non-manifold"), std::string::npos) << message;
  EXPECT_NE(message.find("triangle 1 "), std::string::npos) << message;
}

TEST(MeshPlacement, ScaleThenRotateThenTranslate) {
  scene::TriangleMesh mesh;
  mesh.vertices = {{100, 0, 0}, {0, 0, 50}};
  scene::Mesh placement;
  placement.scale = 2;
  placement.units = 0.01;  // cm
  placement.axis = {0, 0, 3};
  placement.degrees = 90;
  placement.translation = {1, 2, 3};
  io::place_mesh(mesh, placement);
  // (100, 0, 0) cm × 2 = (2, 0, 0) m, a quarter turn about z: (0, 2, 0), then + (1, 2, 3).
  EXPECT_NEAR(mesh.vertices[0][0], 1, 1e-15);
  EXPECT_NEAR(mesh.vertices[0][1], 4, 1e-15);
  EXPECT_NEAR(mesh.vertices[0][2], 3, 1e-15);
  // On the axis: only scaled and translated.
  EXPECT_EQ(mesh.vertices[1], (std::array<double, 3>{1, 2, 4}));
}

}  // namespace
}  // namespace tide
