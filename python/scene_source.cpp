#include "scene_source.hpp"

#include "tide/core/config.hpp"
#include "tide/io/scene_reader.hpp"

namespace tide::python {

SceneSource scene_from_file(const std::filesystem::path& file) {
  scene::Scene scene = io::read_scene_file(file);
  io::CheckpointIdentity identity = io::checkpoint_identity(file, scene.dimension);
  return {std::move(scene), std::move(identity)};
}

SceneSource scene_from_text(std::string_view json_text, const std::string& name) {
  scene::Scene scene = io::parse_scene(json_text, name);
  io::CheckpointIdentity identity{
      io::checkpoint_format_version, io::scene_text_hash(json_text), TIDE_REAL_NAME, scene.dimension, {}};
  return {std::move(scene), std::move(identity)};
}

}  // namespace tide::python
