#include "tide/render/mesh_shading.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "lighting.hpp"
#include "tide/render/particle_splats.hpp"

namespace tide::render {
namespace {

Point3 subtract(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Σ over a vertex's triangles of (b − a) × (c − a), which weights each normal by twice its area.
std::vector<Point3> vertex_normals(const scene::TriangleMesh& mesh) {
  std::vector<Point3> normals(mesh.vertices.size(), Point3{0, 0, 0});
  for (const auto& triangle : mesh.triangles) {
    const Point3 normal = cross(subtract(mesh.vertices[triangle[1]], mesh.vertices[triangle[0]]),
                                subtract(mesh.vertices[triangle[2]], mesh.vertices[triangle[0]]));
    for (const std::uint32_t v : triangle)
      for (int d = 0; d < 3; ++d) normals[v][d] += normal[d];
  }
  return normals;
}

}  // namespace

void draw_mesh(Image& image, const Camera& camera, const scene::TriangleMesh& mesh, Colour colour) {
  std::vector<double> depth = empty_depth(camera);
  draw_mesh(image, camera, mesh, colour, depth);
}

void draw_mesh(Image& image, const Camera& camera, const scene::TriangleMesh& mesh, Colour colour,
               std::vector<double>& depth) {
  const std::vector<Point3> normals = vertex_normals(mesh);
  const PixelRegion& region = camera.region;
  for (const auto& triangle : mesh.triangles) {
    Point3 corner[3];
    for (int k = 0; k < 3; ++k) corner[k] = camera.project(mesh.vertices[triangle[k]]);
    // Twice the signed area in pixels; barycentric weights are the sub-triangles' shares of it.
    const double area = (corner[1][0] - corner[0][0]) * (corner[2][1] - corner[0][1]) -
                        (corner[2][0] - corner[0][0]) * (corner[1][1] - corner[0][1]);
    if (area == 0) continue;
    const int left =
        std::max(region.left, static_cast<int>(std::floor(std::min({corner[0][0], corner[1][0], corner[2][0]}))));
    const int right = std::min(region.left + region.width - 1,
                               static_cast<int>(std::ceil(std::max({corner[0][0], corner[1][0], corner[2][0]}))));
    const int top =
        std::max(region.top, static_cast<int>(std::floor(std::min({corner[0][1], corner[1][1], corner[2][1]}))));
    const int bottom = std::min(region.top + region.height - 1,
                                static_cast<int>(std::ceil(std::max({corner[0][1], corner[1][1], corner[2][1]}))));
    for (int y = top; y <= bottom; ++y) {
      for (int x = left; x <= right; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        double weight[3];
        for (int k = 0; k < 3; ++k) {
          const Point3& a = corner[(k + 1) % 3];
          const Point3& b = corner[(k + 2) % 3];
          weight[k] = ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) / area;
        }
        if (weight[0] < 0 || weight[1] < 0 || weight[2] < 0) continue;
        const double z = weight[0] * corner[0][2] + weight[1] * corner[1][2] + weight[2] * corner[2][2];
        double& nearest = depth[static_cast<std::size_t>(y - region.top) * region.width + (x - region.left)];
        if (z >= nearest) continue;
        nearest = z;
        Point3 normal{0, 0, 0};
        for (int k = 0; k < 3; ++k)
          for (int d = 0; d < 3; ++d) normal[d] += weight[k] * normals[triangle[k]][d];
        // In picture axes (right, up, towards the viewer), as the light is given.
        const Point3 facing = {dot(normal, camera.right), dot(normal, camera.up), -dot(normal, camera.forward)};
        const double length = std::sqrt(dot(facing, facing));
        const double cosine = length > 0 ? std::abs(dot(facing, light_direction)) / length : 0;
        image.at(x, y) = lit(colour, cosine);
      }
    }
  }
}

}  // namespace tide::render
