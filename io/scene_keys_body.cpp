#include <array>

#include "scene_keys.hpp"
#include "scene_sections.hpp"

namespace tide::io {

std::span<const Key<scene::Body>> body_keys() {
  static constexpr std::array<Key<scene::Body>, 4> keys{{
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
      {"release_time", "number >= 0", "s", "`0`",
       "The body is held where it starts, at rest, until this simulated time, while the fluid settles around it (as "
       "DualSPHysics' FtPause); the fluid's force on it is summed from the start.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Body& body) {
         body.release_time = values.number(value, non_negative);
       }},
      {"applied_force", "vector", "N (2D: N/m)", "`[0, 0, 0]`",
       "A constant force on the body at its centre of mass, besides gravity and the fluid's: a tow, or a body's "
       "weight less its buoyancy where the scene leaves gravity, and with it the hydrostatic pressure, out (a body "
       "settling slowly through a viscous fluid: docs/bodies.md).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Body& body) {
         body.applied_force = values.vector(value);
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

std::span<const Key<scene::BodyContact>> body_contact_keys() {
  static constexpr std::array<Key<scene::BodyContact>, 3> keys{{
      {"restitution", "number in (0, 1]", "–", "`0.2`",
       "The ratio of the normal speeds after and before an impact of two solid particles (the spring's damping).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::BodyContact& contact) {
         contact.restitution = values.number(value, in_unit_interval);
       }},
      {"friction", "number >= 0", "–", "`0.5`",
       "Coulomb's coefficient: the tangential force of a contact is at most this times the normal force.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::BodyContact& contact) {
         contact.friction = values.number(value, non_negative);
       }},
      {"frequency", "number > 0", "rad/s", "0.2 / the acoustic time step",
       "ω of a particle pair's spring, k = m ω² with m the lighter particle's share of its body's mass: a body resting "
       "on others sinks into them by about g / ω² times its particles per contact.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::BodyContact& contact) {
         contact.frequency = values.number(value, positive);
       }},
  }};
  return keys;
}

}  // namespace tide::io
