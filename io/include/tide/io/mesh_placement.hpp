#pragma once

// Places a mesh in the scene (docs/bodies.md, "Meshes"): each vertex x of the file becomes
//   R (scale × units × x) + translation,
// R the rotation by `degrees` counter-clockwise about `axis` through the file's origin
// (Rodrigues' formula). Scale first, then rotate, then translate.

#include "tide/core/scene.hpp"
#include "tide/core/triangle_mesh.hpp"

namespace tide::io {

/// Moves `mesh`'s vertices from file coordinates to the scene's metres as `placement` says.
void place_mesh(scene::TriangleMesh& mesh, const scene::Mesh& placement);

/// The smallest box holding every vertex.
scene::Box mesh_bounds(const scene::TriangleMesh& mesh);

}  // namespace tide::io
