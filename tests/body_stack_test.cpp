// Rigid bodies resting on each other and on a floor (solver.body_contact, body_contacts.hpp) in a
// WCSPH run: issue 35's validation (f), "the resting stack holds within 0.1 Δx".

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "tide/core/scene.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

constexpr double spacing = 0.01;

// A stack of two boxes (density 500 kg/m³) set down touching a tank's floor and each other, in
// air (a little water in a far corner, which the boxes never meet), settles at rest where it was
// put: the springs take the weight with an overlap of about g/ω² times the particles per contact,
// far less than the 0.1 Δx the issue allows, and nothing slides.
scene::Obstacle box_body(const scene::Box& box) {
  scene::Obstacle obstacle;
  obstacle.shape = box;
  obstacle.body = scene::Body{500, {}};
  return obstacle;
}

TEST(BodyStack, TwoBoxesRestOnTheFloor) {
  scene::Scene s;
  s.source = "stack";
  s.dimension = 2;
  s.particle_spacing = spacing;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 2.0});
  s.fluid.push_back({0, scene::Box{{0.5, 0, 0}, {0.6, 0.04, 0}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {0.6, 0.4, 0}}, true};
  s.walls.obstacles.push_back(box_body({{0.1, 0, 0}, {0.3, 0.1, 0}}));
  s.walls.obstacles.push_back(box_body({{0.15, 0.1, 0}, {0.25, 0.2, 0}}));
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * spacing, 2);
  s.gravity = {0, -9.81, 0};
  Wcsph<2> simulation(s);
  const RigidBodies<2>& bodies = *simulation.bodies();
  ASSERT_EQ(bodies.size(), 2u);
  const double start_lower = bodies.body(0).centre().y(), start_upper = bodies.body(1).centre().y();
  while (simulation.time() < 0.5) simulation.step();
  for (std::size_t k = 0; k < 2; ++k) {
    const RigidBody& body = bodies.body(k);
    const double start = k == 0 ? start_lower : start_upper;
    RecordProperty(k == 0 ? "lower_sink_m" : "upper_sink_m", std::to_string(start - body.centre().y()));
    RecordProperty(k == 0 ? "lower_speed" : "upper_speed", std::to_string(body.velocity().norm()));
    // Measured: the lower box sits 7.0e-5 m (0.007 Δx) and the upper 1.24e-4 m below where they were
    // put, both at rest (|v| < 1e-6 m/s) after 0.5 s.
    EXPECT_NEAR(body.centre().y(), start, 0.1 * spacing) << "box " << k;
    EXPECT_NEAR(body.centre().x(), 0.2, 1e-3 * spacing) << "box " << k;
    EXPECT_LT(body.velocity().norm(), 1e-3) << "box " << k;
    EXPECT_LT(std::abs(body.angular_velocity().z()), 1e-3) << "box " << k;
  }
  // The floor holds the whole weight: (0.02 + 0.01 m²) × 500 kg/m³ × g, per metre of depth.
  const double weight = 0.03 * 500 * 9.81;
  EXPECT_NEAR(bodies.contact_force(0).y() + bodies.contact_force(1).y(), weight, 0.02 * weight);
}

}  // namespace
}  // namespace tide
