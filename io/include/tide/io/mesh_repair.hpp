#pragma once

// Makes a mesh read from a file (mesh_reader.hpp) a closed, consistently oriented surface, or
// refuses it (docs/bodies.md, "Meshes"). Repairs, where the result is unambiguous:
//   1. vertices with exactly equal coordinates become one (STL stores every triangle's corners);
//   2. degenerate triangles go: a repeated vertex, or a cross product of its edges exactly zero;
//   3. triangles are turned to agree with their neighbours across shared edges (each edge walked
//      in opposite directions by its two triangles), component by component in triangle order,
//      and a component whose signed volume is negative is turned inside out (outward normals).
// Refused with the file, the triangle index and the reason: an edge of only one triangle (an
// open mesh), an edge of more than two (non-manifold), a component that cannot be oriented.

#include <cstddef>
#include <filesystem>

#include "tide/core/scene_error.hpp"
#include "tide/core/triangle_mesh.hpp"

namespace tide::io {

/// What repair_mesh changed.
struct MeshRepairs {
  std::size_t merged_vertices = 0;
  std::size_t removed_triangles = 0;
  std::size_t turned_triangles = 0;
};

/// Repairs `mesh` in place; `file` names it in a refusal.
MeshRepairs repair_mesh(scene::TriangleMesh& mesh, const std::filesystem::path& file);

/// The signed volume the surface encloses, Σ det(a, b, c) / 6 over its triangles (divergence
/// theorem); positive for outward normals.
double signed_volume(const scene::TriangleMesh& mesh);

}  // namespace tide::io
