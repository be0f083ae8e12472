#include <array>

#include "scene_keys.hpp"
#include "scene_sections.hpp"

namespace tide::io {

std::span<const Key<scene::Body>> body_keys() {
  static constexpr std::array<Key<scene::Body>, 2> keys{{
      {"density", "number > 0", "kg/m³", "",
       "The body's uniform density; its mass, centre of mass and inertia follow from its shape (in 2D, per metre "
       "of depth).",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::Body& body) {
         body.density = values.number(value, positive);
       }},
      {"constraints", "object", "–", "none", "What the body may not do.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Body& body) {
         read_section(values, value, body_constraint_keys(), body.constraints);
       }},
  }};
  return keys;
}

std::span<const Key<scene::BodyConstraints>> body_constraint_keys() {
  static constexpr std::array<Key<scene::BodyConstraints>, 4> keys{{
      {"locked_translation", "array of booleans, one per axis", "–", "all `false`",
       "Axes along which the centre of mass does not move.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::BodyConstraints& constraints) {
         constraints.locked_translation = values.flags(value);
       }},
      {"locked_rotation", "boolean", "–", "`false`", "The body does not turn. Not with `rotation_axis`.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::BodyConstraints& constraints) {
         constraints.locked_rotation = values.boolean(value);
       }},
      {"rotation_axis", "vector (3D only)", "–", "none (free; 2D bodies turn about z)",
       "The body turns about this axis only (normalised); with `pivot`, a hinge.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::BodyConstraints& constraints) {
         constraints.rotation_axis =
             read_rotation_axis(values, value, "no rotation_axis in a 2D scene (2D bodies turn about z)");
       }},
      {"pivot", "vector", "m", "none",
       "A point fixed in the body and in space: the body turns about it and does not translate.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::BodyConstraints& constraints) {
         constraints.pivot = values.vector(value);
       }},
  }};
  return keys;
}

}  // namespace tide::io
