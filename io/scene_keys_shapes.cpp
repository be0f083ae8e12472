#include <algorithm>
#include <array>
#include <iterator>
#include <vector>

#include "scene_keys.hpp"
#include "scene_shapes.hpp"
#include "scene_text.hpp"

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
