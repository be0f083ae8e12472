// Rigid bodies moved by the fluid (scene::Body, tide/solvers/rigid_bodies.hpp) in WCSPH runs at
// low resolution: a floating box settles at Archimedes' draft, upright, and a body in a periodic
// box without gravity exchanges momentum with the fluid in equal and opposite amounts.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "tide/core/scene.hpp"
#include "tide/solvers/instability.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

constexpr double g = 9.81;

std::string scientific(double value) {
  std::ostringstream text;
  text << std::scientific << std::setprecision(3) << value;
  return text.str();
}

scene::Obstacle body(scene::Box box, double density) {
  scene::Obstacle obstacle;
  obstacle.shape = box;
  obstacle.body = scene::Body{density, {}};
  return obstacle;
}

// A tank 0.6 m wide with water 0.3 m deep and a box 0.2 m wide, 0.1 m high, of half the water's
// density, let go 3 cm above its draft of ρ_b/ρ_f × 0.1 m = 5 cm.
constexpr double spacing = 0.01;
constexpr double tank_width = 0.6, water_depth = 0.3;
constexpr double box_width = 0.2, box_height = 0.1, density_ratio = 0.5;

scene::Scene floating_box(double ratio = density_ratio) {
  scene::Scene s;
  s.source = "floating box";
  s.dimension = 2;
  s.particle_spacing = spacing;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 2.0});  // c0 = 20 m/s
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {tank_width, water_depth, 0}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {tank_width, 2 * water_depth, 0}}, true};
  const double bottom = water_depth - 0.03;
  const double left = (tank_width - box_width) / 2;
  s.walls.obstacles.push_back(body({{left, bottom, 0}, {left + box_width, bottom + box_height, 0}}, 1000 * ratio));
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * spacing, 2);
  s.gravity = {0, -g, 0};
  s.solver.alpha = 0.1;
  return s;
}

// The free surface away from the box: the mean height of the topmost particle of the columns
// within 0.1 m of the tank's sides, plus half a spacing (that particle's share).
double water_level(const Wcsph<2>& simulation) {
  const auto x = simulation.fluid()[simulation.fluid_fields().position];
  const int columns = static_cast<int>(std::lround(tank_width / spacing)), side = 10;
  std::vector<double> top(columns, -1);
  for (std::size_t i = 0; i < simulation.fluid().size(); ++i) {
    const int column = std::clamp(static_cast<int>(std::floor(x[i][0] / spacing)), 0, columns - 1);
    top[column] = std::max(top[column], static_cast<double>(x[i][1]));
  }
  double sum = 0;
  for (int k = 0; k < side; ++k) sum += top[k] + top[columns - 1 - k];
  return sum / (2 * side) + spacing / 2;
}

TEST(FloatingBody, BoxSettlesAtArchimedesDraftUpright) {
  Wcsph<2> simulation(floating_box());
  ASSERT_EQ(simulation.bodies()->size(), 1u);
  EXPECT_EQ(simulation.bodies()->contact(0).name(), "walls.obstacles[0]");
  EXPECT_TRUE(simulation.pipeline().contains("body_force"));
  const RigidBody& box = simulation.bodies()->body(0);
  double draft_sum = 0, worst_tilt = 0;
  int samples = 0;
  while (simulation.time() < 3.0) {
    simulation.step();
    const double tilt = 2 * std::asin(std::abs(box.orientation().z()));
    worst_tilt = std::max(worst_tilt, tilt);
    if (simulation.time() < 2.0) continue;
    draft_sum += water_level(simulation) - (box.centre().y() - box_height / 2);
    ++samples;
  }
  const double draft = draft_sum / samples;
  const double expected = density_ratio * box_height;
  RecordProperty("draft_m", scientific(draft));
  // The draft converges as the lattice is refined: measured 2.6% short at this Δx = 1 cm (the draft
  // is 5 Δx) and 0.84% at Δx = 5 mm, where the 2% of Archimedes' check holds; this low-resolution
  // case bounds the 1 cm error.
  EXPECT_NEAR(draft, expected, 0.03 * expected) << "mean draft over 2-3 s";
  EXPECT_LT(worst_tilt, 0.05) << "rad: the box stays upright";
}

