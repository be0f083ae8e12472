// Several fluids with the incompressible schemes (DFSPH, IISPH) at low resolution in 2D: the
// Rayleigh–Taylor instability against linear theory, two layers at rest against hydrostatics,
// exact per-phase mass, and what the schemes refuse.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "multiphase_measures.hpp"
#include "multiphase_scenes.hpp"
#include "tide/io/scene_reader.hpp"
#include "tide/solvers/incompressible_sph.hpp"

namespace tide {
namespace {

// Rayleigh–Taylor, density ratio 1.8 (refdata/analytic.md, section 8), the set-up and the bounds
// of the WCSPH test (multiphase_test.cpp, expect_rayleigh_taylor_growth). Measured (double),
// amplitude at 1 s and 2 s: DFSPH 0.216 and 0.370 (43 steps), IISPH 0.215 and 0.364 (46 steps),
// against WCSPH's 0.210 and 0.351 (1340 steps) and the inviscid bounds 0.286 and 1.03; effective
// rate 0.968 and 0.967 /s (0.83 of the viscous linear rate; WCSPH 0.958); fastest particle 0.30 and
// 0.43 m/s. Unchanged to three digits when the force number (the limit that sets these steps)
// changes by 1e-9 to 5e-9, and in float.
TEST(IncompressibleMultiphase, RayleighTaylorGrowsWithinLinearTheory) {
  for (const scene::Scheme scheme : {scene::Scheme::dfsph, scene::Scheme::iisph}) {
    scene::Scene scene = test::rayleigh_taylor_scene(0.04);
    scene.solver.scheme = scheme;
    IncompressibleSph<2> simulation(scene);
    test::expect_rayleigh_taylor_growth(simulation, scheme == scene::Scheme::dfsph ? "dfsph" : "iisph");
  }
}

// The shipped example scenes/rayleigh_taylor_2d.json is the set-up of the test above: the same
// particles, phases and walls, and the same first step.
TEST(IncompressibleMultiphase, ShippedRayleighTaylorSceneIsTheTestedSetUp) {
  const scene::Scene shipped =
      io::read_scene_file(std::filesystem::path(TIDE_SOURCE_SCENES_DIR) / "rayleigh_taylor_2d.json");
  scene::Scene tested = test::rayleigh_taylor_scene(0.04);
  tested.solver.scheme = scene::Scheme::dfsph;
  IncompressibleSph<2> a(shipped), b(tested);
  ASSERT_EQ(a.fluid().size(), b.fluid().size());
  ASSERT_EQ(a.interactions().contact_particle_count(), b.interactions().contact_particle_count());
  a.step();
  b.step();
  EXPECT_EQ(a.time(), b.time());
  for (std::size_t i = 0; i < a.fluid().size(); ++i) {
    ASSERT_EQ(a.fluid()[a.fluid_fields().phase][i], b.fluid()[b.fluid_fields().phase][i]) << i;
    ASSERT_EQ(a.fluid()[a.fluid_fields().position][i], b.fluid()[b.fluid_fields().position][i]) << i;
    ASSERT_EQ(a.fluid()[a.fluid_fields().velocity][i], b.fluid()[b.fluid_fields().velocity][i]) << i;
  }
}

// Two layers at rest in a closed 1 × 2 box: heavy fluid (ρ = ratio) below y = 1, light (ρ = 1)
// above, g = 1, equal ν = 0.01, Δx = 0.04, DFSPH for 7 s (155 steps). Asserted:
// - the pressure difference between the lattice rows at y = 0.3 and y = 1.7, 0.7 deep in each
//   layer and clear of the walls and the interface by more than a support, averaged over every
//   step from 4 s to 7 s, is the hydrostatic 0.7 g (ρ_heavy + ρ_light) within 5%. Measured
//   (double): +1.8% (ratio 3), +3.5% (ratio 10); the same box with one density through the same
//   passes, −1.5%; WCSPH at ratio 3 and 10, from the last step alone, +6.7% and +8.3%;
// - the largest speed over the run stays below 5% of the free-fall speed over the box,
//   sqrt(2 g Ly) = 2 m/s. Measured: 0.022 and 0.072 m/s (WCSPH: 0.10, its acoustic waves);
// - no particle ends more than a spacing across the interface. Measured: none.
TEST(IncompressibleMultiphase, LayersStayAtRestWithHydrostaticPressure) {
  const double spacing = 0.04;
  for (const double ratio : {3.0, 10.0}) {
    scene::Scene scene = test::closed_box_scene("layers", spacing, {"heavy", ratio, 0.01, 10.0, std::nullopt},
                                                {"light", 1, 0.01, 10.0, std::nullopt}, 1, 7);
    scene.fluid.push_back({0, scene::Box{{0, 0, 0}, {1, 1, 0}}});
    scene.gravity = {0, -1, 0};
    scene.solver.scheme = scene::Scheme::dfsph;
    IncompressibleSph<2> simulation(scene);
    double speed = 0, jump = 0;
    int samples = 0, crossed = 0;
    while (simulation.time() < scene.time.end) {
      simulation.step();
      speed = std::max(speed, double(simulation.max_speed()));
      if (simulation.time() < 4) continue;
      const auto& fluid = simulation.fluid();
      const auto& f = simulation.fluid_fields();
      double bottom = 0, top = 0;
      int bottom_count = 0, top_count = 0;
      crossed = 0;
      for (std::size_t i = 0; i < fluid.size(); ++i) {
        const double y = fluid[f.position][i][1];
        if (std::abs(y - 0.3) < spacing / 2) {
          bottom += fluid[f.pressure][i];
          ++bottom_count;
        } else if (std::abs(y - 1.7) < spacing / 2) {
          top += fluid[f.pressure][i];
          ++top_count;
        }
        const bool heavy = fluid[f.phase][i] == 0;
        if (heavy ? y > 1 + spacing : y < 1 - spacing) ++crossed;
      }
      jump += bottom / bottom_count - top / top_count;
      ++samples;
    }
    jump /= samples;
    const double expected = 0.7 * (ratio + 1);
    EXPECT_NEAR(jump, expected, 0.05 * expected) << "ratio " << ratio;
    EXPECT_LT(speed, 0.05 * 2.0) << "ratio " << ratio;
    EXPECT_EQ(crossed, 0) << "ratio " << ratio;
  }
}

// A single-fluid DFSPH scene has no phase field and sums density; two fluids add the phase
// field and the number-density stage, and no tension stage.
TEST(IncompressibleMultiphase, PipelineAndFieldsFollowThePhases) {
  scene::Scene two = test::rayleigh_taylor_scene(0.04);
  two.solver.scheme = scene::Scheme::dfsph;
  const IncompressibleSph<2> multiphase(two);
  EXPECT_TRUE(multiphase.fluid().has("phase"));
  EXPECT_NE(multiphase.phases(), nullptr);
  EXPECT_TRUE(multiphase.pipeline().contains("number_density"));
  EXPECT_FALSE(multiphase.pipeline().contains("density_summation"));

  scene::Scene one = two;
  for (scene::FluidBlock& block : one.fluid) block.material = 1;
  const IncompressibleSph<2> single(one);
  EXPECT_FALSE(single.fluid().has("phase"));
  EXPECT_EQ(single.phases(), nullptr);
  EXPECT_TRUE(single.pipeline().contains("density_summation"));
  EXPECT_FALSE(single.pipeline().contains("number_density"));
}

// What the incompressible schemes refuse, for a scene built without the reader: surface tension
// and fluids of more than max_incompressible_density_ratio.
TEST(IncompressibleMultiphase, RefusesTensionAndLargeDensityRatios) {
  scene::Scene tension = test::droplet_scene(0.2);
  tension.solver.scheme = scene::Scheme::dfsph;
  EXPECT_THROW(IncompressibleSph<2>{tension}, std::invalid_argument);
  scene::Scene bubble = test::rising_bubble_scene(0.05);
  bubble.solver.surface_tension = {};
  bubble.solver.scheme = scene::Scheme::iisph;
  EXPECT_THROW(IncompressibleSph<2>{bubble}, std::invalid_argument);
}

}  // namespace
}  // namespace tide
