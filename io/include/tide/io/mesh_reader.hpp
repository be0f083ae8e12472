#pragma once

// Triangle meshes from files, by extension (case-insensitive): .obj (Wavefront, read by
// tinyobjloader), .stl (binary or ASCII) and .ply (ascii or binary_little_endian; vertex x, y, z
// and face vertex_indices). Polygons are split into triangles as fans from their first vertex.
// A file that cannot be read as its format says throws a SceneError naming the file and what is
// wrong (truncated, a count the file cannot hold, a coordinate that is not finite, an index out of
// range); declared counts are checked against the file's size before anything is allocated.

#include <filesystem>

#include "tide/core/scene_error.hpp"
#include "tide/core/triangle_mesh.hpp"

namespace tide::io {

/// The mesh in `file`, as written: no vertex merged, no triangle removed or turned.
scene::TriangleMesh read_mesh_file(const std::filesystem::path& file);

}  // namespace tide::io
