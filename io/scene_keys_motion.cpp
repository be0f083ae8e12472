#include <array>
#include <cmath>
#include <filesystem>
#include <string>

#include "motion_table_file.hpp"
#include "scene_keys.hpp"
#include "scene_sections.hpp"
#include "scene_shapes.hpp"

namespace tide::io {
namespace {

void read_axis(const ValueReader& values, const Node& value, scene::Vec& axis) {
  axis = read_rotation_axis(values, value, "no axis in a 2D scene (2D scenes rotate about z)");
}

}  // namespace

scene::Vec read_rotation_axis(const ValueReader& values, const Node& value, const std::string& refusal_in_2d) {
  if (values.dimension() == 2) values.fail(value, refusal_in_2d);
  const scene::Vec given = values.vector(value);
  const double length = std::hypot(given[0], given[1], given[2]);
  if (!(length > 0) || !std::isfinite(length)) values.fail(value, "a non-zero vector");
  return {given[0] / length, given[1] / length, given[2] / length};
}

std::span<const Key<scene::Rotation>> rotation_motion_keys() {
  static constexpr std::array<Key<scene::Rotation>, 4> keys{{
      {"centre", "vector", "m", "", "A point of the rotation axis.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Rotation& rotation) {
         rotation.centre = values.vector(value);
       }},
      {"axis", "vector (3D only)", "–", "`[0, 0, 1]`", "The rotation axis (normalised).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Rotation& rotation) {
         read_axis(values, value, rotation.axis);
       }},
      {"angular_velocity", "number", "rad/s", "", "ω0, positive counter-clockwise about the axis.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Rotation& rotation) {
         rotation.angular_velocity = values.number(value, any_number);
       }},
      {"ramp_time", "number ≥ 0", "s", "`0`",
       "Time over which ω rises from 0 to ω0 as ω0 (1 − cos(π t / ramp_time)) / 2.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Rotation& rotation) {
         rotation.ramp_time = values.number(value, non_negative);
       }},
  }};
  return keys;
}

std::span<const Key<scene::Oscillation>> oscillation_keys() {
  static constexpr std::array<Key<scene::Oscillation>, 3> keys{{
      {"amplitude", "vector", "m", "", "A of the displacement d(t) = A (sin(2π f t + φ) − sin φ).", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Oscillation& oscillation) {
         oscillation.amplitude = values.vector(value);
       }},
      {"frequency", "number > 0", "Hz", "", "f.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Oscillation& oscillation) {
         oscillation.frequency = values.number(value, positive);
       }},
      {"phase", "number", "rad", "`0`", "φ; −π/2 starts at rest.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Oscillation& oscillation) {
         oscillation.phase = values.number(value, any_number);
       }},
  }};
  return keys;
}

std::span<const Key<scene::FlapOscillation>> flap_keys() {
  static constexpr std::array<Key<scene::FlapOscillation>, 5> keys{{
      {"hinge", "vector", "m", "", "A point of the hinge axis.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::FlapOscillation& flap) {
         flap.hinge = values.vector(value);
       }},
      {"axis", "vector (3D only)", "–", "`[0, 0, 1]`", "The hinge axis (normalised).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::FlapOscillation& flap) {
         read_axis(values, value, flap.axis);
       }},
      {"amplitude", "number", "rad", "", "θA of the angle θ(t) = θA (sin(2π f t + φ) − sin φ).", Presence::required,
       [](const ValueReader& values, const Node& value, scene::FlapOscillation& flap) {
         flap.amplitude = values.number(value, any_number);
       }},
      {"frequency", "number > 0", "Hz", "", "f.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::FlapOscillation& flap) {
         flap.frequency = values.number(value, positive);
       }},
      {"phase", "number", "rad", "`0`", "φ; −π/2 starts at rest.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::FlapOscillation& flap) {
         flap.phase = values.number(value, any_number);
       }},
  }};
  return keys;
}

std::span<const Key<scene::MotionTable>> motion_table_keys() {
  static constexpr std::array<Key<scene::MotionTable>, 3> keys{{
      {"centre", "vector", "m", "zero", "A point of the rotation axis at the start; it moves with the displacement.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::MotionTable& table) {
         table.centre = values.vector(value);
       }},
      {"axis", "vector (3D only)", "–", "`[0, 0, 1]`", "The rotation axis (normalised).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::MotionTable& table) {
         read_axis(values, value, table.axis);
       }},
      {"file", "string", "–", "",
       "CSV file, relative to the scene file: a header line, then rows `time, x, y[, z], angle` (s, m, rad) from "
       "time 0 with no displacement and angle; linear between rows, held after the last.",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::MotionTable& table) {
         const std::string file = values.text(value);
         const std::filesystem::path path = std::filesystem::path(values.file()).parent_path() / file;
         try {
           table.samples = read_motion_table(path, values.dimension());
         } catch (const MotionTableError& error) {
           values.fail(value.path, "a motion table (docs/bodies.md)", path.string() + ": " + error.what());
         }
         table.file = path.string();
       }},
  }};
  return keys;
}

std::span<const Key<scene::Steered>> steered_keys() {
  static constexpr std::array<Key<scene::Steered>, 1> keys{{
      {"max_speed", "number > 0", "m/s", "`1`", "The fastest the solid follows where it is steered.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Steered& steered) {
         steered.max_speed = values.number(value, positive);
       }},
  }};
  return keys;
}

scene::Motion read_motion(const ValueReader& values, const Node& node) {
  values.expect_object(node, std::array<std::string_view, 5>{"rotation", "oscillation", "flap", "table", "steered"});
  const std::string_view law =
      one_key_of(values, node, {"rotation", "oscillation", "flap", "table", "steered"}, "motion key");
  const Node value = child(node, law);
  if (law == "rotation") {
    scene::Rotation rotation;
    read_section(values, value, rotation_motion_keys(), rotation);
    return rotation;
  }
  if (law == "oscillation") {
    scene::Oscillation oscillation;
    read_section(values, value, oscillation_keys(), oscillation);
    return oscillation;
  }
  if (law == "flap") {
    scene::FlapOscillation flap;
    read_section(values, value, flap_keys(), flap);
    return flap;
  }
  if (law == "steered") {
    scene::Steered steered;
    read_section(values, value, steered_keys(), steered);
    return steered;
  }
  scene::MotionTable table;
  read_section(values, value, motion_table_keys(), table);
  return table;
}

}  // namespace tide::io