// Light bodies (issue 35: density ratios 0.1 to 0.5 stay stable). The coupling is explicit: a
// body lighter than the fluid it sets moving (its added mass; for this flat box about ρ π B²/8,
// 16 kg per metre against its 2 kg) could overshoot by more each step. WCSPH's short acoustic step
// keeps a box of a tenth of water's density stable: measured upright within 0.005 rad and moving at
// most 0.046 m/s over 2–3 s, as the half-density box above does with the waves it rides
// (0.036 m/s). Its draft, 1 cm, is one Δx here and measured 0.56 cm: the box rests on the top
// particle layer.
TEST(FloatingBody, LightBoxFloatsStably) {
  constexpr double ratio = 0.1;
  Wcsph<2> simulation(floating_box(ratio));
  const RigidBody& box = simulation.bodies()->body(0);
  double draft_sum = 0, worst_tilt = 0, late_speed = 0;
  int samples = 0;
  while (simulation.time() < 3.0) {
    simulation.step();
    worst_tilt = std::max(worst_tilt, 2 * std::asin(std::abs(box.orientation().z())));
    if (simulation.time() < 2.0) continue;
    late_speed = std::max(late_speed, box.velocity().norm());
    draft_sum += water_level(simulation) - (box.centre().y() - box_height / 2);
    ++samples;
  }
  const double draft = draft_sum / samples;
  RecordProperty("draft_m", scientific(draft));
  RecordProperty("late_speed", scientific(late_speed));
  RecordProperty("tilt", scientific(worst_tilt));
  EXPECT_GT(draft, 0) << "the box floats in the water, not above it";
  EXPECT_LT(draft, ratio * box_height + spacing) << "within a particle layer of its draft";
  EXPECT_LT(worst_tilt, 0.05) << "rad: the box stays upright";
  EXPECT_LT(late_speed, 0.1) << "m/s over 2-3 s: the box rides the waves, it does not bounce";
}

// A body that goes faster than the stability band stops the run with a message that names it,
// not a fluid particle: here the band is 0.02 c0 = 0.4 m/s and the box falls through the air
// above still water, reaching it after 0.04 s.
TEST(FloatingBody, BodyOutsideTheSpeedBandIsNamed) {
  scene::Scene s = floating_box();
  s.solver.max_mach_number = 0.02;
  scene::Box& box = std::get<scene::Box>(s.walls.obstacles[0].shape);
  box.min[1] += 0.1;
  box.max[1] += 0.1;
  Wcsph<2> simulation(s);
  try {
    while (simulation.time() < 0.1) simulation.step();
    FAIL() << "the falling box should leave the speed band";
  } catch (const InstabilityError& error) {
    EXPECT_NE(std::string(error.what()).find("walls.obstacles[0]"), std::string::npos) << error.what();
    EXPECT_EQ(error.field(), "speed");
    EXPECT_GT(error.value(), 0.4);
  }
}

// body.applied_force pulls at the centre of mass as gravity would: a box in air, away from the
// water, without gravity, gains F t / M, exactly as a body under g = F/M (velocity Verlet is exact
// for a constant force), and does not turn.
TEST(FloatingBody, AppliedForceAcceleratesTheBodyAsGravityWould) {
  scene::Scene s = floating_box();
  s.gravity = {0, 0, 0};
  scene::Obstacle& obstacle = s.walls.obstacles[0];
  std::get<scene::Box>(obstacle.shape).min[1] += 0.2;
  std::get<scene::Box>(obstacle.shape).max[1] += 0.2;
  scene::Body& box = *obstacle.body;
  box.applied_force = {3.0, 4.0, 0};
  const double mass = box.density * box_width * box_height;
  Wcsph<2> simulation(s);
  const RigidBody& body = simulation.bodies()->body(0);
  while (simulation.time() < 0.01) simulation.step();
  const double t = simulation.time();
  EXPECT_NEAR(body.velocity().x(), 3.0 / mass * t, 1e-9);
  EXPECT_NEAR(body.velocity().y(), 4.0 / mass * t, 1e-9);
  EXPECT_EQ(body.angular_velocity().z(), 0.0);
}

