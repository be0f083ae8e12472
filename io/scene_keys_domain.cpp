#include <array>

#include "scene_keys.hpp"
#include "scene_sections.hpp"
#include "scene_shapes.hpp"
#include "scene_text.hpp"

namespace tide::io {

std::span<const Key<scene::Domain>> domain_keys() {
  static constexpr std::array<Key<scene::Domain>, 4> keys{{
      {"min", "vector", "m", "", "Low corner.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Domain& domain) {
         read_min_corner(values, value, domain.box);
       }},
      {"max", "vector", "m", "", "High corner; `max` > `min` on every axis.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Domain& domain) {
         read_max_corner(values, value, domain.box);
       }},
      {"periodic", "array of `dimension` booleans", "–", "all `false`",
       "Per axis: particles leaving on one side re-enter on the other.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Domain& domain) {
         domain.periodic = values.flags(value);
       }},
      {"inflow", "object", "–", "none",
       "Pseudo-periodic inflow/outflow along x (`wcsph` only; x must be periodic): `{\"velocity\": U, \"length\": "
       "L}`, and optionally `\"phase\"`: the name of a material the inflow injects.",
       Presence::optional,
       // Pseudo-periodic: the outflow at max x re-enters at min x, so x must be periodic.
       [](const ValueReader& values, const Node& value, scene::Domain& domain) {
         values.expect_object(value, key_names(inflow_keys()));
         if (!domain.periodic[0]) {
           values.fail(value,
                       "no inflow unless the x axis is periodic (\"periodic\": [true, ...]): the outflow re-enters "
                       "there");
         }
         read_section(values, value, inflow_keys(), domain.inflow.emplace());
       }},
  }};
  return keys;
}

std::span<const Key<scene::Inflow>> inflow_keys() {
  static constexpr std::array<Key<scene::Inflow>, 3> keys{{
      {"velocity", "number", "m/s", "", "The speed along x given to the fluid in the inflow buffer.",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::Inflow& inflow) {
         inflow.velocity = values.number(value, any_number);
       }},
      {"length", "number > 0, shorter than the domain along x", "m", "",
       "The buffer's extent along x from the domain's min x.", Presence::required,
       // Read into the scene's own domain (read_domain), whose corners are read by now.
       [](const ValueReader& values, const Node& value, scene::Inflow& inflow) {
         const scene::Box& box = values.scene().domain.box;
         const double width = box.max[0] - box.min[0];
         inflow.length =
             values.number(value, "a number > 0 and < the domain's length along x (" + format_number(width) + ")",
                           [&](double length) { return length > 0 && length < width; });
       }},
      {"phase", "string", "–", "none", "The name of a material that every particle re-entering at min x becomes.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Inflow& inflow) {
         inflow.phase = values.material_index(value, values.scene().materials);
       }},
  }};
  return keys;
}

void read_domain(const ValueReader& values, const Node& node, scene::Scene& scene) {
  if (node.present()) {
    read_section(values, node, domain_keys(), scene.domain);
    return;
  }
  if (!scene.walls.container) {
    values.fail(node,
                "an object with the keys \"min\", \"max\", \"periodic\" (only a scene with a wall container, "
                "from which the domain is derived, may leave it out)");
  }
  scene.domain =
      scene::domain_around(*scene.walls.container, scene.walls.layers * scene.particle_spacing, scene.dimension);
}

}  // namespace tide::io
