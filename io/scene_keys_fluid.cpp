#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "scene_keys.hpp"
#include "scene_sections.hpp"
#include "scene_shapes.hpp"

namespace tide::io {
namespace {

// A crowd scene (read before the materials and the fluid) has agents instead: true where it
// has a crowd, which may not have this key.
bool refused_in_crowd(const ValueReader& values, const Node& node, const scene::Scene& scene) {
  if (!scene.crowd) return false;
  if (node.present()) values.fail(node, "nothing in a crowd scene (its people are crowd.agents)");
  return true;
}

}  // namespace

std::span<const Key<scene::Material>> material_keys() {
  static constexpr std::array<Key<scene::Material>, 5> keys{{
      {"name", "non-empty string, unique", "–", "", "What fluid blocks call this material.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Material& material) {
         material.name = values.text(value);
         const auto& earlier = values.scene().materials;
         const auto same_name = [&](const scene::Material& other) { return other.name == material.name; };
         if (std::any_of(earlier.begin(), earlier.end(), same_name))
           values.fail(value, "a name no earlier material has");
       }},
      {"rest_density", "number > 0", "kg/m³", "`1000`", "Density ρ₀ at zero pressure.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Material& material) {
         material.rest_density = values.number(value, positive);
       }},
      {"kinematic_viscosity", "number ≥ 0", "m²/s", "`0`", "ν, used by the laminar viscosity (water: 1e-6).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Material& material) {
         material.kinematic_viscosity = values.number(value, non_negative);
       }},
      // Either given or derived from the expected maximum speed, never both (read_materials).
      {"sound_speed", "number > 0", "m/s", "–", "The artificial speed of sound c₀, given directly.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Material& material) {
         material.sound_speed = values.number(value, positive);
       }},
      {"max_speed", "number > 0", "m/s", "–",
       "The largest speed you expect; c₀ = 10 × `max_speed` (Mach 0.1, density varies by about 1%). For a dam "
       "break of height H, sqrt(2 g H) is a good value.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Material& material) {
         material.max_speed = values.number(value, positive);
       }},
  }};
  return keys;
}

void read_materials(const ValueReader& values, const Node& node, scene::Scene& scene) {
  if (refused_in_crowd(values, node, scene)) return;
  for (const Node& entry : values.elements(node, 1, "a non-empty array of materials")) {
    scene::Material material;
    read_section(values, entry, material_keys(), material);
    if (material.sound_speed.has_value() == material.max_speed.has_value()) {
      values.fail(entry.path, "exactly one of \"sound_speed\" and \"max_speed\"",
                  material.sound_speed ? "both" : "neither");
    }
    scene.materials.push_back(std::move(material));
  }
}

std::span<const Key<scene::TaylorGreenVelocity>> taylor_green_keys() {
  static constexpr std::array<Key<scene::TaylorGreenVelocity>, 2> keys{{
      {"amplitude", "number > 0", "m/s", "`1`", "U of u = −U cos(2πx/L) sin(2πy/L), v = U sin(2πx/L) cos(2πy/L).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::TaylorGreenVelocity& field) {
         field.amplitude = values.number(value, positive);
       }},
      {"length", "number > 0", "m", "`1`", "L, the side of the periodic square [0, L)² of the vortex.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::TaylorGreenVelocity& field) {
         field.length = values.number(value, positive);
       }},
  }};
  return keys;
}

std::span<const Key<scene::RigidRotation>> rotation_keys() {
  static constexpr std::array<Key<scene::RigidRotation>, 2> keys{{
      {"centre", "vector", "m", "", "The centre of rotation (x_c, y_c).", Presence::required,
       [](const ValueReader& values, const Node& value, scene::RigidRotation& rotation) {
         rotation.centre = values.vector(value);
       }},
      {"angular_velocity", "number", "rad/s", "`1`",
       "ω of u = −ω (y − y_c), v = ω (x − x_c), positive counter-clockwise.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::RigidRotation& rotation) {
         rotation.angular_velocity = values.number(value, any_number);
       }},
  }};
  return keys;
}

namespace {

/// A uniform velocity [vx, vy(, vz)] or a named field: {"taylor_green": {...}} or
/// {"rotation": {...}}, both two-dimensional.
void read_initial_velocity(const ValueReader& values, const Node& node, scene::FluidBlock& block) {
  if (node.value->is_array()) {
    block.velocity = values.vector(node);
    return;
  }
  const std::string expected = "a velocity array of " + std::to_string(values.dimension()) +
                               " numbers, {\"taylor_green\": {...}} or {\"rotation\": {...}}";
  if (!node.value->is_object()) values.fail(node, expected);
  static constexpr std::array<std::string_view, 2> fields{"taylor_green", "rotation"};
  values.expect_object(node, fields);
  if (node.value->size() != 1) values.fail(node, expected);
  if (const Node field = child(node, "rotation"); field.present()) {
    if (values.dimension() != 2) values.fail(field, "a 2D scene (the rotation field turns about the z axis)");
    scene::RigidRotation rotation;
    read_section(values, field, rotation_keys(), rotation);
    block.velocity = rotation;
    return;
  }
  const Node field = child(node, "taylor_green");
  if (values.dimension() != 2) values.fail(field, "a 2D scene (the Taylor-Green field is two-dimensional)");
  scene::TaylorGreenVelocity taylor_green;
  read_section(values, field, taylor_green_keys(), taylor_green);
  block.velocity = taylor_green;
}

}  // namespace

std::span<const Key<scene::FluidBlock>> fluid_block_keys() {
  static constexpr std::array<Key<scene::FluidBlock>, 4> keys{{
      {"material", "string", "–", "", "Name of one of `materials`.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::FluidBlock& block) {
         block.material = values.material_index(value, values.scene().materials);
       }},
      // Exactly one shape key (read_fluid).
      {"box", "[box](#box)", "–", "–", "Fill this box."},
      {"ball", "[ball](#ball)", "–", "–", "Fill this ball (a disc in 2D)."},
      {"velocity", "vector, `{\"taylor_green\": {...}}` or `{\"rotation\": {...}}`", "m/s", "`[0, 0(, 0)]`",
       "Initial velocity: uniform, the Taylor–Green vortex field or a rigid rotation (both 2D only).",
       Presence::optional, read_initial_velocity},
  }};
  return keys;
}

void read_fluid(const ValueReader& values, const Node& node, scene::Scene& scene) {
  if (refused_in_crowd(values, node, scene)) return;
  for (const Node& entry : values.elements(node, 1, "a non-empty array of fluid blocks")) {
    scene::FluidBlock block;
    read_section(values, entry, fluid_block_keys(), block);
    if (shape_key(values, entry, {"box", "ball"}) == "box") {
      block.shape = read_box(values, child(entry, "box"));
    } else {
      block.shape = read_ball(values, child(entry, "ball"));
    }
    scene.fluid.push_back(block);
  }
}

}  // namespace tide::io
