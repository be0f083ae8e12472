#pragma once

// The declarative key tables of the scene format: per section (an object of the scene file), each
// key with its type, unit, default and meaning as docs/scenes.md lists them, and the function that
// reads and validates its value. The reader reads a section from its table (read_section); the
// same tables give the allowed keys in error messages, the key reference in docs/scenes.md and
// the fuzz dictionary (tide/io/scene_key_reference.hpp), so that a new key is one table row.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene_json.hpp"
#include "scene_values.hpp"
#include "tide/core/scene.hpp"

namespace tide::io {

/// optional: read where present, else the model's default stays. required: absent is an error.
/// always: the key's reader decides what absence means (a default derived from other keys).
enum class Presence { optional, required, always };

template <class Target>
struct Key {
  std::string_view name;
  std::string_view type;           // docs: what the value may be
  std::string_view unit;           // docs: SI unit, or "–"
  std::string_view default_value;  // docs: what an absent key means (unused where required)
  std::string_view meaning;        // docs: one line
  Presence presence = Presence::optional;
  // Reads the value into `target`; `values.scene()` holds what the keys before it set (the
  // sections before it in the top-level table, the keys before it in its own section).
  void (*read)(const ValueReader& values, const Node& value, Target& target) = nullptr;
};

/// A key's row in docs/scenes.md, without its reader.
struct KeyDoc {
  std::string_view name, type, unit, default_value, meaning;
  bool required = false;
};

/// A section's table as docs/scenes.md shows it under the marker `<!-- scene keys: NAME -->`.
struct SectionDoc {
  std::string_view name;  // e.g. "solver", "materials[i]", "walls.container"
  std::vector<KeyDoc> keys;
};

template <class Target>
std::vector<std::string_view> key_names(std::span<const Key<Target>> keys) {
  std::vector<std::string_view> names;
  for (const Key<Target>& key : keys) names.push_back(key.name);
  return names;
}

template <class Target>
SectionDoc section_doc(std::string_view name, std::span<const Key<Target>> keys) {
  SectionDoc doc{name, {}};
  for (const Key<Target>& key : keys) {
    doc.keys.push_back(
        {key.name, key.type, key.unit, key.default_value, key.meaning, key.presence == Presence::required});
  }
  return doc;
}

/// Reads the object at `node` into `target`, key by key in table order; a key outside the table
/// is an error that lists the table's keys.
template <class Target>
void read_section(const ValueReader& values, const Node& node, std::span<const Key<Target>> keys, Target& target) {
  values.expect_object(node, key_names(keys));
  for (const Key<Target>& key : keys) {
    const Node value = child(node, key.name);
    if (key.read != nullptr && (value.present() || key.presence != Presence::optional)) key.read(values, value, target);
  }
}

// The tables, one per section; each section's reader (scene_sections.hpp) is built on its table.
std::span<const Key<scene::Scene>> top_level_keys();
std::span<const Key<scene::Scene>> kernel_keys();
std::span<const Key<scene::Material>> material_keys();
std::span<const Key<scene::FluidBlock>> fluid_block_keys();
std::span<const Key<scene::TaylorGreenVelocity>> taylor_green_keys();
std::span<const Key<scene::RigidRotation>> rotation_keys();
std::span<const Key<scene::Box>> box_keys();
std::span<const Key<scene::Ball>> ball_keys();
std::span<const Key<scene::Plane>> plane_keys();
std::span<const Key<scene::Mesh>> mesh_keys();
std::span<const Key<scene::Mesh>> mesh_rotation_keys();
std::span<const Key<scene::Walls>> wall_keys();
std::span<const Key<scene::Container>> container_keys();
std::span<const Key<scene::Obstacle>> obstacle_keys();
std::span<const Key<scene::Rotation>> rotation_motion_keys();
std::span<const Key<scene::Oscillation>> oscillation_keys();
std::span<const Key<scene::FlapOscillation>> flap_keys();
std::span<const Key<scene::MotionTable>> motion_table_keys();
std::span<const Key<scene::Steered>> steered_keys();
std::span<const Key<scene::Body>> body_keys();
/// A rotation axis: 3D scenes give it (any length but zero; it is normalised), 2D scenes turn
/// about z and may not (`refusal_in_2d` says so).
scene::Vec read_rotation_axis(const ValueReader& values, const Node& value, const std::string& refusal_in_2d);
std::span<const Key<scene::BodyConstraints>> body_constraint_keys();
std::span<const Key<scene::BodyContact>> body_contact_keys();
std::span<const Key<scene::Domain>> domain_keys();
std::span<const Key<scene::Inflow>> inflow_keys();
std::span<const Key<scene::Solver>> solver_keys();
std::span<const Key<scene::SurfaceTension>> surface_tension_keys();
std::span<const Key<scene::Time>> time_keys();
std::span<const Key<scene::Output>> output_keys();
std::span<const Key<scene::Recovery>> recovery_keys();
std::span<const Key<scene::Probe>> probe_keys();
std::span<const Key<scene::Crowd>> crowd_keys();
std::span<const Key<scene::AgentGroup>> crowd_agent_keys();
std::span<const Key<scene::CrowdExit>> crowd_exit_keys();
std::span<const Key<scene::DesiredSpeed>> crowd_speed_keys();

/// Every table, in the order docs/scenes.md shows them.
std::vector<SectionDoc> section_docs();

}  // namespace tide::io
