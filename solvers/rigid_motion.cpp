#include "tide/solvers/rigid_motion.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <type_traits>
#include <variant>

namespace tide {
namespace {

RigidPose rotating_about(const scene::Vec& centre, const scene::Vec& axis) {
  RigidPose pose;
  pose.centre = to_eigen(centre);
  pose.axis = to_eigen(axis);
  return pose;
}

// θ, ω, α of ω(τ) = ω0 (1 − cos(π τ / T)) / 2 for τ < T and ω0 after, integrated from θ(0) = 0.
RigidPose rotation_pose(const scene::Rotation& rotation, double tau) {
  RigidPose pose = rotating_about(rotation.centre, rotation.axis);
  const double w0 = rotation.angular_velocity;
  const double ramp = rotation.ramp_time;
  if (ramp > 0 && tau < ramp) {
    const double phase = std::numbers::pi * tau / ramp;
    pose.angle = w0 * (tau / 2 - ramp / (2 * std::numbers::pi) * std::sin(phase));
    pose.angular_velocity = w0 * (1 - std::cos(phase)) / 2;
    pose.angular_acceleration = w0 * std::numbers::pi / (2 * ramp) * std::sin(phase);
  } else {
    pose.angle = w0 * (std::max(ramp, 0.0) / 2 + tau - std::max(ramp, 0.0));
    pose.angular_velocity = w0;
  }
  return pose;
}

// s(τ) = sin(2π f τ + φ) − sin φ and its first two derivatives.
struct Oscillator {
  double value, rate, rate_of_rate;
};

Oscillator oscillate(double frequency, double phase, double tau) {
  const double w = 2 * std::numbers::pi * frequency;
  const double s = std::sin(w * tau + phase);
  return {s - std::sin(phase), w * std::cos(w * tau + phase), -w * w * s};
}

RigidPose oscillation_pose(const scene::Oscillation& oscillation, double tau) {
  RigidPose pose;
  const Oscillator s = oscillate(oscillation.frequency, oscillation.phase, tau);
  const Eigen::Vector3d amplitude = to_eigen(oscillation.amplitude);
  pose.displacement = s.value * amplitude;
  pose.velocity = s.rate * amplitude;
  pose.acceleration = s.rate_of_rate * amplitude;
  return pose;
}

RigidPose flap_pose(const scene::FlapOscillation& flap, double tau) {
  RigidPose pose = rotating_about(flap.hinge, flap.axis);
  const Oscillator s = oscillate(flap.frequency, flap.phase, tau);
  pose.angle = flap.amplitude * s.value;
  pose.angular_velocity = flap.amplitude * s.rate;
  pose.angular_acceleration = flap.amplitude * s.rate_of_rate;
  return pose;
}

// Linear between the rows around τ; the last row's pose, at rest, from its time on.
RigidPose table_pose(const scene::MotionTable& table, double tau) {
  RigidPose pose = rotating_about(table.centre, table.axis);
  const auto& rows = table.samples;
  const auto after = std::upper_bound(rows.begin(), rows.end(), tau,
                                      [](double t, const scene::MotionSample& row) { return t < row.time; });
  if (after == rows.end()) {
    pose.displacement = to_eigen(rows.back().displacement);
    pose.angle = rows.back().angle;
    return pose;
  }
  const scene::MotionSample& next = *after;
  const scene::MotionSample& last = after == rows.begin() ? next : *std::prev(after);
  const double span = next.time - last.time;
  const double share = span > 0 ? (tau - last.time) / span : 0;
  const Eigen::Vector3d from = to_eigen(last.displacement), to = to_eigen(next.displacement);
  pose.displacement = from + share * (to - from);
  pose.angle = last.angle + share * (next.angle - last.angle);
  if (span > 0) {
    pose.velocity = (to - from) / span;
    pose.angular_velocity = (next.angle - last.angle) / span;
  }
  return pose;
}

}  // namespace

RigidPose::Point RigidPose::point(const Eigen::Vector3d& start) const {
  const Eigen::Vector3d r = Eigen::AngleAxisd(angle, axis) * (start - centre);
  const Eigen::Vector3d turn = axis.cross(r);
  const Eigen::Vector3d inward = axis * axis.dot(r) - r;
  return {centre + displacement + r, velocity + angular_velocity * turn,
          acceleration + angular_acceleration * turn + angular_velocity * angular_velocity * inward};
}

RigidPose pose_at(const scene::Motion& motion, double tau) {
  return std::visit(
      [tau](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<Law, scene::Rotation>) return rotation_pose(law, tau);
        if constexpr (std::is_same_v<Law, scene::Oscillation>) return oscillation_pose(law, tau);
        if constexpr (std::is_same_v<Law, scene::FlapOscillation>) return flap_pose(law, tau);
        if constexpr (std::is_same_v<Law, scene::MotionTable>) return table_pose(law, tau);
        if constexpr (std::is_same_v<Law, scene::Steered>) return RigidPose{};  // until steered (MovingWalls)
      },
      motion);
}

}  // namespace tide
