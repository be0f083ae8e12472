#pragma once

// What a tidesph function that takes a scene accepts: a Scene, a dict, or a file path.

#include <string>

#include <pybind11/pybind11.h>

#include "scene_source.hpp"

namespace tide::python {

/// Checks a scene given as a dict; `name` stands for its file in messages.
SceneSource scene_from_dict(const pybind11::dict& scene, const std::string& name);

/// A Scene as it is, a dict through scene_from_dict, anything else as a path (str, os.PathLike).
SceneSource scene_argument(const pybind11::object& scene);

}  // namespace tide::python
