// The contact line of the pairwise model in motion: a drop started as a half-disc on the floor
// relaxes to the contact angle its wall strengths set (Tartakovsky & Meakin 2005). The static
// side, Young's law on the lattice, is in contact_angle_test.cpp.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "multiphase_scenes.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

// The angle through the drop (degrees) where a circle fitted to its interface meets the floor
// y = 0. The interface points are the midpoints of drop–ambient pairs closer than 1.5Δx, above
// 2Δx (the rows next to the wall bend with the wall's own forces). Algebraic circle fit
// x² + y² + a x + b y + c = 0 by least squares (Kåsa 1976), centre (−a/2, −b/2).
double fitted_contact_angle(const Wcsph<2>& simulation, double spacing) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto phase = fluid[f.phase];
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (phase[i] != 0) continue;
    for (std::size_t j = 0; j < fluid.size(); ++j) {
      if (phase[j] == 0 || (x[i] - x[j]).norm() >= 1.5 * spacing) continue;
      const Eigen::Vector2d mid = (0.5 * (x[i] + x[j])).template cast<double>();
      if (mid[1] <= 2 * spacing) continue;
      const Eigen::Vector3d row(mid[0], mid[1], 1);
      normal += row * row.transpose();
      right -= row * mid.squaredNorm();
    }
  }
  const Eigen::Vector3d abc = normal.ldlt().solve(right);
  const double centre_x = -abc[0] / 2, centre_y = -abc[1] / 2;
  const double radius = std::sqrt(centre_x * centre_x + centre_y * centre_y - abc[2]);
  return std::acos(std::clamp(-centre_y / radius, -1.0, 1.0)) * 180 / std::numbers::pi;
}

// A drop of the area of a half-disc of radius 12Δx (Δx = 1/40) started as that half-disc (90°)
// in a 1.6 × 0.5 box, run `end` seconds with the strengths of `target`. Against the shared
// sessile-drop scene: support 5Δx (h = 2.5Δx, 5 wall layers) and no unlike attraction. Both
// lower the lattice stiffness of the pair-force fluid that pinned the contact line: with the
// support 4Δx and unlike attraction the drop stopped at 44.6°/134.4° (support 5Δx alone) or
// 37.2°/137.7° after 10 s (no unlike attraction alone) for 30°/150° (docs/multiphase.md).
double relaxed_angle(double target, double end) {
  const double spacing = 1.0 / 40;
  scene::Scene s = test::sessile_drop_scene(spacing, 12 * spacing, 90, target, 1.6, 0.5);
  s.smoothing_ratio = 2.5;
  s.walls.layers = 5;
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * spacing, 2);
  s.solver.surface_tension.unlike_attraction = false;
  Wcsph<2> simulation(s);
  while (simulation.time() < end) simulation.step();
  return fitted_contact_angle(simulation, spacing);
}

// The bound of 10°. Measured (double): 34.7° and 148.2° at 2 s (34.2° and 149.3° at 3 s),
// 90.2° at 1 s for 90°, which does not move from its start. What is left off the target is the
// remaining hysteresis: started at the target the drops stay at 29.6° and 150.1°, and the 90°
// strengths hold a drop started at 60° at 88.5° and one started at 120° at 92.8° (3 s); the fit
// itself scatters by about 1° between samples, and at 150° it moves by 13° per Δx of the floor's
// height (dθ = dy/(r sin θ), r = 8.6Δx), taken here at the wall's surface. 2 s is where the 30°
// drop has covered most of its way (44.7° at 0.5 s, 39.7° at 1 s); 10° leaves room for that last
// creep and the fit.
TEST(MultiphaseContactLine, HalfDiscDropSpreadsTo30Degrees) { EXPECT_NEAR(relaxed_angle(30, 2), 30, 10); }

TEST(MultiphaseContactLine, HalfDiscDropStaysAt90Degrees) { EXPECT_NEAR(relaxed_angle(90, 1), 90, 10); }

TEST(MultiphaseContactLine, HalfDiscDropRetractsTo150Degrees) { EXPECT_NEAR(relaxed_angle(150, 2), 150, 10); }

}  // namespace
}  // namespace tide
