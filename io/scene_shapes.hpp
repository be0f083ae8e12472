#pragma once

// Reading the shapes of a scene (boxes, balls, planes, meshes) and the corners of the boxes that are
// sections of their own (the domain, the container).

#include <initializer_list>
#include <string_view>

#include "scene_json.hpp"
#include "scene_values.hpp"
#include "tide/core/scene.hpp"

namespace tide::io {

scene::Box read_box(const ValueReader& values, const Node& node);
scene::Ball read_ball(const ValueReader& values, const Node& node);
scene::Plane read_plane(const ValueReader& values, const Node& node);

/// A mesh's keys, then its file (relative to the scene file's directory) read, repaired and
/// placed: a mesh the scene cannot use fails at the "file" key, naming the mesh file and why.
scene::Mesh read_mesh(const ValueReader& values, const Node& node);

/// A box's "min" corner, read before its "max".
void read_min_corner(const ValueReader& values, const Node& node, scene::Box& box);

/// A box's "max" corner: above "min" on every axis.
void read_max_corner(const ValueReader& values, const Node& node, scene::Box& box);

/// The one key of `object` among `keys`; otherwise an error expecting "exactly one <what> of ...".
std::string_view one_key_of(const ValueReader& values, const Node& object, std::initializer_list<std::string_view> keys,
                            std::string_view what);

/// The one key of `object` among `shapes`.
std::string_view shape_key(const ValueReader& values, const Node& object,
                           std::initializer_list<std::string_view> shapes);

}  // namespace tide::io
