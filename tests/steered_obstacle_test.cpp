// What a running program changes in a simulation (Simulation::steer, set_gravity,
// set_kinematic_viscosity; tide serve's controls): a steered obstacle (scene::Steered) goes where
// it is steered at its max_speed and pushes the water, stays inside the domain, and gravity and
// viscosity change from the next step.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "tide/core/scene.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide {
namespace {

constexpr double spacing = 0.02;
constexpr double max_speed = 0.5;  // m/s, the obstacle's

// Water 0.2 m deep in a closed tank 1 m wide, a disc of radius 0.06 m in it at (0.3, 0.1).
scene::Scene tank(scene::Scheme scheme) {
  scene::Scene s;
  s.source = "steered tank";
  s.dimension = 2;
  s.particle_spacing = spacing;
  s.materials.push_back({"water", 1000, 1e-4, std::nullopt, 2.0});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {1, 0.2, 0}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {1, 0.5, 0}}, false};
  scene::Obstacle disc;
  disc.shape = scene::Ball{{0.3, 0.1, 0}, 0.06};
  disc.motion = scene::Steered{max_speed};
  s.walls.obstacles.push_back(disc);
  const double t = s.walls.layers * spacing;
  s.domain.box = {{-t, -t, 0}, {1 + t, 0.5 + t, 0}};
  s.solver.scheme = scheme;
  s.solver.viscosity = scene::ViscosityModel::laminar;
  return s;
}

struct Extent {
  double mean_x = 0, least_x = std::numeric_limits<double>::max(), most_x = -std::numeric_limits<double>::max();
};

Extent obstacle_extent(const Simulation<2>& simulation) {
  const Contact<2>& disc = simulation.interactions().contact(simulation.interactions().contact_count() - 1);
  EXPECT_TRUE(disc.moves());
  const auto x = disc.particles()[disc.fields().position];
  Extent extent;
  for (std::size_t b = 0; b < disc.particles().size(); ++b) {
    extent.mean_x += x[b][0] / static_cast<double>(disc.particles().size());
    extent.least_x = std::min(extent.least_x, static_cast<double>(x[b][0]));
    extent.most_x = std::max(extent.most_x, static_cast<double>(x[b][0]));
  }
  return extent;
}

double fluid_momentum_x(const Simulation<2>& simulation) {
  const auto v = simulation.fluid()[simulation.fluid_fields().velocity];
  double sum = 0;
  for (std::size_t i = 0; i < simulation.fluid().size(); ++i) sum += v[i][0];
  return sum;
}

TEST(SteeredObstacle, FollowsItsTargetAtItsMaxSpeedAndPushesTheWater) {
  for (const scene::Scheme scheme : {scene::Scheme::wcsph, scene::Scheme::dfsph}) {
    SCOPED_TRACE(static_cast<int>(scheme));
    const auto simulation = make_simulation<2>(tank(scheme));
    const double home = obstacle_extent(*simulation).mean_x;
    // Unsteered, it stays where the scene puts it.
    for (int k = 0; k < 5; ++k) simulation->step();
    EXPECT_EQ(obstacle_extent(*simulation).mean_x, home);

    ASSERT_TRUE(simulation->steer({0.4, 0, 0}));
    const double start = simulation->time();
    while (simulation->time() < start + 0.2) {
      simulation->step();
      // On its way it moves at max_speed: 0.1 m in 0.2 s, short of the target 0.4 m away.
      EXPECT_NEAR(obstacle_extent(*simulation).mean_x - home, max_speed * (simulation->time() - start), 1e-6);
    }
    EXPECT_GT(fluid_momentum_x(*simulation), 0) << "the water is pushed the way the disc goes";
    while (simulation->time() < start + 1.0) simulation->step();
    EXPECT_NEAR(obstacle_extent(*simulation).mean_x - home, 0.4, 1e-6) << "arrived, and held there";
  }
}

TEST(SteeredObstacle, StaysInsideTheDomain) {
  scene::Scene s = tank(scene::Scheme::dfsph);
  s.walls.obstacles[0].shape = scene::Ball{{0.3, 0.35, 0}, 0.06};  // above the water, clear of it
  const auto simulation = make_simulation<2>(s);
  ASSERT_TRUE(simulation->steer({5, 0, 0}));  // far beyond the right wall
  while (simulation->time() < 2.0) simulation->step();
  const double right = tank(scene::Scheme::dfsph).domain.box.max[0];
  EXPECT_NEAR(obstacle_extent(*simulation).most_x, right - spacing, 1e-6) << "one spacing inside the domain";
}

TEST(SteeredObstacle, ASceneWithoutOneIsNotSteered) {
  scene::Scene s = tank(scene::Scheme::wcsph);
  s.walls.obstacles.clear();
  EXPECT_FALSE(make_simulation<2>(s)->steer({0.1, 0, 0}));
}

TEST(LiveChanges, GravityTurnedSidewaysMovesTheWater) {
  const auto simulation = make_simulation<2>(tank(scene::Scheme::dfsph));
  ASSERT_TRUE(simulation->set_gravity(Vector<2>(5, -9.81)));
  EXPECT_EQ(simulation->gravity(), Vector<2>(5, -9.81));
  while (simulation->time() < 0.1) simulation->step();
  EXPECT_GT(fluid_momentum_x(*simulation), 0);
}

TEST(LiveChanges, ViscosityChangesOnlyWhereItIsLaminar) {
  const auto laminar = make_simulation<2>(tank(scene::Scheme::wcsph));
  EXPECT_TRUE(laminar->set_kinematic_viscosity(1e-2));
  scene::Scene s = tank(scene::Scheme::wcsph);
  s.solver.viscosity = scene::ViscosityModel::artificial;
  EXPECT_FALSE(make_simulation<2>(s)->set_kinematic_viscosity(1e-2));
}

// Gravity turned sideways, the no-slip floor holds a thick fluid back: over 0.3 s the viscous
// layer grows to sqrt(ν t) = 55 mm of the 0.2 m depth at ν = 0.01 m²/s, against 5.5 mm at 1e-4.
TEST(LiveChanges, HigherViscosityDampsTheFlow) {
  const auto momentum_after = [](double viscosity) {
    const auto simulation = make_simulation<2>(tank(scene::Scheme::dfsph));
    EXPECT_TRUE(simulation->set_kinematic_viscosity(static_cast<Real>(viscosity)));
    simulation->set_gravity(Vector<2>(5, -9.81));
    while (simulation->time() < 0.3) simulation->step();
    return std::abs(fluid_momentum_x(*simulation));
  };
  EXPECT_LT(momentum_after(1e-2), momentum_after(1e-4));
}

}  // namespace
}  // namespace tide
