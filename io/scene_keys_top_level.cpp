#include <array>
#include <limits>

#include "scene_keys.hpp"
#include "scene_sections.hpp"
#include "scene_text.hpp"

namespace tide::io {
namespace {

constexpr double standard_gravity = 9.81;  // m/s²

void read_gravity(const ValueReader& values, const Node& value, scene::Scene& scene) {
  scene.gravity = {};
  scene.gravity[scene.dimension - 1] = -standard_gravity;  // up is the last axis
  if (value.present()) scene.gravity = values.vector(value);
}

}  // namespace

// Read in this order: each section may depend on those above it (the fluid on the materials, the
// domain on the container, the probes on the domain).
std::span<const Key<scene::Scene>> top_level_keys() {
  static constexpr std::array<Key<scene::Scene>, 13> keys{{
      {"dimension", "integer, 2 or 3", "–", "", "Number of space dimensions.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Scene& scene) {
         scene.dimension = static_cast<int>(values.integer(value, 2, 3, "2 or 3"));
       }},
      {"particle_spacing", "number > 0", "m", "", "Distance Δx between neighbouring particles on the initial lattice.",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::Scene& scene) {
         scene.particle_spacing = values.number(value, positive);
       }},
      {"kernel", "object", "–", "see below", "Smoothing kernel.", Presence::always, read_kernel},
      {"crowd", "object", "–", "no crowd",
       "People instead of a fluid, with `solver.scheme` `\"crowd\"`: agents, exits and the crowd model "
       "([crowds.md](crowds.md)). A crowd scene has no `materials` and no `fluid`.",
       Presence::optional, read_crowd},
      {"materials", "non-empty array of objects", "–", "none with a `crowd`", "The fluids. Required without a `crowd`.",
       Presence::always, read_materials},
      {"fluid", "non-empty array of objects", "–", "none with a `crowd`",
       "The blocks filled with fluid particles at the start. Required without a `crowd`.", Presence::always,
       read_fluid},
      {"walls", "object", "–", "no walls", "Container and obstacles made of wall particles.", Presence::optional,
       read_walls},
      {"domain", "object", "–", "derived from `walls.container`",
       "Region particles may occupy. Required without a container.", Presence::always, read_domain},
      {"gravity", "vector", "m/s²", "`[0, -9.81]` (2D), `[0, 0, -9.81]` (3D)",
       "Body acceleration on every fluid particle.", Presence::always, read_gravity},
      {"solver", "object", "–", "see below", "Scheme and numerical options.", Presence::optional, read_solver},
      {"time", "object", "–", "", "Simulated time span and output interval.", Presence::required, read_time},
      {"output", "object", "–", "see below", "What each output frame holds, and how often probes are read.",
       Presence::always, read_output},
      {"probes", "array of objects", "–", "`[]`", "Pressure sensors and wave gauges, written to `probes.csv`.",
       Presence::optional, read_probes},
  }};
  return keys;
}

std::span<const Key<scene::Scene>> kernel_keys() {
  static constexpr std::array<Key<scene::Scene>, 2> keys{{
      {"type", "string", "–", "`\"wendland_c2\"`", "Kernel name, from the table below.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Scene& scene) {
         scene.kernel = values.kernel_type(value);
       }},
      {"smoothing_ratio", "number > 0, and support radius in spacings < 2³¹ − 1", "–", "`1.3`",
       "Smoothing length over particle spacing, h / Δx. (The upper bound only refuses absurd values whose "
       "wall-layer count would not fit an integer.)",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Scene& scene) {
         // The wall layers this ratio needs, ceil(support / spacing), are counted in an int.
         const double support = static_cast<double>(kernel_support_factor(scene.kernel));
         const double most_layers = std::numeric_limits<int>::max();
         scene.smoothing_ratio = values.number(value, "a number > 0 and < " + format_number(most_layers / support),
                                               [&](double x) { return x > 0 && support * x < most_layers; });
       }},
  }};
  return keys;
}

void read_kernel(const ValueReader& values, const Node& node, scene::Scene& scene) {
  if (node.present()) read_section(values, node, kernel_keys(), scene);
  scene.walls.layers = scene::required_wall_layers(scene.kernel, scene.smoothing_ratio);
}

}  // namespace tide::io
