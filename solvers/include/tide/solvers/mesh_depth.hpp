#pragma once

// How deep a point lies inside a mesh obstacle (scene::Mesh, closed and oriented outward by the
// scene reader), for the particle sampling (particle_sampling.hpp): the distance to the surface
// for a point inside; a negative number, not a distance, for a point outside.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>

#include "tide/core/scene.hpp"

namespace tide {

/// 3D. Inside where the generalised winding number (Jacobson, Kavan & Sorkine-Hornung 2013), the
/// sum of the triangles' solid angles (Van Oosterom & Strackee 1983) over 4π, rounds to an odd
/// integer: no ray to fall on an edge, and a cavity (an inner shell) counts as outside.
double depth_in_mesh(const scene::Mesh& mesh, const std::array<double, 3>& p);

/// 2D: the same for the mesh's section by the plane z = 0, a set of closed outlines. Inside by
/// the crossing number of a ray along +x (Shimrat 1962, with half-open edges so that a ray
/// through an outline's corner counts it once), the depth being the distance to the outlines.
double depth_in_mesh_section(const scene::Mesh& mesh, double x, double y);

/// The segment triangle t of `mesh` cuts from the plane z = 0, none where it does not cross it (a
/// vertex at z = 0 counts as above the plane). The two triangles that share an edge get the same
/// point on it, bit for bit, so the segments of a closed mesh join into closed outlines.
std::optional<std::array<Eigen::Vector2d, 2>> triangle_section(const scene::TriangleMesh& mesh,
                                                               const std::array<std::uint32_t, 3>& t);

}  // namespace tide
