// Rigid bodies on their own (tide/solvers/mass_properties.hpp, rigid_body.hpp): mass properties
// against the textbook formulas, and Newton–Euler stepping against exact solutions (free fall,
// torque-free precession of a symmetric top, a pendulum on a pivot) and conservation laws.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <utility>
#include <variant>

#include "mesh_shapes.hpp"
#include "tide/solvers/mass_properties.hpp"
#include "tide/solvers/rigid_body.hpp"

namespace tide {
namespace {

constexpr double pi = std::numbers::pi;

// Sums of a few hundred products of numbers of order 1: a relative round-off of about 1e-13.
constexpr double round_off = 1e-12;

void expect_matrix_near(const Eigen::Matrix3d& actual, const Eigen::Matrix3d& expected, double tolerance) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance * expected.cwiseAbs().maxCoeff()) << actual;
}

TEST(MassProperties, BoxIsTheTextbookCuboid) {
  const scene::Box box{{1, 2, 3}, {1.5, 2.2, 4}};  // edges 0.5, 0.2, 1
  const MassProperties p = mass_properties(box, 800, 3);
  const double m = 800 * 0.5 * 0.2 * 1;
  EXPECT_NEAR(p.mass, m, round_off * m);
  EXPECT_TRUE(p.centre.isApprox(Eigen::Vector3d(1.25, 2.1, 3.5), round_off));
  const Eigen::Matrix3d expected = Eigen::Vector3d(0.04 + 1, 0.25 + 1, 0.25 + 0.04).asDiagonal() * (m / 12);
  expect_matrix_near(p.inertia, expected, round_off);
}

TEST(MassProperties, RectangleAndDiscInTwoDimensionsArePerMetreOfDepth) {
  const MassProperties box = mass_properties(scene::Box{{0, 0, 0}, {0.4, 0.1, 0}}, 500, 2);
  EXPECT_NEAR(box.mass, 500 * 0.04, round_off);
  EXPECT_NEAR(box.inertia(2, 2), box.mass * (0.16 + 0.01) / 12, round_off);
  EXPECT_EQ(box.inertia(0, 0), 0);
  const MassProperties disc = mass_properties(scene::Ball{{1, 1, 0}, 0.2}, 1000, 2);
  EXPECT_NEAR(disc.mass, 1000 * pi * 0.04, round_off * disc.mass);
  EXPECT_NEAR(disc.inertia(2, 2), disc.mass * 0.04 / 2, round_off * disc.mass);
}

TEST(MassProperties, BallIsTwoFifthsMR2) {
  const MassProperties p = mass_properties(scene::Ball{{0, 0, 1}, 0.5}, 1000, 3);
  const double m = 1000 * 4 * pi * 0.125 / 3;
  EXPECT_NEAR(p.mass, m, round_off * m);
  expect_matrix_near(p.inertia, Eigen::Matrix3d::Identity() * (0.4 * m * 0.25), round_off);
}

scene::Mesh placed(scene::TriangleMesh surface) {
  return std::get<scene::Mesh>(test::mesh_obstacle(std::move(surface)).shape);
}

// A closed box mesh is the box: the divergence-theorem sums are exact for a polyhedron.
TEST(MassProperties, BoxMeshEqualsTheBoxInBothDimensions) {
  const scene::Vec low{-0.3, 0.1, -0.2}, high{0.5, 0.4, 0.6};
  const scene::Mesh mesh = placed(test::box_mesh(low, high));
  for (const int dimension : {2, 3}) {
    const MassProperties from_mesh = mass_properties(mesh, 700, dimension);
    const MassProperties from_box = mass_properties(scene::Box{low, high}, 700, dimension);
    EXPECT_NEAR(from_mesh.mass, from_box.mass, round_off * from_box.mass) << dimension << "D";
    EXPECT_LE((from_mesh.centre - from_box.centre).norm(), round_off) << dimension << "D";
    expect_matrix_near(from_mesh.inertia, from_box.inertia, round_off);
  }
}

// Turned by R, a box's inertia is R I Rᵀ: the off-diagonal moments of the mesh sums.
TEST(MassProperties, TurnedBoxMeshHasTheTurnedInertia) {
  const scene::Vec low{-0.3, -0.1, -0.2}, high{0.5, 0.4, 0.6};
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  scene::TriangleMesh surface = test::box_mesh(low, high);
  for (auto& v : surface.vertices) {
    const Eigen::Vector3d turned = r * Eigen::Vector3d(v[0], v[1], v[2]);
    v = {turned.x(), turned.y(), turned.z()};
  }
  const MassProperties from_mesh = mass_properties(placed(std::move(surface)), 700, 3);
  const MassProperties from_box = mass_properties(scene::Box{low, high}, 700, 3);
  EXPECT_NEAR(from_mesh.mass, from_box.mass, round_off * from_box.mass);
  EXPECT_LE((from_mesh.centre - r * from_box.centre).norm(), round_off);
  expect_matrix_near(from_mesh.inertia, r * from_box.inertia * r.transpose(), round_off);
}

TEST(MassProperties, ParallelAxisTheorem) {
  const MassProperties rod = mass_properties(scene::Box{{0, -0.01, -0.01}, {1, 0.01, 0.01}}, 1000, 3);
  // About one end, across the rod: m L²/3 plus the thin section's own share.
  const Eigen::Matrix3d end = inertia_about(rod, Eigen::Vector3d::Zero());
  EXPECT_NEAR(end(2, 2), rod.mass * (1.0 / 3 + 0.0004 / 12), round_off * rod.mass);
}

