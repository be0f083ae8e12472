// Two independent wall contacts from one scene: a channel whose lower plate is free-slip (the
// scene's walls.slip) and whose upper plate, an obstacle with "slip": "no_slip", drags the fluid.
// With no shear at the lower plate, the start-up flow tends to a plug at the plate's speed; had
// the upper plate's slip not reached its own contact, or the lower plate's leaked into it, the
// flow would be the linear Couette profile (no-slip both sides) or never start (free-slip both).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "tide/core/scene.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide {
namespace {

constexpr double gap = 1e-3;            // m between the plates
constexpr double viscosity = 1e-6;      // m²/s
constexpr double plate_speed = 2.5e-5;  // m/s, as in Morris, Fox & Zhu 1997's Couette case

// u(y, t) of the fluid at rest at t = 0 under a plate at y = L set moving at U, above a plane of
// no shear at y = 0 (∂u/∂y = 0): u = U − Σ_n 4U/((2n+1)π) (−1)^n cos(k_n y) exp(−ν k_n² t),
// k_n = (2n+1)π/(2L), the separable solution of the diffusion equation with those conditions.
double plug_start_up_speed(double y, double t) {
  double u = plate_speed;
  for (int n = 0; n < 200; ++n) {
    const double k = (2 * n + 1) * std::numbers::pi / (2 * gap);
    u -= 4 * plate_speed / ((2 * n + 1) * std::numbers::pi) * (n % 2 == 0 ? 1 : -1) * std::cos(k * y) *
         std::exp(-viscosity * k * k * t);
  }
  return u;
}

// Ten particles across the gap, periodic along it, laminar viscosity; the lower plate takes the
// scene's walls.slip, the upper one `upper_slip`.
scene::Scene channel(scene::WallSlip walls_slip, std::optional<scene::WallSlip> upper_slip) {
  scene::Scene s;
  s.source = "two-contact channel";
  s.dimension = 2;
  s.particle_spacing = gap / 10;
  s.materials.push_back({"water", 1000, viscosity, std::nullopt, plate_speed});
  const double length = s.particle_spacing * 12;
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {length, gap, 0}}});
  const double thickness = s.walls.layers * s.particle_spacing;
  s.walls.slip = walls_slip;
  s.walls.obstacles.push_back({scene::Plane{{0, 0, 0}, {0, 1, 0}}, {}, std::nullopt, std::nullopt, std::nullopt});
  s.walls.obstacles.push_back(
      {scene::Plane{{0, gap, 0}, {0, -1, 0}}, {plate_speed, 0, 0}, upper_slip, std::nullopt, std::nullopt});
  s.domain.box = {{0, -thickness, 0}, {length, gap + thickness, 0}};
  s.domain.periodic = {true, false, false};
  s.gravity = {0, 0, 0};
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  return s;
}

// The largest |u − u_exact| / U over the fluid at the simulation's time.
double largest_deviation(const Simulation<2>& simulation, double (*exact)(double, double)) {
  const auto x = simulation.fluid()[simulation.fluid_fields().position];
  const auto v = simulation.fluid()[simulation.fluid_fields().velocity];
  double largest = 0;
  for (std::size_t i = 0; i < simulation.fluid().size(); ++i)
    largest = std::max(largest, std::abs(v[i][0] - exact(x[i][1], simulation.time())) / plate_speed);
  return largest;
}

void run_until(Simulation<2>& simulation, double end) {
  while (simulation.time() < end) simulation.step();
}

TEST(WallContacts, AnObstacleWithItsOwnSlipIsASecondContact) {
  const auto simulation = make_simulation<2>(channel(scene::WallSlip::free_slip, scene::WallSlip::no_slip));
  const Interactions<2>& interactions = simulation->interactions();
  ASSERT_EQ(interactions.contact_count(), 2u);
  EXPECT_EQ(interactions.contact(0).name(), "walls");
  EXPECT_FALSE(interactions.contact(0).viscous()) << "the lower plate keeps the scene's free slip";
  EXPECT_EQ(interactions.contact(1).name(), "no-slip walls");
  EXPECT_TRUE(interactions.contact(1).viscous());
  EXPECT_TRUE(interactions.contact(1).fields().surface_velocity.has_value()) << "the upper plate moves";
  EXPECT_FALSE(interactions.contact(0).fields().surface_velocity.has_value()) << "the lower plate does not";

  const auto single = make_simulation<2>(channel(scene::WallSlip::free_slip, std::nullopt));
  ASSERT_EQ(single->interactions().contact_count(), 1u);
  EXPECT_EQ(single->interactions().contact(0).particles().size(), interactions.contact_particle_count())
      << "the same wall particles, split by slip";
}

// The flow under a no-slip plate above a free-slip one becomes a plug at the plate's speed. The
// analytic deviation from it is 4/π e^(−ν k_0² t) U at most: 0.08% at t = 3 s. The bound, 1%,
// holds if the discrete slowest mode decays at least 65% as fast as the analytic one (the
// Laplacian next to the free-slip plate sees one side of the kernel only); a no-slip lower plate
// would leave the linear Couette profile, 100% off at the plate.
TEST(WallContacts, FreeSlipBelowANoSlipPlateGivesPlugFlow) {
  const auto simulation = make_simulation<2>(channel(scene::WallSlip::free_slip, scene::WallSlip::no_slip));
  run_until(*simulation, 3.0);
  EXPECT_LT(largest_deviation(*simulation, plug_start_up_speed), 0.01);
}

// The same channel with the scene's slip on both plates: one no-slip contact, and the linear
// Couette profile u = U y/L, far from the plug (the test above can fail).
TEST(WallContacts, NoSlipOnBothPlatesGivesCouetteFlow) {
  const auto simulation = make_simulation<2>(channel(scene::WallSlip::no_slip, std::nullopt));
  ASSERT_EQ(simulation->interactions().contact_count(), 1u);
  run_until(*simulation, 3.0);
  EXPECT_GT(largest_deviation(*simulation, plug_start_up_speed), 0.5);
  EXPECT_LT(largest_deviation(*simulation, [](double y, double) { return plate_speed * y / gap; }), 0.05);
}

}  // namespace
}  // namespace tide
