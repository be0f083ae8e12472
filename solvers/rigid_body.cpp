#include "tide/solvers/rigid_body.hpp"

#include <Eigen/Cholesky>
#include <stdexcept>
#include <string>

#include "tide/solvers/rigid_motion.hpp"

namespace tide {
namespace {

// The iterations of the implicit midpoint rotation: each gains about one order of ω dt, and a
// fixed count keeps the result the same on every run.
constexpr int midpoint_iterations = 4;

// exp(ω dt) as a unit quaternion: a turn by |ω| dt about ω.
Eigen::Quaterniond turn(const Eigen::Vector3d& omega, double dt) {
  const double rate = omega.norm();
  if (rate == 0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(rate * dt, omega / rate));
}

}  // namespace

RigidBody::RigidBody(const MassProperties& properties, const scene::BodyConstraints& constraints, int dimension)
    : properties_(properties) {
  if (!(properties.mass > 0)) throw std::invalid_argument("a rigid body needs a positive mass");
  for (int d = 0; d < 3; ++d)
    if (constraints.locked_translation[d] || (dimension == 2 && d == 2)) translation_mask_[d] = 0;
  start_reference_ = properties.centre;
  if (constraints.pivot) {
    start_reference_ = to_eigen(*constraints.pivot);
    translation_mask_.setZero();
  }
  rotates_ = !constraints.locked_rotation;
  if (dimension == 2) {
    has_axis_ = true;  // about z
  } else if (constraints.rotation_axis) {
    has_axis_ = true;
    axis_ = to_eigen(*constraints.rotation_axis).normalized();
  }
  start_inertia_ = inertia_about(properties, start_reference_);
  if (rotates_ && has_axis_ && !(axis_.dot(start_inertia_ * axis_) > 0))
    throw std::invalid_argument("a rigid body needs a positive moment of inertia about its rotation axis");
  reference_ = start_reference_;
}

Eigen::Vector3d RigidBody::angular_velocity_at(const Eigen::Quaterniond& orientation) const {
  if (!rotates_) return Eigen::Vector3d::Zero();
  const Eigen::Matrix3d r = orientation.toRotationMatrix();
  const Eigen::Matrix3d inertia = r * start_inertia_ * r.transpose();
  if (has_axis_) return axis_ * (axis_.dot(angular_momentum_) / axis_.dot(inertia * axis_));
  return inertia.ldlt().solve(angular_momentum_);
}

Eigen::Vector3d RigidBody::constrained_torque(const Eigen::Vector3d& torque) const {
  if (!rotates_) return Eigen::Vector3d::Zero();
  if (has_axis_) return axis_ * axis_.dot(torque);
  return torque;
}

void RigidBody::kick(const Eigen::Vector3d& force, const Eigen::Vector3d& torque, double dt) {
  acceleration_ = translation_mask_.cwiseProduct(force) / properties_.mass;
  velocity_ += dt * acceleration_;
  const Eigen::Vector3d applied = constrained_torque(torque);
  // α = I⁻¹ (τ − ω × L) (Euler's equations in the space frame); about a fixed axis, τ_n / I_n.
  const Eigen::Matrix3d r = orientation_.toRotationMatrix();
  const Eigen::Matrix3d inertia = r * start_inertia_ * r.transpose();
  if (!rotates_) {
    angular_acceleration_.setZero();
  } else if (has_axis_) {
    angular_acceleration_ = applied / axis_.dot(inertia * axis_);
  } else {
    const auto solver = inertia.ldlt();
    const Eigen::Vector3d omega = solver.solve(angular_momentum_);
    angular_acceleration_ = solver.solve(applied - omega.cross(angular_momentum_));
  }
  angular_momentum_ += dt * applied;
}

void RigidBody::drift(double dt) {
  reference_ += dt * velocity_;
  if (!rotates_) return;
  Eigen::Vector3d omega = angular_velocity_at(orientation_);
  for (int k = 0; k < midpoint_iterations; ++k)
    omega = angular_velocity_at((turn(omega, dt / 2) * orientation_).normalized());
  orientation_ = (turn(omega, dt) * orientation_).normalized();
}

RigidBody::Kinematics RigidBody::kinematics() const {
  return {start_reference_, reference_,         orientation_,         velocity_,
          acceleration_,    angular_velocity(), angular_acceleration_};
}

RigidBody::Point RigidBody::Kinematics::point(const Eigen::Vector3d& start) const {
  const Eigen::Vector3d r = lever(start);
  return {reference + r, velocity + angular_velocity.cross(r),
          acceleration + angular_acceleration.cross(r) + angular_velocity.cross(angular_velocity.cross(r))};
}

double RigidBody::kinetic_energy() const {
  return properties_.mass * velocity_.squaredNorm() / 2 + angular_velocity().dot(angular_momentum_) / 2;
}

std::vector<double> RigidBody::motion_state() const {
  std::vector<double> state;
  for (const Eigen::Vector3d* v : {&reference_, &velocity_, &angular_momentum_, &acceleration_, &angular_acceleration_})
    state.insert(state.end(), v->data(), v->data() + 3);
  state.insert(state.end(), {orientation_.w(), orientation_.x(), orientation_.y(), orientation_.z()});
  return state;
}

void RigidBody::restore_motion_state(std::span<const double> state) {
  if (state.size() != 19)
    throw std::invalid_argument("a rigid body's motion is 19 numbers, got " + std::to_string(state.size()));
  std::size_t k = 0;
  for (Eigen::Vector3d* v : {&reference_, &velocity_, &angular_momentum_, &acceleration_, &angular_acceleration_}) {
    *v = Eigen::Vector3d(state[k], state[k + 1], state[k + 2]);
    k += 3;
  }
  orientation_ = Eigen::Quaterniond(state[k], state[k + 1], state[k + 2], state[k + 3]);
}

}  // namespace tide
