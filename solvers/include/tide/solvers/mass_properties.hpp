#pragma once

#include <Eigen/Core>

#include "tide/core/scene.hpp"

namespace tide {

/// Mass, centre of mass and inertia tensor of a solid of uniform density, in the scene's axes.
/// In 2D the solid is the shape's section by z = 0, extruded one metre: the mass is per metre of
/// depth, and only the inertia about z (inertia(2, 2)) has a meaning; the rest is zero.
struct MassProperties {
  double mass = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centre of mass
};

/// An axis-aligned box: m = ρ V, I_xx = m (b² + c²) / 12 for edges a, b, c along x, y, z.
MassProperties mass_properties(const scene::Box& box, double density, int dimension);

/// A ball (3D: I = 2/5 m r²) or a disc (2D: I_zz = 1/2 m r²).
MassProperties mass_properties(const scene::Ball& ball, double density, int dimension);

/// A closed mesh oriented outward (scene::Mesh as the scene reader places it), exact for the
/// polyhedron (3D) or for its section by z = 0 (2D), by the divergence theorem: the signed
/// tetrahedra from the origin to each triangle (Tonon 2004, J. Math. Stat. 1, 8), or the signed
/// triangles from the origin to each edge of the section's outlines (Green's theorem).
MassProperties mass_properties(const scene::Mesh& mesh, double density, int dimension);

/// Inertia about `point` from the inertia about the centre of mass (parallel axis theorem):
/// I_p = I_c + m (|d|² 1 − d dᵀ), d = c − p.
Eigen::Matrix3d inertia_about(const MassProperties& properties, const Eigen::Vector3d& point);

}  // namespace tide
