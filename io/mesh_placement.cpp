#include "tide/io/mesh_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tide::io {

void place_mesh(scene::TriangleMesh& mesh, const scene::Mesh& placement) {
  const double factor = placement.scale * placement.units;
  const double length = std::sqrt(placement.axis[0] * placement.axis[0] + placement.axis[1] * placement.axis[1] +
                                  placement.axis[2] * placement.axis[2]);
  const scene::Vec k{placement.axis[0] / length, placement.axis[1] / length, placement.axis[2] / length};
  const double angle = placement.degrees * std::numbers::pi / 180;
  const double c = std::cos(angle), s = std::sin(angle);
  for (auto& vertex : mesh.vertices) {
    const scene::Vec x{factor * vertex[0], factor * vertex[1], factor * vertex[2]};
    // Rodrigues: x cos θ + (k × x) sin θ + k (k · x)(1 − cos θ).
    const scene::Vec kx{k[1] * x[2] - k[2] * x[1], k[2] * x[0] - k[0] * x[2], k[0] * x[1] - k[1] * x[0]};
    const double along = (k[0] * x[0] + k[1] * x[1] + k[2] * x[2]) * (1 - c);
    for (int d = 0; d < 3; ++d) vertex[d] = x[d] * c + kx[d] * s + k[d] * along + placement.translation[d];
  }
}

scene::Box mesh_bounds(const scene::TriangleMesh& mesh) {
  scene::Box box;
  box.min.fill(std::numeric_limits<double>::infinity());
  box.max.fill(-std::numeric_limits<double>::infinity());
  for (const auto& vertex : mesh.vertices) {
    for (int d = 0; d < 3; ++d) {
      box.min[d] = std::min(box.min[d], vertex[d]);
      box.max[d] = std::max(box.max[d], vertex[d]);
    }
  }
  return box;
}

}  // namespace tide::io
