#pragma once

// A scene as the Python module holds it: the checked scene and what a checkpoint of its runs is
// written for (io::CheckpointIdentity), from a scene file or from JSON text (a Python dict).

#include <filesystem>
#include <string>
#include <string_view>

#include "tide/core/scene.hpp"
#include "tide/io/checkpoint_file.hpp"

namespace tide::python {

struct SceneSource {
  scene::Scene scene;
  /// A checkpoint's identity for a run of this scene: for a file the one `tide run` gives it, so
  /// that a run directory's checkpoint.h5 can be restored; for JSON text, the hash of the text.
  io::CheckpointIdentity identity;
};

/// Reads and checks a scene file (io::SceneError names the file and key path).
SceneSource scene_from_file(const std::filesystem::path& file);

/// Checks a scene given as JSON text; `name` stands for the file in messages.
SceneSource scene_from_text(std::string_view json_text, const std::string& name);

}  // namespace tide::python