// No gravity, every axis periodic, fluid streaming past a disc at rest: the fluid's momentum
// Σ m_i v_i plus the body's M V stays what it was, to round-off, while the flow drags the disc.
scene::Scene periodic_box_with_disc() {
  scene::Scene s;
  s.source = "periodic box with a disc";
  s.dimension = 2;
  s.particle_spacing = 0.01;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 2.0});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {0.4, 0.4, 0}}, scene::Vec{0.5, 0.2, 0}});
  scene::Obstacle disc;
  disc.shape = scene::Ball{{0.2, 0.2, 0}, 0.06};
  disc.body = scene::Body{700, {}};
  s.walls.obstacles.push_back(disc);
  s.domain.box = {{0, 0, 0}, {0.4, 0.4, 0}};
  s.domain.periodic = {true, true, false};
  s.gravity = {0, 0, 0};
  s.solver.alpha = 0.1;
  return s;
}

void expect_momentum_conserved(const scene::Scene& s) {
  Wcsph<2> simulation(s);
  ASSERT_EQ(simulation.bodies()->size(), 1u);
  const auto momentum = [&] {
    const auto v = simulation.fluid()[simulation.fluid_fields().velocity];
    const auto m = simulation.fluid()[simulation.fluid_fields().mass];
    Eigen::Vector2d p = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < simulation.fluid().size(); ++i)
      p += static_cast<double>(m[i]) * Eigen::Vector2d(v[i][0], v[i][1]);
    const RigidBody& body = simulation.bodies()->body(0);
    return std::pair{p, Eigen::Vector2d(body.mass_properties().mass * body.velocity().head<2>())};
  };
  const auto [fluid_start, body_start] = momentum();
  for (int n = 0; n < 1000; ++n) simulation.step();
  const auto [fluid_end, body_end] = momentum();
  const double scale = fluid_start.norm();
  testing::Test::RecordProperty("momentum_error",
                                scientific((fluid_end + body_end - fluid_start - body_start).norm() / scale));
  EXPECT_GT(body_end.norm(), 1e-3 * scale) << "the flow drags the disc";
  // Each step adds the round-off of summing some 1 500 terms twice, in the particles' precision:
  // measured 3.4e-14 of |P| after 1 000 steps in double (150 ε), 9.8e-9 in float (0.08 ε).
  EXPECT_LT((fluid_end + body_end - fluid_start - body_start).norm(),
            1e4 * std::numeric_limits<Real>::epsilon() * scale);
}

TEST(FloatingBody, FluidAndBodyConserveMomentum) { expect_momentum_conserved(periodic_box_with_disc()); }

// The same with two fluids, oil of 800 kg/m³ over the lower half's water, in the number-density
// form of Hu & Adams 2006 (passes/body_force.hpp mirrors it), with laminar viscosity: the
// pressure and viscous forces between each fluid and the disc are equal and opposite too.
TEST(FloatingBody, TwoFluidsAndBodyConserveMomentum) {
  scene::Scene s = periodic_box_with_disc();
  s.materials[0].kinematic_viscosity = 1e-4;
  s.materials.push_back({"oil", 800, 1e-3, std::nullopt, 2.0});
  s.fluid.push_back({1, scene::Box{{0, 0.2, 0}, {0.4, 0.4, 0}}, scene::Vec{0.5, 0.2, 0}});
  s.solver.viscosity = scene::ViscosityModel::laminar;
  expect_momentum_conserved(s);
}

}  // namespace
}  // namespace tide
