// Pseudo-periodic inflow/outflow (scene key domain.inflow): the mass flux through a straight
// channel against mass conservation.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "inflow_scenes.hpp"
#include "tide/solvers/recovery.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

// The mass flux along x through the slab [centre − width/2, centre + width/2): Σ m_i u_i / width
// over the particles in it, the slab average of the flux density ρu integrated across the gap.
double mass_flux(const Wcsph<2>& simulation, double centre, double width) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  double flux = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const double x = fluid[f.position][i][0];
    if (std::abs(x - centre) < width / 2) flux += fluid[f.mass][i] * fluid[f.velocity][i][0];
  }
  return flux / width;
}

// The channel of inflow_channel_scene (Δx = 1/40, 400 particles) starts as a plug at U = 1; the
// buffer (x < 0.15) keeps driving it at U while the plates slow it. In a steady state mass
// conservation makes the flux the same through every section. Averaged over t = 5 … 6 s (the
// profile develops in (gap/2)²/ν = 1.6 s; at 2.5 … 3 s the sections were still 0.1–2.7% below the
// buffer), every 25 steps, the flux Σ m u / w through slabs w = 0.2 wide centred at x = 0.35, 0.55
// and 0.75, against the buffer's flux U × (its mass per unit length). Measured (double): 0.24488,
// 0.24451, 0.24481 against 0.24610 (−0.5% to −0.65%; counting the mass that crosses x = 0.075,
// 0.15, 0.55 and 0.9 gives 0.2442 to 0.2460, a spread of ±0.4% at 400 crossings in the second),
// asserted within 1.5%. The buffer's flux against U times the channel's mean mass per length
// M/L = 0.24872: measured −1.05%, asserted within 2%, the density difference that the Poiseuille
// pressure drop 12 μ U L / gap² = 1.9 Pa makes along the channel at c² = 100. No particle leaves.
TEST(Inflow, ChannelCarriesTheBuffersMassFlux) {
  const scene::Scene scene = test::inflow_channel_scene(1.0 / 40);
  Wcsph<2> simulation(scene);
  const auto& fluid = simulation.fluid();
  const std::size_t particles = fluid.size();
  double total_mass = 0;
  for (std::size_t i = 0; i < particles; ++i) total_mass += fluid[simulation.fluid_fields().mass][i];
  const double buffer = scene.domain.inflow->length, speed = scene.domain.inflow->velocity;
  const double length = scene.domain.box.max[0] - scene.domain.box.min[0];
  const std::array<double, 3> sections{0.35, 0.55, 0.75};
  std::array<double, 3> flux{};
  double buffer_flux = 0;
  int samples = 0;
  while (simulation.time() < 6) {
    simulation.step();
    if (simulation.time() < 5 || simulation.step_count() % 25 != 0) continue;
    for (std::size_t k = 0; k < sections.size(); ++k) flux[k] += mass_flux(simulation, sections[k], 0.2);
    buffer_flux += mass_flux(simulation, buffer / 2, buffer);
    ++samples;
  }
  ASSERT_GT(samples, 40);  // 49: every 25 steps of about 0.8 ms
  buffer_flux /= samples;
  EXPECT_NEAR(buffer_flux, speed * total_mass / length, 0.02 * buffer_flux);
  for (std::size_t k = 0; k < sections.size(); ++k)
    EXPECT_NEAR(flux[k] / samples, buffer_flux, 0.015 * buffer_flux) << "x = " << sections[k];
  EXPECT_EQ(fluid.size(), particles);
  EXPECT_TRUE(simulation.pipeline().contains("inflow_drift"));
  EXPECT_TRUE(simulation.pipeline().contains("inflow_velocity"));
}

// Water injection (domain.inflow.phase): the channel of inflow_channel_scene with free-slip
// plates, water (ρ0 = 1) in the buffer and oil (ρ0 = 0.8) downstream, all moving as a plug at
// U = 1. Every step, a particle whose phase changed must have been oil, now be water with the
// water's particle mass, and have just re-entered at the seam (within U Δt + Δx/2 of min x, the
// farthest a particle past max x lands after the wrap); no water becomes oil. The plug carries
// the oil across the outflow at the rate U × gap, so after t = 0.5 s the oil has lost
// U t gap / Δx² = 200 particles (measured: 200), asserted within one column of particles (gap / Δx = 10): the
// particles cross in columns. Mass per phase is then each phase's count times its particle mass,
// and the oil recovery of the channel (output.recovery) the share of the oil particles that crossed.
TEST(Inflow, InjectsItsPhaseAtTheSeamOnly) {
  const double spacing = 1.0 / 40;
  scene::Scene scene = test::inflow_channel_scene(spacing);
  scene.materials.push_back({"oil", 0.8, 0.01, 10.0, std::nullopt});
  scene.fluid.push_back({1, scene::Box{{0.15, 0, 0}, {1, 0.25, 0}}, scene::Vec{1, 0, 0}});
  scene.domain.inflow->phase = 0;
  scene.walls.slip = scene::WallSlip::free_slip;
  Wcsph<2> simulation(scene);
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const std::size_t particles = fluid.size();
  const Real water_mass = simulation.phases()->table[0].mass, oil_mass = simulation.phases()->table[1].mass;
  const auto count_oil = [&] {
    return static_cast<std::size_t>(std::count(fluid[f.phase].begin(), fluid[f.phase].end(), Index(1)));
  };
  const std::size_t initial_oil = count_oil();
  ASSERT_EQ(initial_oil, 340u);  // x in [0.15, 1): 34 columns of 10
  const RecoveryMeter<2> meter(simulation, scene::Recovery{1, scene.domain.box});
  std::vector<Index> phase_of(particles);
  const auto remember_phases = [&] {
    for (std::size_t i = 0; i < fluid.size(); ++i) phase_of[fluid[fluid.id()][i]] = fluid[f.phase][i];
  };
  remember_phases();
  std::size_t changes = 0;
  while (simulation.time() < 0.5) {
    const double dt = simulation.step().time_step.dt;
    ASSERT_EQ(fluid.size(), particles);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const Index before = phase_of[fluid[fluid.id()][i]], now = fluid[f.phase][i];
      EXPECT_EQ(fluid[f.mass][i], now == 0 ? water_mass : oil_mass);
      if (before == now) continue;
      ++changes;
      EXPECT_EQ(before, 1u);
      EXPECT_LT(fluid[f.position][i][0] - scene.domain.box.min[0], 1.0 * dt + spacing / 2);
    }
    remember_phases();
  }
  const double expected = 1.0 * simulation.time() * 0.25 / (spacing * spacing);
  EXPECT_EQ(changes, initial_oil - count_oil());
  // The oil recovered from the whole channel is the oil that crossed the outflow.
  EXPECT_NEAR(meter.recovery(meter.mass(simulation)), static_cast<double>(changes) / initial_oil, 1e-12);
  EXPECT_NEAR(static_cast<double>(changes), expected, 0.25 / spacing);
  EXPECT_TRUE(simulation.pipeline().contains("inflow_phase"));
}

}  // namespace
}  // namespace tide
