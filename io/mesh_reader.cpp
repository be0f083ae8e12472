#include "tide/io/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "mesh_file.hpp"

namespace tide::io {

scene::TriangleMesh read_mesh_file(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  scene::TriangleMesh mesh;
  if (extension == ".obj") {
    mesh = read_obj(file);
  } else if (extension == ".stl") {
    mesh = read_stl(file);
  } else if (extension == ".ply") {
    mesh = read_ply(file);
  } else {
    refuse_mesh(file, "a mesh file ending in .obj, .stl or .ply",
                extension.empty() ? "no extension" : "the extension \"" + extension + "\"");
  }
  check_mesh(file, mesh);
  return mesh;
}

}  // namespace tide::io
