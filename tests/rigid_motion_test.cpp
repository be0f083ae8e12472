// The prescribed motions of obstacles (tide/solvers/rigid_motion.hpp) against their laws: poses
// at chosen times, rates that are the derivatives of the poses, and the kinematics of a point.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tide/solvers/rigid_motion.hpp"

namespace tide {
namespace {

constexpr double pi = std::numbers::pi;

// Central differences of the pose's angle and displacement have a truncation error of
// h² |f'''| / 6 and a round-off of ε |f| / h; with h = 1e-5 s and the motions below (|f| ≲ 10,
// |f'''| ≲ 1e4) both stay below 1e-5 (relative to rates of order 1 to 100).
constexpr double step = 1e-5;
constexpr double rate_tolerance = 1e-5;

void expect_rates_are_derivatives(const scene::Motion& motion, double tau) {
  const RigidPose before = pose_at(motion, tau - step), now = pose_at(motion, tau), after = pose_at(motion, tau + step);
  const auto scaled = [](double value) { return rate_tolerance * std::max(1.0, std::abs(value)); };
  EXPECT_NEAR(now.angular_velocity, (after.angle - before.angle) / (2 * step), scaled(now.angular_velocity))
      << "τ " << tau;
  EXPECT_NEAR(now.angular_acceleration, (after.angular_velocity - before.angular_velocity) / (2 * step),
              scaled(now.angular_acceleration))
      << "τ " << tau;
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(now.velocity[d], (after.displacement[d] - before.displacement[d]) / (2 * step), scaled(now.velocity[d]))
        << "τ " << tau;
    EXPECT_NEAR(now.acceleration[d], (after.velocity[d] - before.velocity[d]) / (2 * step), scaled(now.acceleration[d]))
        << "τ " << tau;
  }
}

TEST(RigidMotion, RampedRotationReachesItsSpeedSmoothly) {
  const scene::Rotation rotation{{1, 2, 0}, {0, 0, 1}, 3.0, 0.5};
  const RigidPose start = pose_at(rotation, 0);
  EXPECT_EQ(start.angle, 0);
  EXPECT_EQ(start.angular_velocity, 0);
  EXPECT_EQ(start.angular_acceleration, 0);
  // Halfway up the ramp ω = ω0/2 and α peaks at ω0 π / (2 T); at its end θ = ω0 T / 2.
  const RigidPose half = pose_at(rotation, 0.25);
  EXPECT_NEAR(half.angular_velocity, 1.5, 1e-15);
  EXPECT_NEAR(half.angular_acceleration, 3.0 * pi / 1.0, 1e-14);
  const RigidPose end = pose_at(rotation, 0.5);
  EXPECT_NEAR(end.angle, 0.75, 1e-15);
  EXPECT_EQ(end.angular_velocity, 3.0);
  EXPECT_NEAR(pose_at(rotation, 1.5).angle, 0.75 + 3.0, 1e-14);
  for (const double tau : {0.1, 0.3, 0.49, 0.7, 2.0}) expect_rates_are_derivatives(rotation, tau);
  EXPECT_EQ(pose_at(scene::Rotation{{}, {0, 0, 1}, 2.0, 0}, 0.25).angle, 0.5);  // no ramp: θ = ω0 τ
}

TEST(RigidMotion, OscillationsFollowTheirSine) {
  const scene::Oscillation piston{{0.1, -0.05, 0}, 2.0, -pi / 2};  // d = A (1 − cos(4π τ)): at rest at τ = 0
  EXPECT_NEAR(pose_at(piston, 0).velocity.norm(), 0, 1e-16);
  const RigidPose quarter = pose_at(piston, 0.125);  // 4π τ = π/2: d = A, ḋ = 4π A
  EXPECT_NEAR(quarter.displacement[0], 0.1, 1e-15);
  EXPECT_NEAR(quarter.displacement[1], -0.05, 1e-15);
  EXPECT_NEAR(quarter.velocity[0], 0.4 * pi, 1e-14);
  EXPECT_NEAR(pose_at(piston, 0.25).displacement[0], 0.2, 1e-15);  // the far end, 2A
  const scene::FlapOscillation flap{{0.5, 0, 0}, {0, 0, 1}, 0.2, 0.5, 0};
  EXPECT_NEAR(pose_at(flap, 0.5).angle, 0.2, 1e-15);  // π τ = π/2
  EXPECT_NEAR(pose_at(flap, 0).angular_velocity, 0.2 * pi, 1e-15);
  for (const double tau : {0.03, 0.2, 0.61}) {
    expect_rates_are_derivatives(piston, tau);
    expect_rates_are_derivatives(flap, tau);
  }
}

TEST(RigidMotion, TableIsLinearBetweenRowsAndHeldAfter) {
  scene::MotionTable table;
  table.centre = {1, 0, 0};
  table.samples = {{0, {0, 0, 0}, 0}, {1, {0.2, 0, 0}, 0.5}, {3, {0.2, 0.4, 0}, 0.5}};
  const RigidPose first = pose_at(table, 0.25);
  EXPECT_NEAR(first.displacement[0], 0.05, 1e-16);
  EXPECT_NEAR(first.angle, 0.125, 1e-16);
  EXPECT_NEAR(first.velocity[0], 0.2, 1e-16);
  EXPECT_NEAR(first.angular_velocity, 0.5, 1e-16);
  const RigidPose second = pose_at(table, 2);
  EXPECT_NEAR(second.displacement[1], 0.2, 1e-16);
  EXPECT_NEAR(second.velocity[1], 0.2, 1e-16);
  EXPECT_EQ(second.angular_velocity, 0);
  const RigidPose held = pose_at(table, 10);
  EXPECT_EQ(held.displacement, Eigen::Vector3d(0.2, 0.4, 0));
  EXPECT_EQ(held.velocity, Eigen::Vector3d::Zero());
  EXPECT_EQ(pose_at(table, 0).displacement, Eigen::Vector3d::Zero());
}

// A point on a solid turning at ω about z through c moves on its circle: a quarter turn takes
// (c + r, 0) to (c, r), its velocity is ω r tangential and its acceleration −ω² r towards the
// axis plus α r tangential, on top of the axis' own translation.
TEST(RigidMotion, PointOfATurningSolid) {
  RigidPose pose;
  pose.centre = {1, 2, 0};
  pose.displacement = {0.5, 0, 0};
  pose.velocity = {0.1, 0.2, 0};
  pose.acceleration = {0, -1, 0};
  pose.angle = pi / 2;
  pose.angular_velocity = 2;
  pose.angular_acceleration = 3;
  const RigidPose::Point p = pose.point({1.5, 2, 0});  // r = 0.5 along x, turned to y
  const double tolerance = 1e-15;
  EXPECT_NEAR(p.position[0], 1.5, tolerance);
  EXPECT_NEAR(p.position[1], 2.5, tolerance);
  EXPECT_NEAR(p.velocity[0], 0.1 - 2 * 0.5, tolerance);
  EXPECT_NEAR(p.velocity[1], 0.2, tolerance);
  EXPECT_NEAR(p.acceleration[0], -3 * 0.5, tolerance);
  EXPECT_NEAR(p.acceleration[1], -1 - 4 * 0.5, tolerance);
  // About an axis along x in 3D, a point on the axis does not move.
  pose.axis = {1, 0, 0};
  const RigidPose::Point on_axis = pose.point({7, 2, 0});
  EXPECT_NEAR(on_axis.position[1], 2, tolerance);
  EXPECT_NEAR(on_axis.position[2], 0, tolerance);
  EXPECT_NEAR((on_axis.velocity - pose.velocity).norm(), 0, tolerance);
}

}  // namespace
}  // namespace tide
