// The fundamental diagram of issue 36, case (a): mean speed against density in a periodic
// corridor, set against Weidmann 1993. An agent walks no faster than the space to the agent
// ahead of it allows (the collision-free speed model's V(s), docs/crowds.md, "Model"), so the
// crowd slows as it thickens; the model does not reproduce Weidmann's curve (root mean square
// error 53% over 0.5-3.4 persons/m², docs/crowds.md, "Fundamental diagram"), so what this test
// asserts is the shape a fundamental diagram has, with the distance to Weidmann printed.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "crowd_scenes.hpp"
#include "tide/solvers/crowd_sph.hpp"

namespace tide {
namespace {

// Weidmann 1993: v(ρ) = v0 (1 − exp(−γ (1/ρ − 1/ρ_max))), γ = 1.913 m⁻², ρ_max = 5.4 persons/m²
// (the constants of ../shared/refdata/crowd_weidmann.md, from a public implementation of it),
// with v0 = 1.34 m/s (issue 36).
double weidmann_speed(double density) { return 1.34 * (1 - std::exp(-1.913 * (1 / density - 1 / 5.4))); }

TEST(CrowdCorridor, MeanSpeedFallsWithDensity) {
  const double length = 20, width = 4;
  double squared_error = 0;
  std::vector<double> speeds;
  // Up to 2 persons/m² the agents start at random places (random sequential addition), above
  // it on a hexagonal lattice, which holds 273 a body diameter (0.5 m) apart in this corridor:
  // 3.4 persons/m².
  for (const std::size_t count : {40, 80, 120, 160, 200, 240, 272}) {
    CrowdSph crowd(test::crowd_corridor(count, length, width, 30, count <= 160 ? "random" : "lattice"));
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
    std::printf(
        "density %.2f persons/m^2: mean speed %.4f m/s (mean desired %.4f, %+.1f%%), Weidmann %.4f m/s, %+.1f%%\n",
        density, speed, desired, 100 * (speed / desired - 1), weidmann_speed(density), 100 * error);
    // Measured: 0.886 m/s at 0.5 persons/m², 36% below the mean desired speed: the agent ahead
    // in one's way is often near enough to slow one, V(s) = (s − ℓ)/T < v0 for s < 1.84 m.
    EXPECT_LT(speed, desired) << density;
    EXPECT_GT(speed, 0) << density;
    speeds.push_back(speed);
  }
  // Measured: 0.886, 0.619, 0.406, 0.388, 0.244, 0.112, 0.043 m/s (bound: each slower than the
  // one before).
  for (std::size_t k = 1; k < speeds.size(); ++k) EXPECT_LT(speeds[k], speeds[k - 1]) << k;
  std::printf("root mean square error against Weidmann 1993: %.1f%%\n",
              100 * std::sqrt(squared_error / static_cast<double>(speeds.size())));
}

}  // namespace
}  // namespace tide
