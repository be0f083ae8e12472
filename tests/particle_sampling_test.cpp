// Fluid and wall particles from scene geometry: fluid fills the blocks but never a solid; walls
// are `layers` deep behind the container faces and inside each obstacle's surface; all particles
// sit on one lattice, so no two are closer than one spacing.

#include "tide/solvers/particle_sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace tide {
namespace {

scene::Scene obstacle_scene() {
  scene::Scene s;
  s.dimension = 2;
  s.particle_spacing = 0.01;
  s.materials.push_back({"water", 1000, 0, std::nullopt, 1.0});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {1, 0.6, 0}}});
  s.walls.layers = 3;
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {1, 1, 0}}, true};
  s.walls.obstacles.push_back({scene::Ball{{0.5, 0.3, 0}, 0.1}, {}, std::nullopt, std::nullopt, std::nullopt});
  s.walls.obstacles.push_back({scene::Box{{0.1, 0.1, 0}, {0.2, 0.2, 0}}, {}, std::nullopt, std::nullopt, std::nullopt});
  // A slope through the lower right corner: solid below y = x − 0.697 (between lattice points).
  s.walls.obstacles.push_back(
      {scene::Plane{{0.8, 0.103, 0}, {-1, 1, 0}}, {}, std::nullopt, std::nullopt, std::nullopt});
  s.domain.box = {{-0.03, -0.03, 0}, {1.03, 2, 0}};
  return s;
}

bool inside_solid(const Vector<2>& p) {
  const bool in_ball = (p - Vector<2>(0.5, 0.3)).norm() < 0.1;
  const bool in_box = p.x() >= 0.1 && p.x() < 0.2 && p.y() >= 0.1 && p.y() < 0.2;
  const bool below_slope = p.y() - (p.x() - 0.697) < 0;
  return in_ball || in_box || below_slope;
}

TEST(ParticleSampling, FluidFillsTheBlockOutsideEverySolid) {
  const scene::Scene s = obstacle_scene();
  const auto fluid = sample_fluid<2>(s).positions;
  std::size_t expected = 0;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 60; ++j) expected += inside_solid(Vector<2>(0.005 + 0.01 * i, 0.005 + 0.01 * j)) ? 0 : 1;
  EXPECT_EQ(fluid.size(), expected);
  for (const auto& p : fluid) EXPECT_FALSE(inside_solid(p)) << p.transpose();
}

TEST(ParticleSampling, WallsLineContainerAndObstaclesWithoutOverlap) {
  const scene::Scene s = obstacle_scene();
  const auto fluid = sample_fluid<2>(s).positions;
  const auto walls = sample_walls<2>(s).positions;
  // The ball's wall is a ring 3 spacings deep: its area π(r² − (r − 3Δx)²) in lattice cells.
  std::size_t ring = 0;
  for (const auto& p : walls) {
    const Real from_centre = (p - Vector<2>(0.5, 0.3)).norm();
    if (from_centre < 0.1) {
      ++ring;
      EXPECT_GE(from_centre, Real(0.1 - 0.03 - 1e-9));
    }
  }
  const double ring_cells = std::numbers::pi * (0.1 * 0.1 - 0.07 * 0.07) / (0.01 * 0.01);
  EXPECT_NEAR(static_cast<double>(ring), ring_cells, 0.1 * ring_cells);
  // Container walls reach the rim (y < 1) but not above it: the top is open.
  for (const auto& p : walls) EXPECT_LT(p.y(), 1.0);
  // One lattice for everything: no two particles closer than one spacing (no duplicates where
  // the slope meets the container, nor between fluid and walls).
  std::vector<Vector<2>> all = fluid;
  all.insert(all.end(), walls.begin(), walls.end());
  for (std::size_t a = 0; a < all.size(); ++a)
    for (std::size_t b = a + 1; b < all.size(); ++b) ASSERT_GT((all[a] - all[b]).norm(), Real(0.0099)) << a << " " << b;
}

TEST(ParticleSampling, ThreeDimensionalContainerHasLayersOnFiveFaces) {
  scene::Scene s;
  s.dimension = 3;
  s.particle_spacing = 0.1;
  s.walls.layers = 2;
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {1, 1, 1}}, true};
  s.domain.box = {{-0.2, -0.2, -0.2}, {1.2, 1.2, 2}};
  // Outer box 14 × 14 × 12 cells (open top: no layers above z = 1) minus the 10³ inner cells.
  EXPECT_EQ(sample_walls<3>(s).size(), std::size_t(14 * 14 * 12 - 10 * 10 * 10));
}

// A lid (plane obstacle) on an open container, as in the lid-driven cavity: its layers above
// the rim are all made, once each, and carry the lid's velocity; the container's carry none.
TEST(ParticleSampling, MovingLidOnAnOpenContainer) {
  scene::Scene s;
  s.dimension = 2;
  s.particle_spacing = 0.1;
  s.walls.layers = 2;
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {1, 1, 0}}, true};
  s.walls.obstacles.push_back(
      {scene::Plane{{0, 1, 0}, {0, -1, 0}}, {2, 0, 0}, std::nullopt, std::nullopt, std::nullopt});
  s.domain.box = {{-0.2, -0.2, 0}, {1.2, 1.2, 0}};
  const auto walls = sample_walls<2>(s);
  std::size_t lid = 0;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const bool above_rim = walls.positions[i].y() > 1;
    lid += above_rim ? 1 : 0;
    EXPECT_EQ(walls.velocities[i], above_rim ? Vector<2>(2, 0) : Vector<2>(0, 0)) << walls.positions[i].transpose();
  }
  EXPECT_EQ(lid, std::size_t(14 * 2));                            // the lid spans the domain, 2 layers
  EXPECT_EQ(walls.size() - lid, std::size_t(14 * 12 - 10 * 10));  // container: 3 faces up to the rim
}

// The Taylor–Green block starts with u = −U cos 2πx/L sin 2πy/L, v = U sin 2πx/L cos 2πy/L.
TEST(ParticleSampling, TaylorGreenInitialVelocity) {
  scene::FluidBlock block{0, scene::Box{{0, 0, 0}, {2, 2, 0}}, scene::TaylorGreenVelocity{3, 2}};
  const Vector<2> x(0.25, 0.125);
  const double k = std::numbers::pi;
  const Vector<2> v = initial_velocity<2>(block, x);
  EXPECT_NEAR(v.x(), -3 * std::cos(k * 0.25) * std::sin(k * 0.125), 1e-6);
  EXPECT_NEAR(v.y(), 3 * std::sin(k * 0.25) * std::cos(k * 0.125), 1e-6);
}

// A rigid rotation at ω about c: v = ω ẑ × (x − c), u = −ω (y − y_c), v = ω (x − x_c).
TEST(ParticleSampling, RigidRotationInitialVelocity) {
  scene::FluidBlock block{0, scene::Box{{0, 0, 0}, {2, 2, 0}}, scene::RigidRotation{{1, 0.5, 0}, 2}};
  const Vector<2> v = initial_velocity<2>(block, Vector<2>(1.25, 1.0));
  EXPECT_NEAR(v.x(), -2 * 0.5, 1e-6);
  EXPECT_NEAR(v.y(), 2 * 0.25, 1e-6);
}

}  // namespace
}  // namespace tide
