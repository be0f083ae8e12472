#include <string>

#include "geometry_checks.hpp"
#include "scene_text.hpp"
#include "tide/core/scene_error.hpp"

namespace tide::io {

// The wall particles must lie inside the domain, which would otherwise remove them. An open top
// has no wall above the container's rim.
void check_container_in_domain(const scene::Scene& scene) {
  if (!scene.walls.container) return;
  const scene::Container& container = *scene.walls.container;
  const scene::Box& domain = scene.domain.box;
  const double slack = coordinate_slack(scene);
  const double wall = scene.walls.layers * scene.particle_spacing;
  const std::string wall_text =
      std::to_string(scene.walls.layers) + " wall layers of " + format_number(scene.particle_spacing);
  for (int d = 0; d < scene.dimension; ++d) {
    const std::string axis = axis_index(d);
    if (container.inner.min[d] - wall < domain.min[d] - slack) {
      throw scene::SceneError(scene.source, "/walls/container/min/" + std::to_string(d),
                              "a number >= " + format_number(domain.min[d] + wall) + " (the domain's min" + axis +
                                  " plus " + wall_text + ")",
                              format_number(container.inner.min[d]));
    }
    const bool open_above = container.open_top && d == scene.dimension - 1;
    const double wall_above = open_above ? 0 : wall;
    if (container.inner.max[d] + wall_above > domain.max[d] + slack) {
      throw scene::SceneError(scene.source, "/walls/container/max/" + std::to_string(d),
                              "a number <= " + format_number(domain.max[d] - wall_above) + " (the domain's max" + axis +
                                  (open_above ? "" : " minus " + wall_text) + ")",
                              format_number(container.inner.max[d]));
    }
  }
}

}  // namespace tide::io
