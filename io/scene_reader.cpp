#include "tide/io/scene_reader.hpp"

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <system_error>
#include <utility>

#include "geometry_checks.hpp"
#include "scene_json.hpp"
#include "scene_keys.hpp"
#include "scene_values.hpp"

namespace tide::io {

// The keys first, section by section from their tables (scene_keys_*.cpp), then the geometry
// (geometry_checks.hpp), the particle count before anything is sampled.
scene::Scene parse_scene(std::string_view json_text, std::string source_name) {
  const nlohmann::json document = parse_json(json_text, source_name);
  scene::Scene scene;
  scene.source = source_name;
  const ValueReader values(std::move(source_name), scene);
  read_section(values, Node{&document, ""}, top_level_keys(), scene);
  check_container_in_domain(scene);
  check_mesh_placement(scene);
  check_fluid_placement(scene);
  check_fluid_lattice_points(scene);
  check_particle_count(scene);
  return scene;
}

scene::Scene read_scene_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    const char* found = !std::filesystem::exists(file, error)        ? "no such file"
                        : std::filesystem::is_directory(file, error) ? "a directory"
                                                                     : "something other than a regular file";
    throw SceneError(name, "", "a scene file", found);
  }
  std::ifstream stream(file, std::ios::binary);
  const std::string contents{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (!stream.is_open() || stream.bad())
    throw SceneError(name, "", "a readable scene file", "a file that cannot be read");
  return parse_scene(contents, name);
}

}  // namespace tide::io
