// Multiphase flow and surface tension at low resolution in 2D, against the Laplace law (csf and
// pairwise), area conservation, Rayleigh–Taylor linear theory and exact per-phase mass
// conservation (refdata/analytic.md, sections 5, 6 and 8).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "multiphase_measures.hpp"
#include "multiphase_scenes.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

using test::DropletState;
using test::measure_droplet;
using test::phase_totals;

// Laplace law, 2D: Δp = σ/R (refdata/analytic.md, section 5). A drop of R = 8 and 12 Δx in a
// periodic box of the same density, csf tension, after 1 s (11 capillary times sqrt(ρR³/σ) at
// R = 0.2; the viscous decay time R²/ν is 0.8 s). Measured (double): Δp = 4.918 (−1.6%) at
// R = 0.2 and 3.301 (−1.0%) at R = 0.3; max spurious speed 0.035 and 0.023 m/s. The 5%
// bound holds; the spurious speeds are asserted below 0.05 m/s, 2.5e-3 of the capillary speed
// σ/μ = 20 m/s (Adami, Hu & Adams 2010 report spurious speeds of that order at this resolution).
// Not yet an equilibrium value: the jump keeps drifting after 1 s (−11% to −16% between 2.5 and
// 4 s at R = 0.2) and is not converged in Δx (docs/multiphase.md, the csf study), so this guards
// the set-up at t = 1 s; the time-converged Laplace law for csf is open (issue 7).
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

// The pairwise model's pressure is the SPH pressure plus the virial of the pair forces
// (Irving & Kirkwood 1950): P_i = p_i + (n_i/(2D)) Σ_j r_ij F_ij, F_ij = s_ab cos(3π r_ij/(2R)),
// n_i = ρ_i/m_i. Returns its jump between the particles deeper than 2h inside the drop of `radius`
// and those farther than 2h outside it, by a brute-force pair sum over the periodic unit box.
double pairwise_pressure_jump(const Wcsph<2>& simulation, double radius) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto p = fluid[f.pressure];
  const auto density = fluid[f.density];
  const auto mass = fluid[f.mass];
  const auto phase = fluid[f.phase];
  const double support = std::visit([](const auto& k) { return double(k.support_radius()); }, simulation.kernel());
  const double wave = 1.5 * std::numbers::pi / support;
  const double band = 2 * simulation.smoothing_length();
  std::array<double, 2> sum{};
  std::array<int, 2> count{};
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const double r = (x[i] - Vector<2>(0.5, 0.5)).norm();
    if (r > radius - band && r < radius + band) continue;
    double virial = 0;
    for (std::size_t j = 0; j < fluid.size(); ++j) {
      Vector<2> d = x[i] - x[j];
      for (int k = 0; k < 2; ++k) d[k] = d[k] > 0.5 ? d[k] - 1 : (d[k] < -0.5 ? d[k] + 1 : d[k]);
      if (j == i || std::abs(d[0]) >= support || std::abs(d[1]) >= support) continue;
      const double r_ij = d.norm();
      if (r_ij >= support) continue;
      virial += r_ij * simulation.pair_strength(phase[i], phase[j]) * std::cos(wave * r_ij);
    }
    const int side = r < radius ? 0 : 1;
    sum[side] += p[i] + density[i] / mass[i] / 4 * virial;
    ++count[side];
  }
  return sum[0] / count[0] - sum[1] / count[1];
}

// Laplace law (refdata/analytic.md, section 5) for the pairwise model of Tartakovsky & Meakin 2005,
// the drop of the csf test (R = 0.2, Δx = 1/40, equal densities, σ = 1). Two choices keep it whole:
// - the support R = 4Δx (h = 2Δx): with the kernel's 3Δx the nearest neighbours sit at the zero of
//   the force, R/3 = Δx, nothing resists the cohesion between them and the drop clumped and failed
//   the density check within 35 steps;
// - a background pressure 150 above the bulk virial pressure of the pair forces (−67 here): with
//   60 the bulk is in tension (total −7) and the lattice disorders.
// The jump of the total pressure oscillates with the drop's capillary mode (4.4 to 5.0 between 1 s
// and 2 s), so it is averaged over that second, every 50 steps. Measured (double): 4.78 (−4.4%)
// against σ/R = 5; within the 5% of the csf test. (With background pressure 300 it is 4.66, −6.9%;
// the SPH part alone is 6.3, +25%, since the denser drop has a more negative virial.)
TEST(Multiphase, PairwiseLaplaceLaw) {
  const double radius = 0.2;
  scene::Scene scene = test::droplet_scene(radius);
  scene.smoothing_ratio = 2;
  scene.solver.background_pressure = 150;
  scene.solver.surface_tension = {scene::SurfaceTensionModel::pairwise, 1.0, 90, 0};
  Wcsph<2> simulation(scene);
  double jump = 0;
  int samples = 0;
  while (simulation.time() < 2.0) {
    simulation.step();
    if (simulation.time() > 1.0 && simulation.step_count() % 50 == 0) {
      jump += pairwise_pressure_jump(simulation, radius);
      ++samples;
    }
  }
  EXPECT_NEAR(jump / samples, 1 / radius, 0.05 / radius);
  EXPECT_GT(samples, 20);
}

