// Multiphase flow and surface tension at low resolution in 2D, against the Laplace law, area
// conservation, Rayleigh–Taylor growth, Young's contact angle and exact per-phase mass
// conservation (refdata/analytic.md, sections 5, 6, 8 and 9).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "multiphase_scenes.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

struct DropletState {
  double inside_pressure = 0;   // mean over particles deeper than 2h inside the interface
  double outside_pressure = 0;  // mean over particles farther than 2h outside it
  double max_speed = 0;
};

DropletState measure_droplet(const Wcsph<2>& simulation, double radius) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto p = fluid[f.pressure];
  const double band = 2 * simulation.smoothing_length();
  DropletState state;
  int inside = 0, outside = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const double r = (x[i] - Vector<2>(0.5, 0.5)).norm();
    if (r < radius - band) {
      state.inside_pressure += p[i];
      ++inside;
    } else if (r > radius + band) {
      state.outside_pressure += p[i];
      ++outside;
    }
  }
  state.inside_pressure /= inside;
  state.outside_pressure /= outside;
  state.max_speed = simulation.max_speed();
  return state;
}

// Laplace law, 2D: Δp = σ/R (refdata/analytic.md, section 5). A drop of R = 8 and 12 Δx in a
// periodic box of the same density, csf tension, after 1 s (11 capillary times sqrt(ρR³/σ) at
// R = 0.2; the viscous decay time R²/ν is 0.8 s). Measured (double): Δp = 4.918 (−1.6%) at
// R = 0.2 and 3.301 (−1.0%) at R = 0.3; max spurious speed 0.035 and 0.023 m/s. The 5%
// bound holds; the spurious speeds are asserted below 0.05 m/s, 2.5e-3 of the capillary speed
// σ/μ = 20 m/s (Adami, Hu & Adams 2010 report spurious speeds of that order at this resolution).
TEST(Multiphase, LaplaceLawForTwoRadii) {
  for (const double radius : {0.2, 0.3}) {
    Wcsph<2> simulation(test::droplet_scene(radius));
    while (simulation.time() < 1.0) simulation.step();
    const DropletState state = measure_droplet(simulation, radius);
    const double jump = state.inside_pressure - state.outside_pressure;
    EXPECT_NEAR(jump, 1 / radius, 0.05 / radius) << "R = " << radius;
    EXPECT_LT(state.max_speed, 0.05) << "R = " << radius;
  }
}

// A square drop of side a = 0.3 relaxes to the circle of equal area, R = a/sqrt(π) = 0.1693
// (refdata/analytic.md, section 6; PySPH's square_droplet set-up at Δx = 1/40). After 1 s the
// outline (the farthest drop particle in each of 16 angular sectors, plus half a spacing) has a
// mean radius within 5% of R and varies by less than half a spacing between sectors, where the
// square varied by (sqrt(2) − 1) a/2 = 2.5 Δx. Measured (double): mean radius 0.16925 (−0.03%),
// spread 0.0043 (0.17 Δx); the pressure jump 5.974 against σ/R = 5.908 (+1.1%), asserted within
// the Laplace test's 5%.
TEST(Multiphase, SquareDropletRelaxesToAreaPreservingCircle) {
  const double side = 0.3;
  const double spacing = 1.0 / 40;
  Wcsph<2> simulation(test::droplet_scene(side / 2, true));
  while (simulation.time() < 1.0) simulation.step();
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto phase = fluid[f.phase];
  constexpr int sectors = 16;
  std::array<double, sectors> outline{};
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (phase[i] != 0) continue;
    const Vector<2> d = x[i] - Vector<2>(0.5, 0.5);
    const int k = std::min(
        sectors - 1, static_cast<int>((std::atan2(d[1], d[0]) + std::numbers::pi) / (2 * std::numbers::pi) * sectors));
    outline[k] = std::max(outline[k], d.norm() + spacing / 2);
  }
  const double expected = side / std::sqrt(std::numbers::pi);
  double mean = 0;
  for (const double r : outline) mean += r / sectors;
  const auto [low, high] = std::minmax_element(outline.begin(), outline.end());
  EXPECT_NEAR(mean, expected, 0.05 * expected);
  EXPECT_LT(*high - *low, spacing / 2);
  const DropletState state = measure_droplet(simulation, expected);
  EXPECT_NEAR(state.inside_pressure - state.outside_pressure, 1 / expected, 0.05 / expected);
}

// The number-density formulation keeps every particle's mass: the mass of each phase is the same
// number, bit for bit, after 200 steps of a drop in its ambient fluid, and so is the particle count.
TEST(Multiphase, MassOfEachPhaseIsConservedExactly) {
  Wcsph<2> simulation(test::droplet_scene(0.2, false, 2.0));
  const auto phase_mass = [&] {
    const auto& fluid = simulation.fluid();
    const auto& f = simulation.fluid_fields();
    std::array<double, 2> mass{};
    std::array<std::size_t, 2> count{};
    // Summed in id order, so the sum does not depend on the Morton order of the particles.
    std::vector<std::pair<Index, std::size_t>> by_id;
    for (std::size_t i = 0; i < fluid.size(); ++i) by_id.emplace_back(fluid[fluid.id()][i], i);
    std::sort(by_id.begin(), by_id.end());
    for (const auto& [id, i] : by_id) {
      mass[fluid[f.phase][i]] += fluid[f.mass][i];
      ++count[fluid[f.phase][i]];
    }
    return std::pair{mass, count};
  };
  const auto before = phase_mass();
  for (int k = 0; k < 200; ++k) simulation.step();
  const auto after = phase_mass();
  EXPECT_EQ(before.first, after.first);
  EXPECT_EQ(before.second, after.second);
  EXPECT_GT(before.second[0], 0u);
  EXPECT_GT(before.second[1], 0u);
}

// DESIGN.md, "Pipelines": a single-fluid scene allocates no phase or colour field and runs no
// tension pass; the multiphase csf scene has both, and each tension model its own passes.
TEST(Multiphase, SingleFluidSceneHasNoPhaseFieldsOrTensionPasses) {
  scene::Scene single = test::droplet_scene(0.2);
  single.fluid.pop_back();
  single.solver.surface_tension = {};
  const Wcsph<2> plain(single);
  for (const FieldInfo& field : plain.fluid().fields()) {
    EXPECT_NE(field.name, "phase");
    EXPECT_NE(field.name, "colour_gradient");
  }
  EXPECT_EQ(plain.phases(), nullptr);
  const std::vector<std::string_view> expected{
      "kick_drift", "neighbor_search", "density_summation", "wall_state", "momentum", "kick", "state_check"};
  EXPECT_EQ(plain.pipeline(), expected);

  const Wcsph<2> csf(test::droplet_scene(0.2));
  EXPECT_TRUE(csf.fluid().has("phase"));
  EXPECT_TRUE(csf.fluid().has("colour_gradient"));
  const auto& passes = csf.pipeline();
  EXPECT_NE(std::find(passes.begin(), passes.end(), "number_density"), passes.end());
  EXPECT_NE(std::find(passes.begin(), passes.end(), "continuum_surface_force"), passes.end());

  scene::Scene pairwise = single;
  pairwise.solver.surface_tension = {scene::SurfaceTensionModel::pairwise, 1.0, 90, 0};
  const Wcsph<2> pair(pairwise);
  EXPECT_FALSE(pair.fluid().has("colour_gradient"));
  EXPECT_FALSE(pair.fluid().has("phase"));
  EXPECT_NE(std::find(pair.pipeline().begin(), pair.pipeline().end(), "pairwise_surface_force"), pair.pipeline().end());
}

}  // namespace
}  // namespace tide
