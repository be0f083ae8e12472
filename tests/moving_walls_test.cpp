// Obstacles with a prescribed motion (scene::Motion, tide/solvers/moving_walls.hpp) in a run: a
// tank of three box obstacles shaken up and down as one, with water inside. The walls must be
// exactly where their motion puts them, the water must move with the tank (it cannot leave it),
// and its pressure must be the hydrostatic one of the tank's frame, ρ0 (g + a(t)) (H − y).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "tide/core/scene.hpp"
#include "tide/solvers/rigid_motion.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide {
namespace {

constexpr double spacing = 0.01;  // Δx, m
constexpr double width = 0.2;     // m, inner width of the tank
constexpr double depth = 0.1;     // H, m, of water
constexpr double g = 9.81;
constexpr double amplitude = 0.01;  // A, m: d(τ) = A (1 − cos(2π f τ)), at rest at τ = 0
constexpr double frequency = 2;     // f, Hz: a peaks at A (2π f)² = 1.58 m/s², 16% of g

scene::Oscillation shaking() { return {{0, amplitude, 0}, frequency, -std::numbers::pi / 2}; }

scene::Scene shaken_tank() {
  scene::Scene s;
  s.source = "shaken tank";
  s.dimension = 2;
  s.particle_spacing = spacing;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 2.0});  // c0 = 20 m/s
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {width, depth, 0}}});
  const double t = s.walls.layers * spacing;
  const auto wall = [&](scene::Box box) {
    scene::Obstacle obstacle;
    obstacle.shape = box;
    obstacle.motion = shaking();
    return obstacle;
  };
  s.walls.obstacles = {wall({{-t, -t, 0}, {width + t, 0, 0}}), wall({{-t, 0, 0}, {0, 3 * depth, 0}}),
                       wall({{width, 0, 0}, {width + t, 3 * depth, 0}})};
  s.domain.box = {{-2 * t, -2 * t, 0}, {width + 2 * t, 4 * depth, 0}};
  s.gravity = {0, -g, 0};
  s.solver.alpha = 0.1;
  return s;
}

// The mean of `values` over the fluid particles whose position `keep` picks.
template <class Keep>
double mean_over(const Simulation<2>& simulation, std::span<const Real> values, Keep&& keep) {
  const auto x = simulation.fluid()[simulation.fluid_fields().position];
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < simulation.fluid().size(); ++i) {
    if (!keep(x[i])) continue;
    sum += values[i];
    ++count;
  }
  return sum / count;
}

// Least squares y = a + b x.
struct LineFit {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  void add(double x, double y) {
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  double slope() const { return (n * sxy - sx * sy) / (n * sxx - sx * sx); }
};

TEST(MovingWalls, ShakenTankCarriesItsWater) {
  const auto simulation = make_simulation<2>(shaken_tank());
  const Interactions<2>& interactions = simulation->interactions();
  ASSERT_EQ(interactions.contact_count(), 3u) << "each moving obstacle is a contact of its own";
  EXPECT_EQ(interactions.contact(0).name(), "walls.obstacles[0]");
  EXPECT_TRUE(interactions.contact(0).moves());
  EXPECT_TRUE(simulation->pipeline().contains("prescribed_motion"));

  const auto fluid_y = [&] {
    const auto x = simulation->fluid()[simulation->fluid_fields().position];
    double sum = 0;
    for (std::size_t i = 0; i < simulation->fluid().size(); ++i) sum += x[i][1];
    return sum / static_cast<double>(simulation->fluid().size());
  };
  const double start_y = fluid_y();
  double worst_follow = 0;
  double worst_pressure = 0;
  LineFit fit;
  while (simulation->time() < 1.0) {
    simulation->step();
    const RigidPose pose = pose_at(shaking(), simulation->time());
    worst_follow = std::max(worst_follow, std::abs(fluid_y() - start_y - pose.displacement[1]));
    const double floor = pose.displacement[1];
    const double bottom = mean_over(*simulation, simulation->fluid()[simulation->fluid_fields().pressure],
                                    [&](const Vector<2>& x) { return x[1] - floor < 2 * spacing; });
    const double expected = 1000 * (g + pose.acceleration[1]) * (depth - spacing);
    if (simulation->time() >= 0.4) {
      worst_pressure = std::max(worst_pressure, std::abs(bottom - expected));
      fit.add(expected, bottom);
    }
  }
  // The water column settles under its weight by g H² / (2 c0²) = 0.12 mm and breathes acoustically
  // by as much; a tank that left its water behind would be off by up to 2A = 20 mm. Measured:
  // 0.25 mm (0.025 Δx) over two periods.
  EXPECT_LT(worst_follow, 0.1 * spacing);
  // After the start-up waves (0.4 s), the bottom rows' pressure is ρ0 (g + a(t)) (H − Δx) to within
  // the WCSPH pressure noise of c0 = 20 m/s, and it swings with a(t) by 2 ρ0 A (2π f)² (H − Δx) =
  // 284 Pa: measured, 74 Pa at worst (0.075 ρ0 g H) and a slope of 1.04 against the exact value.
  EXPECT_LT(worst_pressure, 0.1 * 1000 * g * depth);
  EXPECT_NEAR(fit.slope(), 1, 0.1);

  // Every wall particle sits at c + d + R(x0 − c) of its start position x0 and moves with ḋ.
  const RigidPose pose = pose_at(shaking(), simulation->time());
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<2>& contact = interactions.contact(k);
    const ParticleSet<2>& walls = contact.particles();
    const auto x = walls[contact.fields().position];
    const auto v = walls[*contact.fields().surface_velocity];
    const auto start = walls[walls.vector("start_position")];
    for (std::size_t b = 0; b < walls.size(); ++b) {
      EXPECT_EQ(x[b][0], start[b][0]);
      EXPECT_EQ(x[b][1], static_cast<Real>(static_cast<double>(start[b][1]) + pose.displacement[1]));
      EXPECT_EQ(v[b][1], static_cast<Real>(pose.velocity[1]));
    }
  }
}

// The acoustic limit counts the walls' speed with the fluid's: shaken at 10 Hz by ±2 cm, the tank's
// walls reach 1.26 m/s (6% of c0) a quarter period in, where water at rest would allow a step 6%
// longer than the walls do: every step keeps dt (c0 + |v_wall|) ≤ cfl h, |v_wall| the walls' speed
// where the last step left them.
TEST(MovingWalls, TimeStepCountsTheWallsSpeed) {
  scene::Scene s = shaken_tank();
  const scene::Oscillation fast{{0, 0.02, 0}, 10, -std::numbers::pi / 2};
  for (scene::Obstacle& obstacle : s.walls.obstacles) obstacle.motion = fast;
  const auto simulation = make_simulation<2>(s);
  const double c0 = 20, limit = s.solver.cfl * simulation->smoothing_length();
  double fastest_wall = 0;
  while (simulation->time() < 0.03) {
    const double wall_speed = pose_at(fast, simulation->time()).velocity.norm();
    fastest_wall = std::max(fastest_wall, wall_speed);
    const double dt = simulation->step().time_step.dt;
    EXPECT_LE(dt * (c0 + wall_speed), limit * (1 + 1e-6)) << "at t = " << simulation->time();
  }
  EXPECT_GT(fastest_wall, 1.2);
}

}  // namespace
}  // namespace tide
