// Wavefront OBJ through Debian's tinyobjloader (libtinyobjloader-dev), its header compiled here
// alone with double coordinates. Materials (.mtl) are not read: only the geometry matters.
#define TINYOBJLOADER_USE_DOUBLE
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include <string>
#include <vector>

#include "mesh_file.hpp"

namespace tide::io {

scene::TriangleMesh read_obj(const std::filesystem::path& file) {
  const std::string text = read_file_bytes(file);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // fans from the first vertex, as for STL and PLY (add_polygon)
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) {
    const std::string& error = reader.Error();
    refuse_mesh(file, "a Wavefront OBJ file", error.empty() ? "text tinyobjloader cannot read" : error);
  }
  const std::vector<double>& coordinates = reader.GetAttrib().vertices;
  scene::TriangleMesh mesh;
  mesh.vertices.reserve(coordinates.size() / 3);
  for (std::size_t v = 0; v + 2 < coordinates.size(); v += 3)
    mesh.vertices.push_back({coordinates[v], coordinates[v + 1], coordinates[v + 2]});
  std::vector<std::uint32_t> corners;
  std::size_t face = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t next = 0;
    for (const unsigned int count : shape.mesh.num_face_vertices) {
      corners.clear();
      for (unsigned int k = 0; k < count; ++k) {
        const int index = shape.mesh.indices[next++].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= mesh.vertices.size()) {
          refuse_mesh(file, "face vertex indices from 1 to the vertex count " + std::to_string(mesh.vertices.size()),
                      "face " + std::to_string(face) + " naming vertex " + std::to_string(index + 1));
        }
        corners.push_back(static_cast<std::uint32_t>(index));
      }
      add_polygon(mesh, corners);
      ++face;
    }
  }
  return mesh;
}

}  // namespace tide::io
