#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "tide/core/scene_body.hpp"
#include "tide/solvers/mass_properties.hpp"

namespace tide {

/// One rigid body's motion under a force and a torque (Newton–Euler), in double precision and on
/// one thread, so that it is the same for any thread count. The body turns about its reference
/// point o: its centre of mass, or the pivot of its constraints. It keeps the angular momentum
/// about o, L = I_o ω with I_o = R I_o,start Rᵀ (R: the orientation, a unit quaternion), so a
/// torque-free body keeps L exactly.
///
/// Stepping is velocity Verlet, split like the fluid's: kick(F, τ, dt/2) adds the impulse of half
/// a step, drift(dt) moves the body with the velocities of mid-step, kick again with the forces at
/// the new pose. The rotation of a drift is exp(ω* dt) with ω* the angular velocity of L at the
/// half-turned orientation (implicit midpoint, a fixed number of iterations), second order and
/// exact for a body that turns about a principal axis.
///
/// Constraints: locked axes of translation keep their velocity at zero and ignore the force
/// along them; a locked rotation keeps ω = 0; a rotation axis n keeps ω along n (L is projected
/// on n, ω = n (n·L)/(nᵀ I_o n)); a pivot locks all translation. A 2D body turns about z only.
class RigidBody {
 public:
  RigidBody(const MassProperties& properties, const scene::BodyConstraints& constraints, int dimension);

  /// Adds dt × the force and the torque about the reference point (gravity included by the
  /// caller; body_gravity gives its force and torque), respecting the constraints.
  void kick(const Eigen::Vector3d& force, const Eigen::Vector3d& torque, double dt);
  /// Moves the body by dt with its present velocities.
  void drift(double dt);

  /// Gravity's force on the body and its torque about the reference point.
  Eigen::Vector3d gravity_force(const Eigen::Vector3d& g) const { return properties_.mass * g; }
  Eigen::Vector3d gravity_torque(const Eigen::Vector3d& g) const {
    return (centre() - reference_).cross(gravity_force(g));
  }

  /// Where a point of the body that started at `start` is, and its velocity and acceleration
  /// (the acceleration of the last kick: a = A + α × r + ω × (ω × r)).
  struct Point {
    Eigen::Vector3d position, velocity, acceleration;
  };
  /// The body's motion at this moment, with ω worked out once (a solve in 3D), for the many
  /// points of its particles.
  struct Kinematics {
    Eigen::Vector3d start_reference, reference;
    Eigen::Quaterniond orientation;
    Eigen::Vector3d velocity, acceleration, angular_velocity, angular_acceleration;
    /// r = R (x0 − o0): the lever from the reference point of the point that started at `start`.
    Eigen::Vector3d lever(const Eigen::Vector3d& start) const { return orientation * (start - start_reference); }
    Point point(const Eigen::Vector3d& start) const;
  };
  Kinematics kinematics() const;
  Point point(const Eigen::Vector3d& start) const { return kinematics().point(start); }

  const MassProperties& mass_properties() const { return properties_; }
  Eigen::Vector3d centre() const { return point(properties_.centre).position; }
  const Eigen::Vector3d& reference_point() const { return reference_; }
  const Eigen::Quaterniond& orientation() const { return orientation_; }
  const Eigen::Vector3d& velocity() const { return velocity_; }  // of the reference point
  Eigen::Vector3d angular_velocity() const { return angular_velocity_at(orientation_); }
  const Eigen::Vector3d& angular_momentum() const { return angular_momentum_; }  // about the reference point
  /// Translational plus rotational kinetic energy, M v_c²/2 + ω·L/2 about the reference point
  /// (about a pivot, the whole kinetic energy is ω·L/2).
  double kinetic_energy() const;

  /// What changes as the body moves, as numbers (a checkpoint's part): the reference point, the
  /// orientation, the velocity, the angular momentum and the accelerations of the last kick.
  std::vector<double> motion_state() const;
  /// Takes back what motion_state() gave; std::invalid_argument for another count of numbers.
  void restore_motion_state(std::span<const double> state);

 private:
  Eigen::Vector3d angular_velocity_at(const Eigen::Quaterniond& orientation) const;
  Eigen::Vector3d constrained_torque(const Eigen::Vector3d& torque) const;

  MassProperties properties_;  // at the start
  Eigen::Vector3d start_reference_;
  Eigen::Matrix3d start_inertia_;  // about the reference point, at the start
  Eigen::Vector3d translation_mask_ = Eigen::Vector3d::Ones();
  bool rotates_ = true;
  bool has_axis_ = false;
  Eigen::Vector3d axis_ = Eigen::Vector3d::UnitZ();

  Eigen::Vector3d reference_;
  Eigen::Quaterniond orientation_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_momentum_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_acceleration_ = Eigen::Vector3d::Zero();
};

}  // namespace tide
