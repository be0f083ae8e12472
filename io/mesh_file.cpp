#include "mesh_file.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <system_error>

namespace tide::io {
namespace {

// 5 million triangles as binary STL: far beyond what the sampling (every triangle per lattice
// point, mesh_depth.hpp) is meant for, and well inside the memory of a machine that runs scenes.
constexpr std::uintmax_t largest_mesh_bytes = 256u << 20;

}  // namespace

std::string read_file_bytes(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error))
    refuse_mesh(file, "a mesh file",
                std::filesystem::exists(file, error) ? "something other than a regular file" : "no such file");
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error || size > largest_mesh_bytes)
    refuse_mesh(file, "a mesh file of at most 256 MiB",
                error ? "a file whose size cannot be read" : std::to_string(size) + " bytes");
  std::ifstream stream(file, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (!stream.is_open() || stream.bad()) refuse_mesh(file, "a readable mesh file", "a file that cannot be read");
  return bytes;
}

void refuse_mesh(const std::filesystem::path& file, std::string expected, std::string found) {
  throw scene::SceneError(file.string(), "", std::move(expected), std::move(found));
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "\"" + std::string(...).
std::string quoted_text(std::string_view text) {
  std::string result = "\"";
  result += text.substr(0, 40);
  result += '"';
  return result;
}

void add_polygon(scene::TriangleMesh& mesh, const std::vector<std::uint32_t>& corners) {
  for (std::size_t k = 2; k < corners.size(); ++k) mesh.triangles.push_back({corners[0], corners[k - 1], corners[k]});
}

void check_mesh(const std::filesystem::path& file, const scene::TriangleMesh& mesh) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    for (const double x : mesh.vertices[v])
      if (!std::isfinite(x))
        refuse_mesh(file, "finite vertex coordinates", "vertex " + std::to_string(v) + " with a non-finite coordinate");
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const std::uint32_t index : mesh.triangles[t]) {
      if (index >= mesh.vertices.size()) {
        refuse_mesh(file, "vertex indices below the vertex count " + std::to_string(mesh.vertices.size()),
                    "triangle " + std::to_string(t) + " with vertex index " + std::to_string(index));
      }
    }
  }
  if (mesh.triangles.empty()) refuse_mesh(file, "at least one triangle", "none");
}

}  // namespace tide::io
