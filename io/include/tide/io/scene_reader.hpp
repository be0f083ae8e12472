#pragma once

// Scene files (JSON, documented key by key in docs/scenes.md) → the scene model. A scene is
// checked completely before any work starts: every key is known, typed and in range, and the
// geometry leaves the solver something sensible to do. The first problem found is thrown as a
// SceneError that says where it is and what was expected there. Which combinations of settings
// the schemes support is the solvers' to say (tide::check_capabilities).

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "tide/core/scene.hpp"
#include "tide/core/scene_error.hpp"

namespace tide::io {

/// what() reads "dam.json: /solver/cfl: expected a number > 0, got "fast"" (see scene::SceneError).
using SceneError = scene::SceneError;

/// The most particles a scene may imply, counted as the lattice points the particle sampling
/// visits (fluid blocks, container walls, obstacles' bounding boxes): the smaller of 2^31 − 1 and
/// this machine's physical memory over 352 B, the least a particle holds in a run
/// (docs/scenes.md, "Checks"). A scene beyond it is refused before anything is allocated.
std::int64_t largest_particle_count();

/// Reads and checks the scene in `file`; messages name the file as given.
scene::Scene read_scene_file(const std::filesystem::path& file);

/// Checks the scene in `json_text`; `source_name` names it in messages and becomes Scene::source.
/// JSON with // and /* */ comments is accepted.
scene::Scene parse_scene(std::string_view json_text, std::string source_name);

}  // namespace tide::io
