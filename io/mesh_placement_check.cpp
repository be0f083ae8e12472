#include <string>
#include <variant>

#include "geometry_checks.hpp"
#include "scene_text.hpp"
#include "tide/core/scene_error.hpp"

namespace tide::io {

// A mesh's wall particles lie inside its bounding box, which must then lie inside the domain
// (that would otherwise remove them). In 2D only x and y count: the section is at z = 0.
void check_mesh_placement(const scene::Scene& scene) {
  const scene::Box& domain = scene.domain.box;
  const double slack = coordinate_slack(scene);
  for (std::size_t k = 0; k < scene.walls.obstacles.size(); ++k) {
    const auto* mesh = std::get_if<scene::Mesh>(&scene.walls.obstacles[k].shape);
    if (mesh == nullptr) continue;
    for (int d = 0; d < scene.dimension; ++d) {
      if (mesh->bounds.min[d] < domain.min[d] - slack || mesh->bounds.max[d] > domain.max[d] + slack) {
        throw scene::SceneError(scene.source, "/walls/obstacles/" + std::to_string(k) + "/mesh",
                                "a mesh inside the domain " + format_box(domain, scene.dimension),
                                "a placed mesh with bounds " + format_box(mesh->bounds, scene.dimension));
      }
    }
    if (scene.dimension == 2 && !(mesh->bounds.min[2] < 0 && mesh->bounds.max[2] > 0)) {
      throw scene::SceneError(
          scene.source, "/walls/obstacles/" + std::to_string(k) + "/mesh",
          "a mesh crossing the plane z = 0 (a 2D scene samples its section there)",
          "a placed mesh from z = " + format_number(mesh->bounds.min[2]) + " to " + format_number(mesh->bounds.max[2]));
    }
  }
}

}  // namespace tide::io