// The number-density formulation keeps every particle's mass: the mass of each phase is the same
// number, bit for bit, after 200 steps of a drop in its ambient fluid, and so is the particle count.
TEST(Multiphase, MassOfEachPhaseIsConservedExactly) {
  Wcsph<2> simulation(test::droplet_scene(0.2, false, 2.0));
  const auto before = phase_totals(simulation);
  for (int k = 0; k < 200; ++k) simulation.step();
  const auto after = phase_totals(simulation);
  EXPECT_EQ(before.first, after.first);
  EXPECT_EQ(before.second, after.second);
  EXPECT_GT(before.second[0], 0u);
  EXPECT_GT(before.second[1], 0u);
}

// Rayleigh–Taylor instability, density ratio 1.8 (refdata/analytic.md, section 8) at Δx = 0.04
// (1250 particles) until t = 2, against the linear theory of expect_rayleigh_taylor_growth.
// Measured (double), every 0.25 s: a0 = 0.140, then 0.144, 0.163, 0.183, 0.210, 0.238, 0.273,
// 0.311, 0.351 at t = 2 s, against the inviscid bounds 0.286 at 1 s and 1.03 at 2 s; the effective
// rate 0.958 /s (0.82 of the viscous linear rate). The amplitude grows at every sample; the
// fastest particle, 0.29 m/s, stays far below the free-fall speed over the box height
// sqrt(2 g Ly) = 2 m/s; no particle is lost and each phase keeps its mass exactly.
TEST(Multiphase, RayleighTaylorGrowsWithinLinearTheory) {
  Wcsph<2> simulation(test::rayleigh_taylor_scene(0.04));
  test::expect_rayleigh_taylor_growth(simulation, "wcsph");
}

// A 1000:1 bubble: the second rising-bubble case of Hysing et al. 2009 (air, ρ = 1 and μ = 0.1, of
// radius R = 0.25 at (0.5, 0.5) in water, ρ = 1000 and μ = 10, in a closed 1 × 2 box, g = 0.98,
// σ = 1.96, csf) at Δx = 0.05 (800 particles) until t = 1, sampled every 0.1 s. What is asserted:
// - it rises: the air's centroid ends more than 2Δx above where it started (the start-up
//   compression under the ramped gravity first lowers it by 0.007). Measured (double): +0.148;
// - its mean velocity stays below what buoyancy alone can give it: a cylinder's added mass is the
//   displaced mass (Lamb, Hydrodynamics, §68), so it accelerates at most at g (ρw − ρa)/(ρw + ρa) < g,
//   and with gravity ramped over t_r, v(t) ≤ g (t − t_r/2). Measured: the largest rise speed 0.351
//   at 0.6 s, where the bound is 0.54;
// - it stays one body (no blow-up, no flung air): every air particle within 1.5 R of the centroid.
//   Measured: 1.22 R at 1 s;
// - no particle is lost and each phase keeps its mass exactly.
TEST(Multiphase, HeavyToLightBubbleRisesAndStaysBounded) {
  const double spacing = 0.05, radius = 0.25, g = 0.98;
  const scene::Scene scene = test::rising_bubble_scene(spacing);
  Wcsph<2> simulation(scene);
  const auto air = [&] {
    const auto& fluid = simulation.fluid();
    const auto& f = simulation.fluid_fields();
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero(), velocity = Eigen::Vector2d::Zero();
    int count = 0;
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      if (fluid[f.phase][i] != 1) continue;
      centroid += fluid[f.position][i].template cast<double>();
      velocity += fluid[f.velocity][i].template cast<double>();
      ++count;
    }
    centroid /= count;
    double spread = 0;
    for (std::size_t i = 0; i < fluid.size(); ++i)
      if (fluid[f.phase][i] == 1)
        spread = std::max(spread, (fluid[f.position][i].template cast<double>() - centroid).norm());
    return std::tuple{centroid[1], velocity[1] / count, spread};
  };
  const auto before = phase_totals(simulation);
  const double start = std::get<0>(air());
  const double ramp = scene.solver.gravity_ramp_time;
  double end = start;
  for (int k = 1; k <= 10; ++k) {
    while (simulation.time() < 0.1 * k) simulation.step();
    const auto [height, rise_speed, spread] = air();
    EXPECT_LT(rise_speed, g * (simulation.time() - ramp / 2)) << "t = " << simulation.time();
    EXPECT_LT(spread, 1.5 * radius) << "t = " << simulation.time();
    end = height;
  }
  EXPECT_GT(end - start, 2 * spacing);
  EXPECT_EQ(before, phase_totals(simulation));
}

// A single-fluid scene allocates no phase or colour field and runs no tension stage; the
// multiphase csf scene has both, and each tension model its own stage.
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
  // The droplet's box is periodic without walls: no wall_state stage either.
  const std::vector<std::string_view> expected{
      "kick_drift", "neighbor_search+density_summation", "momentum", "kick", "advance_time", "state_check"};
  EXPECT_EQ(plain.pipeline().names(), expected);

  const Wcsph<2> csf(test::droplet_scene(0.2));
  EXPECT_TRUE(csf.fluid().has("phase"));
  EXPECT_TRUE(csf.fluid().has("colour_gradient"));
  EXPECT_TRUE(csf.pipeline().contains("neighbor_search+number_density"));
  EXPECT_TRUE(csf.pipeline().contains("colour_gradient+continuum_surface_force"));

  scene::Scene pairwise = single;
  pairwise.solver.surface_tension = {scene::SurfaceTensionModel::pairwise, 1.0, 90, 0};
  const Wcsph<2> pair(pairwise);
  EXPECT_FALSE(pair.fluid().has("colour_gradient"));
  EXPECT_FALSE(pair.fluid().has("phase"));
  EXPECT_TRUE(pair.pipeline().contains("pairwise_surface_force"));
}

}  // namespace
}  // namespace tide
