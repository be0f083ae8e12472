#pragma once

#include <Eigen/Core>

#include "tide/core/scene_motion.hpp"

namespace tide {

/// A scene vector (scene::Vec, double) as an Eigen vector, for the rigid-solid arithmetic.
inline Eigen::Vector3d to_eigen(const scene::Vec& v) { return {v[0], v[1], v[2]}; }

/// A rigid solid's pose at one time and its rates: displaced by `displacement` from where the
/// scene puts it and turned by `angle` about `axis` through the displaced centre, so a point that
/// starts at x0 is at x = c + d + R(θ)(x0 − c). All in double: the motion is evaluated from the
/// start each step, so poses carry no error from step to step.
struct RigidPose {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // c, where the scene puts the axis
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   // n, unit
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // of the displacement, ḋ
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // d̈
  double angle = 0;                                        // θ
  double angular_velocity = 0;                             // ω = θ̇
  double angular_acceleration = 0;                         // α = θ̈

  /// Where the point that started at `start` is, and its velocity and acceleration:
  /// with r = R(θ)(x0 − c), x = c + d + r, v = ḋ + ω n × r, a = d̈ + α n × r + ω² (n (n·r) − r).
  struct Point {
    Eigen::Vector3d position, velocity, acceleration;
  };
  Point point(const Eigen::Vector3d& start) const;
};

/// The pose of `motion` at τ = t − time.start (scene_motion.hpp gives each motion's law).
RigidPose pose_at(const scene::Motion& motion, double tau);

}  // namespace tide
