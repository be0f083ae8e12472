#include <array>
#include <cstdint>
#include <limits>
#include <string>

#include "scene_keys.hpp"
#include "scene_sections.hpp"
#include "scene_shapes.hpp"
#include "scene_text.hpp"

namespace tide::io {
namespace {

/// Fewer layers than the kernel support leave a fluid particle at a wall with a truncated
/// kernel: the wall lets fluid through or pushes it too weakly.
void read_layers(const ValueReader& values, const Node& value, scene::Walls& walls) {
  const scene::Scene& scene = values.scene();
  const int least = scene::required_wall_layers(scene.kernel, scene.smoothing_ratio);
  const double support_in_spacings = static_cast<double>(kernel_support_factor(scene.kernel)) * scene.smoothing_ratio;
  const std::string expected = "an integer >= " + std::to_string(least) + " (ceil(kernel support / spacing), " +
                               "the support being " + format_number(support_in_spacings) + " spacings)";
  walls.layers = static_cast<int>(values.integer(value, least, std::numeric_limits<int>::max(), expected));
}

scene::Obstacle read_obstacle(const ValueReader& values, const Node& node) {
  scene::Obstacle obstacle;
  read_section(values, node, obstacle_keys(), obstacle);
  const std::string_view shape = shape_key(values, node, {"box", "ball", "plane", "mesh"});
  if (shape == "box") {
    obstacle.shape = read_box(values, child(node, shape));
  } else if (shape == "ball") {
    obstacle.shape = read_ball(values, child(node, shape));
  } else if (shape == "plane") {
    obstacle.shape = read_plane(values, child(node, shape));
    if (obstacle.motion) values.fail(child(node, "motion"), "no motion on a plane (a half-space cannot move)");
    if (obstacle.body) values.fail(child(node, "body"), "no body on a plane (a half-space has no finite mass)");
  } else {
    obstacle.shape = read_mesh(values, child(node, shape));
  }
  if (obstacle.body) {
    const Node body = child(node, "body");
    if (obstacle.motion) values.fail(body, "no body on an obstacle with a motion (the fluid moves a body)");
    if (obstacle.velocity != scene::Vec{})
      values.fail(body, "no body on an obstacle with a velocity (a body's surface moves with the body)");
    const scene::BodyConstraints& constraints = obstacle.body->constraints;
    if (constraints.locked_rotation && constraints.rotation_axis)
      values.fail(child(body, "constraints"), "locked_rotation or rotation_axis, not both");
  }
  return obstacle;
}

}  // namespace

std::span<const Key<scene::Walls>> wall_keys() {
  static constexpr std::array<Key<scene::Walls>, 4> keys{{
      {"layers", "integer ≥ ceil(support radius / Δx)", "–", "ceil(support radius / Δx), 3 with the default kernel",
       "Layers of wall particles behind each wall surface.", Presence::optional, read_layers},
      {"slip", "string: `\"no_slip\"` or `\"free_slip\"`", "–", "`\"no_slip\"`",
       "Tangential velocity condition at walls.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Walls& walls) {
         walls.slip = values.choice(value, wall_slip_names);
       }},
      {"container", "object", "–", "none", "A box whose inner faces are walls.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Walls& walls) {
         walls.container.emplace();
         read_section(values, value, container_keys(), *walls.container);
       }},
      {"obstacles", "array of objects", "–", "`[]`",
       "Solid shapes inside the domain, each `{\"box\": ...}`, `{\"ball\": ...}`, `{\"plane\": ...}` or "
       "`{\"mesh\": ...}` (exactly one shape key), with an optional `\"velocity\"`, `\"slip\"`, `\"motion\"` and "
       "`\"body\"`.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Walls& walls) {
         for (const Node& entry : values.elements(value, 0, "an array of obstacles"))
           walls.obstacles.push_back(read_obstacle(values, entry));
       }},
  }};
  return keys;
}

std::span<const Key<scene::Container>> container_keys() {
  static constexpr std::array<Key<scene::Container>, 3> keys{{
      {"min", "vector", "m", "", "Low corner of the inner (fluid-side) box.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Container& container) {
         read_min_corner(values, value, container.inner);
       }},
      {"max", "vector", "m", "", "High corner of the inner box; `max` > `min` on every axis.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Container& container) {
         read_max_corner(values, value, container.inner);
       }},
      {"open_top", "boolean", "–", "`true`", "Leave out the wall at the top (high end of the last axis).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Container& container) {
         container.open_top = values.boolean(value);
       }},
  }};
  return keys;
}

std::span<const Key<scene::Obstacle>> obstacle_keys() {
  static constexpr std::array<Key<scene::Obstacle>, 8> keys{{
      // Exactly one shape key (read_obstacle).
      {"box", "[box](#box)", "–", "–", "A solid box."},
      {"ball", "[ball](#ball)", "–", "–", "A solid ball (a disc in 2D)."},
      {"plane", "[plane](#plane)", "–", "–", "A solid half-space."},
      {"mesh", "[mesh](#mesh)", "–", "–", "A solid closed triangle mesh from a file (docs/bodies.md)."},
      {"velocity", "vector", "m/s", "zero",
       "The velocity of the obstacle's surface in the no-slip condition; its particles stay in place.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Obstacle& obstacle) {
         obstacle.velocity = values.vector(value);
       }},
      {"slip", "string: `\"no_slip\"` or `\"free_slip\"`", "–", "`walls.slip`",
       "The obstacle's tangential velocity condition. One that differs from `walls.slip` makes the obstacles "
       "of that slip a second wall contact (a no-slip obstacle in a free-slip tank, say).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Obstacle& obstacle) {
         obstacle.slip = values.choice(value, wall_slip_names);
       }},
      {"motion", "object: `rotation`, `oscillation`, `flap`, `table` or `steered`", "–", "none",
       "A prescribed rigid motion (docs/bodies.md), or one the running program steers (`steered`: tide serve's "
       "pointer); its particles move, with the motion's velocity as the surface velocity. Not with `velocity`.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Obstacle& obstacle) {
         if (obstacle.velocity != scene::Vec{})
           values.fail(value, "no motion on an obstacle with a velocity (the motion gives its surface velocity)");
         obstacle.motion = read_motion(values, value);
       }},
      {"body", "object: `density`, `constraints`, `release_time`, `applied_force`", "–", "none",
       "A rigid body moved by the fluid's forces and gravity (docs/bodies.md): a box, ball or mesh. Not with "
       "`velocity` or `motion`.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Obstacle& obstacle) {
         obstacle.body.emplace();
         read_section(values, value, body_keys(), *obstacle.body);
       }},
  }};
  return keys;
}

void read_walls(const ValueReader& values, const Node& node, scene::Scene& scene) {
  read_section(values, node, wall_keys(), scene.walls);
}

}  // namespace tide::io
