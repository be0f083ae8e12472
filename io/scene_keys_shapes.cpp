#include <algorithm>
#include <array>
#include <filesystem>
#include <iterator>
#include <memory>
#include <vector>

#include "scene_keys.hpp"
#include "scene_shapes.hpp"
#include "scene_text.hpp"
#include "tide/io/mesh_placement.hpp"
#include "tide/io/mesh_reader.hpp"
#include "tide/io/mesh_repair.hpp"

namespace tide::io {

void read_min_corner(const ValueReader& values, const Node& node, scene::Box& box) { box.min = values.vector(node); }

void read_max_corner(const ValueReader& values, const Node& node, scene::Box& box) {
  box.max = values.vector(node);
  for (int d = 0; d < values.dimension(); ++d) {
    if (!(box.max[d] > box.min[d]))
      values.fail(element(node, d), "a number > min" + axis_index(d) + " (" + format_number(box.min[d]) + ")");
  }
}

std::span<const Key<scene::Box>> box_keys() {
  static constexpr std::array<Key<scene::Box>, 2> keys{{
      {"min", "vector", "m", "", "Low corner.", Presence::required, read_min_corner},
      {"max", "vector", "m", "", "High corner; `max` > `min` on every axis.", Presence::required, read_max_corner},
  }};
  return keys;
}

std::span<const Key<scene::Ball>> ball_keys() {
  static constexpr std::array<Key<scene::Ball>, 2> keys{{
      {"centre", "vector", "m", "", "Centre.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Ball& ball) { ball.centre = values.vector(value); }},
      {"radius", "number > 0", "m", "", "Radius; a ball in 3D, a disc in 2D.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Ball& ball) {
         ball.radius = values.number(value, positive);
       }},
  }};
  return keys;
}

std::span<const Key<scene::Plane>> plane_keys() {
  static constexpr std::array<Key<scene::Plane>, 2> keys{{
      {"point", "vector", "m", "", "A point of the wall surface.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Plane& plane) { plane.point = values.vector(value); }},
      {"normal", "non-zero vector", "–", "",
       "The solid lies on the side opposite the normal (the normal points into the fluid). Obstacles only.",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::Plane& plane) {
         plane.normal = values.vector(value);
         if (plane.normal == scene::Vec{}) values.fail(value, "a non-zero vector");
       }},
  }};
  return keys;
}

// Three numbers whatever the scene's dimension: a mesh is placed in 3D, and a 2D scene takes its
// section by z = 0.
scene::Vec three_numbers(const ValueReader& values, const Node& node) {
  const std::vector<Node> numbers = values.elements(node, 3, "an array of 3 numbers");
  if (numbers.size() != 3) values.fail(node, "an array of 3 numbers");
  return {values.number(numbers[0], any_number), values.number(numbers[1], any_number),
          values.number(numbers[2], any_number)};
}

std::span<const Key<scene::Mesh>> mesh_keys() {
  static constexpr std::array<Key<scene::Mesh>, 5> keys{{
      {"file", "string", "–", "",
       "A closed triangle mesh, `.obj`, `.stl` (binary or ASCII) or `.ply` (ascii or binary_little_endian), "
       "relative to the scene file's directory.",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::Mesh& mesh) { mesh.file = values.text(value); }},
      {"scale", "number > 0", "–", "1", "Factor on the file's coordinates, applied first.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Mesh& mesh) {
         mesh.scale = values.number(value, positive);
       }},
      {"units", "string: `\"m\"`, `\"cm\"` or `\"mm\"`", "–", "`\"m\"`", "The file's length unit.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Mesh& mesh) {
         mesh.units = values.choice(value, mesh_unit_names);
       }},
      {"rotation", "[mesh.rotation](#meshrotation)", "–", "none",
       "A rotation about an axis through the origin of the file's coordinates, after scaling.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Mesh& mesh) {
         read_section(values, value, mesh_rotation_keys(), mesh);
       }},
      {"translation", "3 numbers", "m", "`[0, 0, 0]`", "Added last, after scaling and rotating.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Mesh& mesh) {
         mesh.translation = three_numbers(values, value);
       }},
  }};
  return keys;
}

std::span<const Key<scene::Mesh>> mesh_rotation_keys() {
  static constexpr std::array<Key<scene::Mesh>, 2> keys{{
      {"axis", "3 non-zero numbers", "–", "`[0, 0, 1]`", "The rotation axis (any length).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Mesh& mesh) {
         mesh.axis = three_numbers(values, value);
         if (mesh.axis == scene::Vec{}) values.fail(value, "a non-zero vector");
       }},
      {"degrees", "number", "°", "0", "The angle, counter-clockwise about `axis` (right-hand rule).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Mesh& mesh) {
         mesh.degrees = values.number(value, any_number);
       }},
  }};
  return keys;
}

scene::Box read_box(const ValueReader& values, const Node& node) {
  scene::Box box;
  read_section(values, node, box_keys(), box);
  return box;
}

scene::Ball read_ball(const ValueReader& values, const Node& node) {
  scene::Ball ball;
  read_section(values, node, ball_keys(), ball);
  return ball;
}

scene::Plane read_plane(const ValueReader& values, const Node& node) {
  scene::Plane plane;
  read_section(values, node, plane_keys(), plane);
  return plane;
}

scene::Mesh read_mesh(const ValueReader& values, const Node& node) {
  scene::Mesh mesh;
  read_section(values, node, mesh_keys(), mesh);
  const std::filesystem::path file = std::filesystem::path(values.file()).parent_path() / mesh.file;
  try {
    auto surface = std::make_shared<scene::TriangleMesh>(read_mesh_file(file));
    repair_mesh(*surface, file);
    place_mesh(*surface, mesh);
    mesh.bounds = mesh_bounds(*surface);
    mesh.surface = std::move(surface);
  } catch (const scene::SceneError& error) {
    values.fail(child(node, "file").path, "a closed triangle mesh file", error.what());
  }
  return mesh;
}

std::string_view one_key_of(const ValueReader& values, const Node& object, std::initializer_list<std::string_view> keys,
                            std::string_view what) {
  std::vector<std::string_view> given;
  std::copy_if(keys.begin(), keys.end(), std::back_inserter(given),
               [&](std::string_view key) { return child(object, key).present(); });
  if (given.size() != 1) {
    values.fail(object.path, "exactly one " + std::string(what) + " of " + quoted_list(keys),
                given.empty() ? "none" : quoted_list(given));
  }
  return given.front();
}

std::string_view shape_key(const ValueReader& values, const Node& object,
                           std::initializer_list<std::string_view> shapes) {
  return one_key_of(values, object, shapes, "shape key");
}

}  // namespace tide::io
