#pragma once

// What the mesh readers (obj_reader.cpp, stl_reader.cpp, ply_reader.cpp) share: the file's bytes,
// the error that names the file, and the checks every reader makes on what it read.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tide/core/scene_error.hpp"
#include "tide/core/triangle_mesh.hpp"

namespace tide::io {

/// The whole file; a SceneError if it cannot be read.
std::string read_file_bytes(const std::filesystem::path& file);

/// A SceneError "FILE: expected EXPECTED, got FOUND".
[[noreturn]] void refuse_mesh(const std::filesystem::path& file, std::string expected, std::string found);

/// `text` (its first 40 characters) in double quotes, for messages.
std::string quoted_text(std::string_view text);

/// Appends a polygon as a fan of triangles from its first vertex.
void add_polygon(scene::TriangleMesh& mesh, const std::vector<std::uint32_t>& corners);

/// Finite coordinates, indices below the vertex count, and at least one triangle.
void check_mesh(const std::filesystem::path& file, const scene::TriangleMesh& mesh);

scene::TriangleMesh read_obj(const std::filesystem::path& file);
scene::TriangleMesh read_stl(const std::filesystem::path& file);
scene::TriangleMesh read_ply(const std::filesystem::path& file);

}  // namespace tide::io
