// The shipped oil-displacement scenes (after Zhou et al. 2010; scripts/oil_scenes.py,
// docs/multiphase.md): water injected through the fracture displaces the cavity's oil at the
// injected volume flux, and each phase's mass changes only by the particles that cross the outflow.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>

#include "tide/io/scene_reader.hpp"
#include "tide/solvers/recovery.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

// The middle-fractured cavity (20 mm square, a 4 mm fracture 8 mm above its floor, Δx = 1 mm),
// run for 0.1 s. The inflow buffer drives the water in the fracture at U = 0.05 m/s; the fluids
// are nearly incompressible (Mach ≤ 0.05), so the oil leaves the cavity at the injected volume
// flux U w: after t, U w t / (20 mm)² of it, 0.05 at 0.1 s (20 of its 400 particles). Asserted
// within one column of the fracture's particles (w / Δx = 4, 0.01). No particle leaves the domain,
// and every particle has its phase's mass.
TEST(OilDisplacement, MiddleFracturedCavityYieldsItsOilAtTheInjectedFlux) {
  const scene::Scene scene =
      io::read_scene_file(std::filesystem::path(TIDE_SOURCE_SCENES_DIR) / "oil_middle_h8_horizontal_water_wet.json");
  ASSERT_TRUE(scene.output.recovery && scene.domain.inflow);
  Wcsph<2> simulation(scene);
  const RecoveryMeter<2> meter(simulation, *scene.output.recovery);
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const std::size_t particles = fluid.size();
  // 400 oil particles; a sum of n terms in Real is exact to (n − 1) ε of the sum.
  const double oil_mass = 400 * simulation.phases()->table[1].mass;
  EXPECT_NEAR(meter.initial_mass(), oil_mass, 400 * std::numeric_limits<Real>::epsilon() * oil_mass);
  while (simulation.time() < 0.1) simulation.step();
  const double cavity_area = 0.02 * 0.02, width = 0.004;
  const double expected = scene.domain.inflow->velocity * width * simulation.time() / cavity_area;
  EXPECT_NEAR(meter.recovery(meter.mass(simulation)), expected, 0.01);
  EXPECT_EQ(fluid.size(), particles);
  for (std::size_t i = 0; i < fluid.size(); ++i)
    EXPECT_EQ(fluid[f.mass][i], simulation.phases()->table[fluid[f.phase][i]].mass);
}

}  // namespace
}  // namespace tide
