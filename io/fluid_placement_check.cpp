#include <string>
#include <variant>

#include "geometry_checks.hpp"
#include "scene_text.hpp"
#include "tide/core/scene_error.hpp"

namespace tide::io {
namespace {

using Shape = std::variant<scene::Box, scene::Ball>;

void check_inside(const scene::Scene& scene, const Shape& shape, const std::string& path, const scene::Box& region,
                  const std::string& region_name) {
  const double slack = coordinate_slack(scene);
  const int dimension = scene.dimension;
  if (const auto* ball = std::get_if<scene::Ball>(&shape)) {
    for (int d = 0; d < dimension; ++d) {
      if (ball->centre[d] - ball->radius < region.min[d] - slack ||
          ball->centre[d] + ball->radius > region.max[d] + slack) {
        throw scene::SceneError(scene.source, path,
                                "a ball inside " + region_name + " " + format_box(region, dimension),
                                format_shape(shape, dimension));
      }
    }
    return;
  }
  const auto& box = std::get<scene::Box>(shape);
  for (int d = 0; d < dimension; ++d) {
    const std::string axis = axis_index(d);
    if (box.min[d] < region.min[d] - slack) {
      throw scene::SceneError(
          scene.source, path + "/min/" + std::to_string(d),
          "a number >= " + format_number(region.min[d]) + " (the min" + axis + " of " + region_name + ")",
          format_number(box.min[d]));
    }
    if (box.max[d] > region.max[d] + slack) {
      throw scene::SceneError(
          scene.source, path + "/max/" + std::to_string(d),
          "a number <= " + format_number(region.max[d]) + " (the max" + axis + " of " + region_name + ")",
          format_number(box.max[d]));
    }
  }
}

}  // namespace

void check_fluid_placement(const scene::Scene& scene) {
  for (std::size_t k = 0; k < scene.fluid.size(); ++k) {
    const Shape& shape = scene.fluid[k].shape;
    const std::string path =
        "/fluid/" + std::to_string(k) + (std::holds_alternative<scene::Box>(shape) ? "/box" : "/ball");
    if (scene.walls.container)
      check_inside(scene, shape, path, scene.walls.container->inner, "the container's inner box");
    check_inside(scene, shape, path, scene.domain.box, "the domain");
  }
}

}  // namespace tide::io