TEST(RigidBody, FallsFreelyAsTheParabola) {
  // Velocity Verlet is exact for a constant acceleration, up to round-off.
  RigidBody body(mass_properties(scene::Box{{0, 0, 0}, {0.1, 0.1, 0}}, 500, 2), {}, 2);
  const Eigen::Vector3d g(0, -9.81, 0), start = body.centre();
  const double dt = 1e-3;
  for (int n = 0; n < 1000; ++n) {
    body.kick(body.gravity_force(g), body.gravity_torque(g), dt / 2);
    body.drift(dt);
    body.kick(body.gravity_force(g), body.gravity_torque(g), dt / 2);
  }
  const Eigen::Vector3d expected = start + 0.5 * g * 1.0;
  EXPECT_LE((body.centre() - expected).norm(), 1e-12);
  EXPECT_LE((body.velocity() - g).norm(), 1e-12);
  EXPECT_TRUE(body.orientation().isApprox(Eigen::Quaterniond::Identity(), 1e-15));
}

TEST(RigidBody, LockedAxesDoNotMove) {
  scene::BodyConstraints constraints;
  constraints.locked_translation = {true, false, true};
  constraints.locked_rotation = true;
  RigidBody body(mass_properties(scene::Ball{{0, 0, 0}, 0.1}, 1000, 3), constraints, 3);
  for (int n = 0; n < 10; ++n) {
    body.kick({5, 3, -2}, {1, 2, 3}, 0.01);
    body.drift(0.01);
  }
  EXPECT_EQ(body.centre().x(), 0);
  EXPECT_EQ(body.centre().z(), 0);
  EXPECT_GT(body.centre().y(), 0);
  EXPECT_TRUE(body.angular_velocity().isZero(0));
}

// A symmetric top (I1 = I2 ≠ I3) spinning freely: L is constant, and the symmetry axis turns
// about L at Ω = |L| / I1, keeping its angle to L (Landau & Lifshitz, Mechanics, §33).
TEST(RigidBody, SymmetricTopPrecessesAtLOverI1) {
  MassProperties top;
  top.mass = 1;
  top.inertia = Eigen::Vector3d(1, 1, 2).asDiagonal();
  RigidBody body(top, {}, 3);
  const Eigen::Vector3d impulse(0.3, 0, 1);  // L, at an angle to the symmetry axis z
  body.kick(Eigen::Vector3d::Zero(), impulse, 1);
  const double energy = body.kinetic_energy();
  const double precession = impulse.norm() / 1.0;
  const double dt = 1e-3, time = 5;
  const int steps = static_cast<int>(std::lround(time / dt));
  for (int n = 0; n < steps; ++n) {
    body.kick(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), dt / 2);
    body.drift(dt);
    body.kick(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), dt / 2);
  }
  EXPECT_LE((body.angular_momentum() - impulse).norm(), 1e-15) << "a torque-free body keeps L exactly";
  // The turn keeps |L| and moves the body on the energy surface up to the midpoint's residual:
  // measured 3e-15 relative.
  EXPECT_NEAR(body.kinetic_energy(), energy, 1e-12 * energy);
  const Eigen::Vector3d axis = body.orientation() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d l_hat = impulse.normalized();
  const Eigen::Vector3d expected = Eigen::AngleAxisd(precession * time, l_hat) * Eigen::Vector3d::UnitZ();
  // A second-order phase error over Ω t ≈ 5.2 rad is at most (Ω dt)² Ω t ≈ 6e-6 rad; measured
  // 4.7e-8.
  EXPECT_LE((axis - expected).norm(), 1e-6) << axis.transpose() << " against " << expected.transpose();
}

// A rod on a pivot at one end swinging with a small amplitude: T = 2π √(I_p / (m g d)).
TEST(RigidBody, PendulumOnAPivotHasTheSmallAngleTimePeriod) {
  const double length = 1;
  scene::BodyConstraints hinge;
  hinge.pivot = {0, 0, 0};
  const MassProperties rod = mass_properties(scene::Box{{-0.01, -length, 0}, {0.01, 0, 0}}, 1000, 2);
  RigidBody body(rod, hinge, 2);
  const Eigen::Vector3d g(0, -9.81, 0);
  const double inertia = inertia_about(rod, Eigen::Vector3d::Zero())(2, 2);
  const double period = 2 * pi * std::sqrt(inertia / (rod.mass * 9.81 * length / 2));
  body.kick(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 0.01 * inertia), 1);  // ω0 = 0.01 rad/s
  const double dt = 1e-4;
  double time = 0, last_crossing = -1, previous_x = body.centre().x();
  int crossings = 0;
  double first_crossing = 0;
  while (crossings < 3) {
    body.kick(body.gravity_force(g), body.gravity_torque(g), dt / 2);
    body.drift(dt);
    body.kick(body.gravity_force(g), body.gravity_torque(g), dt / 2);
    time += dt;
    const double x = body.centre().x();
    if ((x > 0) != (previous_x > 0) && time > dt) {  // through the bottom
      const double crossing = time - dt * x / (x - previous_x);
      if (crossings == 0) first_crossing = crossing;
      last_crossing = crossing;
      ++crossings;
    }
    previous_x = x;
  }
  // One period between the first and third crossing; the amplitude of 0.0026 rad adds
  // θ²/16 ≈ 4e-7 to the period, the step (Ω dt)² ≈ 1.5e-7: measured 4.2e-7.
  EXPECT_NEAR(last_crossing - first_crossing, period, 1e-5 * period);
  EXPECT_LE(body.velocity().norm(), 0) << "a pivot does not translate";
  EXPECT_NEAR(body.reference_point().norm(), 0, 0);
}

}  // namespace
}  // namespace tide
