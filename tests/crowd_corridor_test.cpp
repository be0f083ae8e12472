// The fundamental diagram of issue 36, case (a): mean speed against density in a periodic
// corridor, set against Weidmann 1993. The model has no term that slows a uniform crowd: its
// forces between agents are equal and opposite, so the crowd's mean velocity along the corridor
// relaxes to the mean desired velocity at every density. That is what this test asserts; the
// distance to Weidmann's curve is printed and reported in docs/crowds.md ("Fundamental
// diagram"), not asserted, since the model does not reproduce it yet.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "crowd_scenes.hpp"
#include "tide/solvers/crowd_sph.hpp"

namespace tide {
namespace {

// Weidmann 1993: v(ρ) = v0 (1 − exp(−γ (1/ρ − 1/ρ_max))), γ = 1.913 m⁻², ρ_max = 5.4 persons/m²
// (the constants of ../shared/refdata/crowd_weidmann.md, from a public implementation of it),
// with v0 = 1.34 m/s (issue 36).
double weidmann_speed(double density) { return 1.34 * (1 - std::exp(-1.913 * (1 / density - 1 / 5.4))); }

TEST(CrowdCorridor, MeanSpeedIsTheMeanDesiredSpeedAtEveryDensity) {
  const double length = 20, width = 4;
  double squared_error = 0;
  int densities = 0;
  // Up to 2.5 persons/m²: the square lattice the agents start on holds no more at a body
  // diameter (0.5 m) apart in this corridor.
  for (const std::size_t count : {40, 80, 120, 160, 200}) {
    CrowdSph crowd(test::crowd_corridor(count, length, width, 30));
    const ParticleSet<2>& agents = crowd.fluid();
    double desired = 0;
    for (const Real v0 : agents[crowd.desired_speed()]) desired += static_cast<double>(v0);
    desired /= static_cast<double>(agents.size());
    double speed_sum = 0;
    long samples = 0;
    while (crowd.time() < crowd.scene().time.end) {
      crowd.step();
      if (crowd.time() < 15) continue;  // 30 relaxation times after the start
      double along = 0;
      for (std::size_t i = 0; i < agents.size(); ++i)
        along += static_cast<double>(agents[crowd.fluid_fields().velocity][i][0]);
      speed_sum += along / static_cast<double>(agents.size());
      ++samples;
    }
    ASSERT_EQ(agents.size(), count);
    const double density = static_cast<double>(count) / (length * width);
    const double speed = speed_sum / static_cast<double>(samples);
    const double error = speed / weidmann_speed(density) - 1;
    squared_error += error * error;
    ++densities;
    std::printf(
        "density %.2f persons/m^2: mean speed %.4f m/s (mean desired %.4f, %+.4f%%), Weidmann %.4f m/s, %+.1f%%\n",
        density, speed, desired, 100 * (speed / desired - 1), weidmann_speed(density), 100 * error);
    // Measured: at most 0.0125% from the mean desired speed (2.5 persons/m²); only the walls'
    // nearest particles, a little ahead of or behind an agent, push along x. Bound 0.1%.
    EXPECT_NEAR(speed / desired, 1, 0.001) << density;
  }
  std::printf("root mean square error against Weidmann 1993: %.1f%%\n",
              100 * std::sqrt(squared_error / static_cast<double>(densities)));
}

}  // namespace
}  // namespace tide
