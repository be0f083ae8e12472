#pragma once

// A rigid body moved by the fluid, in the scene model: what an obstacle needs, besides its shape,
// to move under the fluid's forces and gravity instead of a prescribed motion (scene_motion.hpp).
// docs/bodies.md gives the keys; solvers/include/tide/solvers/rigid_body.hpp integrates them.

#include <array>
#include <optional>

namespace tide::scene {

/// What a body may not do. A 2D body always turns about z and stays in the plane.
struct BodyConstraints {
  std::array<bool, 3> locked_translation{};            // per axis: the centre of mass does not move along it
  bool locked_rotation = false;                        // the body does not turn
  std::optional<std::array<double, 3>> rotation_axis;  // unit vector: the body turns about it only
  std::optional<std::array<double, 3>> pivot;          // a point fixed in the body and in space: the body turns about
                                                       // it (with rotation_axis, a hinge) and does not translate
};

/// A body of uniform density: its mass, centre of mass and inertia come from its shape.
struct Body {
  double density = 0;  // kg/m³
  BodyConstraints constraints;
  double release_time = 0;                // s: held where it starts, at rest, in the steps that begin before this time
  std::array<double, 3> applied_force{};  // N (2D: N per metre of depth), constant, at the centre of mass
};

/// How bodies touch one another and the walls: a spring and dashpot along the line between two
/// solid particles closer than a particle spacing, with Coulomb friction across it
/// (solvers/include/tide/solvers/body_contacts.hpp).
struct BodyContact {
  double restitution = 0.2;         // normal speed after an impact / before (0 < e <= 1)
  double friction = 0.5;            // Coulomb coefficient μ: the tangential force is at most μ × the normal one
  std::optional<double> frequency;  // rad/s of a particle pair's spring; unset: 0.2 / the acoustic time step
};

}  // namespace tide::scene
