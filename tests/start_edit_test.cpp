// Simulation::edit_start: the starting fields set before the first step, from which the scheme
// starts again (the tidesph module's set_fields; python/tests/test_fields.py checks it from Python).

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "small_scenes.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

// Continuity density keeps the density it is given; the start computes each particle's pressure
// from it by the scheme's own equation of state, exactly (the same expression, the same bits).
TEST(EditStart, PressureFollowsTheDensitySet) {
  scene::Scene s = small_dam_break_2d();
  s.solver.density = scene::DensityMethod::continuity;
  Wcsph<2> simulation(s);
  const FluidFields<2>& f = simulation.fluid_fields();
  simulation.edit_start([&](ParticleSet<2>& fluid) {
    const auto y = fluid[f.position];
    const auto rho = fluid[f.density];
    for (std::size_t i = 0; i < fluid.size(); ++i) rho[i] = Real(1000) * (1 + Real(0.01) * y[i][1] / Real(0.4));
  });
  const auto& fluid = simulation.fluid();
  const auto y = fluid[f.position];
  const auto rho = fluid[f.density];
  const auto p = fluid[f.pressure];
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    ASSERT_EQ(rho[i], Real(1000) * (1 + Real(0.01) * y[i][1] / Real(0.4))) << i;
    ASSERT_EQ(p[i], simulation.equation_of_state().pressure(rho[i])) << i;
  }
}

// Starting again from the fields a scheme starts with is its start: the same bits 20 steps on.
TEST(EditStart, TheSameFieldsGiveTheSameRun) {
  for (const scene::Scheme scheme : {scene::Scheme::wcsph, scene::Scheme::dfsph, scene::Scheme::iisph}) {
    scene::Scene s = small_dam_break_2d();
    s.solver.scheme = scheme;
    const auto plain = make_simulation<2>(s);
    const auto edited = make_simulation<2>(s);
    edited->edit_start([](ParticleSet<2>&) {});
    for (int k = 0; k < 20; ++k) {
      plain->step();
      edited->step();
    }
    StateArchive a, b;
    plain->save(a);
    edited->save(b);
    for (const auto& [path, values] : a.all_reals()) {
      const auto& other = b.all_reals().at(path);
      ASSERT_EQ(values.size(), other.size()) << path;
      EXPECT_TRUE(values.empty() || std::memcmp(values.data(), other.data(), values.size() * sizeof(Real)) == 0)
          << scheme_name(scheme) << ": " << path;
    }
  }
}

TEST(EditStart, OnlyBeforeTheFirstStepAndWithTheSameCount) {
  Wcsph<2> simulation(small_dam_break_2d());
  EXPECT_THROW(simulation.edit_start([](ParticleSet<2>& fluid) { fluid.append(1); }), std::logic_error);
  simulation.step();
  EXPECT_THROW(simulation.edit_start([](ParticleSet<2>&) {}), std::logic_error);
}

}  // namespace
}  // namespace tide
