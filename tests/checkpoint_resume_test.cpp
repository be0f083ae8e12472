// A resumed run continues exactly as if it had never stopped (issue 39): for every scheme and
// optional feature, N steps straight against N/2 steps, a checkpoint file, a fresh simulation
// restored from it and N/2 more, under 1 and under 2 threads. The final states are compared
// whole, every entry save() puts (every field of the fluid and of every contact, the bodies'
// motion, the schemes' scalars and counts), byte for byte.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "inflow_scenes.hpp"
#include "multiphase_scenes.hpp"
#include "small_scenes.hpp"
#include "tide/core/parallel.hpp"
#include "tide/io/checkpoint_file.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/validation/crowd_scenes.hpp"

namespace tide {
namespace {

namespace fs = std::filesystem;

// The small dam break with a skin first re-sorts between steps 61 and 70 and again by step 90
// (measured): 150 steps put the checkpoint at step 75, after a rebuild and before the next, so the
// resumed lists must be those of a build the fresh simulation never made.
struct ResumeCase {
  std::string name;
  std::function<scene::Scene()> scene;
  int steps = 150;
};

template <int D>
StateArchive state_of(const Simulation<D>& simulation) {
  StateArchive archive;
  simulation.save(archive);
  return archive;
}

template <class Map>
void expect_same_entries(const Map& straight, const Map& resumed) {
  ASSERT_EQ(straight.size(), resumed.size());
  for (const auto& [path, values] : straight) {
    const auto other = resumed.find(path);
    ASSERT_NE(other, resumed.end()) << path;
    ASSERT_EQ(values.size(), other->second.size()) << path;
    if (values.empty()) continue;  // memcmp may not be given the null data() of an empty vector
    EXPECT_EQ(std::memcmp(values.data(), other->second.data(), values.size() * sizeof(values[0])), 0)
        << path << " differs after the resume";
  }
}

void expect_same_state(const StateArchive& straight, const StateArchive& resumed) {
  expect_same_entries(straight.all_reals(), resumed.all_reals());
  expect_same_entries(straight.all_doubles(), resumed.all_doubles());
  expect_same_entries(straight.all_counts(), resumed.all_counts());
}

// `steps` steps straight against steps / 2, a checkpoint file, a fresh simulation restored from
// it and the rest, resumed under 1 and under 2 threads.
template <int D>
void expect_resume_bit_for_bit(const scene::Scene& scene, int steps, const std::string& name) {
  const int half = steps / 2;
  const fs::path file = fs::path(testing::TempDir()) / ("checkpoint_resume_" + name + ".h5");
  const io::CheckpointIdentity identity{io::checkpoint_format_version, "test scene", "any", D, {}};

  StateArchive straight;
  {
    const ThreadLimit limit(1);
    const auto simulation = make_simulation<D>(scene);
    for (int k = 0; k < half; ++k) simulation->step();
    io::write_checkpoint(file, identity, simulation->step_count(), simulation->time(), state_of(*simulation));
    for (int k = half; k < steps; ++k) simulation->step();
    straight = state_of(*simulation);
  }
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    const ThreadLimit limit(threads);
    const auto simulation = make_simulation<D>(scene);
    simulation->restore(io::read_checkpoint(file, identity));
    EXPECT_EQ(simulation->step_count(), static_cast<std::uint64_t>(half));
    for (int k = half; k < steps; ++k) simulation->step();
    expect_same_state(straight, state_of(*simulation));
  }
  fs::remove(file);
}

class CheckpointResume : public testing::TestWithParam<ResumeCase> {};

TEST_P(CheckpointResume, ContinuesBitForBit) {
  const ResumeCase& c = GetParam();
  expect_resume_bit_for_bit<2>(c.scene(), c.steps, c.name);
}

// In 3D: a 5 × 5 × 10 column carrying a light box (the bodies' quaternion and angular momentum),
// 150 steps.
TEST(CheckpointResume3D, DamBreakWithABodyContinuesBitForBit) {
  scene::Scene s;
  s.source = "small 3D dam break";
  s.dimension = 3;
  s.particle_spacing = 0.02;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 2.0});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {0.1, 0.1, 0.2}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {0.3, 0.1, 0.3}}, true};
  s.domain.box = {{-0.08, -0.08, -0.08}, {0.38, 0.18, 0.6}};
  s.gravity = {0, 0, -9.81};
  scene::Obstacle box;
  box.shape = scene::Box{{0.02, 0.02, 0.12}, {0.08, 0.08, 0.16}};
  box.body = scene::Body{400, {}};
  s.walls.obstacles.push_back(box);
  expect_resume_bit_for_bit<3>(s, 150, "dam_break_3d");
}

scene::Scene wcsph(scene::DensityMethod density, scene::Shifting shifting, double delta_sph = 0.1,
                   double artificial_stress = 0) {
  scene::Scene s = small_dam_break_2d();
  s.solver.density = density;
  s.solver.shifting = shifting;
  s.solver.delta_sph = delta_sph;
  s.solver.artificial_stress = artificial_stress;
  s.solver.clamp_negative_pressure = artificial_stress == 0;
  return s;
}

scene::Scene incompressible(scene::Scheme scheme, double skin,
                            scene::PressureSolver solver = scene::PressureSolver::jacobi) {
  scene::Scene s = small_dam_break_2d();
  s.solver.scheme = scheme;
  s.solver.neighbor_skin = skin;
  s.solver.pressure_solver = solver;
  return s;
}

scene::Scene droplet(scene::SurfaceTensionModel model) {
  scene::Scene s = test::droplet_scene(0.2, false, 2.0);
  s.solver.surface_tension.model = model;
  // As in thread_determinism_test: coefficients that keep this drop together.
  if (model == scene::SurfaceTensionModel::akinci) s.solver.surface_tension.coefficient = 0.1;
  if (model == scene::SurfaceTensionModel::pairwise) s.solver.surface_tension.coefficient = 0.01;
  return s;
}

scene::Scene with_paddle(scene::Scheme scheme) {
  scene::Scene s = small_dam_break_with_paddle_2d();
  s.solver.scheme = scheme;
  return s;
}

// A light box released inside the column, so that it moves from the first step.
scene::Scene with_body() {
  scene::Scene s = small_dam_break_2d();
  scene::Obstacle box;
  box.shape = scene::Box{{0.05, 0.25, 0}, {0.15, 0.29, 0}};
  box.body = scene::Body{400, {}};
  s.walls.obstacles.push_back(box);
  return s;
}

// 220 agents, 20 of them by the door, some out through it within the 400 steps (2 s).
scene::Scene crowd() {
  validation::CrowdRoom room;
  room.length = 30;
  room.width = 20;
  room.agents = R"([{"region": {"min": [1, 1], "max": [10, 19]}, "count": 200},
                    {"region": {"min": [27, 8], "max": [29.5, 12]}, "count": 20}])";
  return validation::crowd_room(room);
}

using scene::DensityMethod;
using scene::PressureSolver;
using scene::Scheme;
using scene::Shifting;
using scene::SurfaceTensionModel;

INSTANTIATE_TEST_SUITE_P(
    EverySchemeAndFeature, CheckpointResume,
    testing::Values(
        ResumeCase{"wcsph_summation", [] { return wcsph(DensityMethod::summation, Shifting::none); }},
        ResumeCase{"wcsph_continuity", [] { return wcsph(DensityMethod::continuity, Shifting::none, 0); }},
        ResumeCase{"wcsph_delta_sph", [] { return wcsph(DensityMethod::continuity, Shifting::none, 0.1); }},
        // The Riemann continuity pass reads the pressures of the step before, which the resume's
        // start recomputes from the same state.
        ResumeCase{"wcsph_riemann_corrected",
                   [] {
                     scene::Scene s = wcsph(DensityMethod::continuity, Shifting::none);
                     s.solver.riemann_solver = scene::RiemannSolver::low_dissipation;
                     s.solver.kernel_gradient_correction = true;
                     return s;
                   }},
        ResumeCase{"wcsph_shifting", [] { return wcsph(DensityMethod::summation, Shifting::fickian); }},
        // Without a skin the resume rebuilds nothing: the shifted positions are not those of the
        // last sort, and the next search sorts from the order it finds.
        ResumeCase{"wcsph_shifting_no_skin",
                   [] {
                     scene::Scene s = wcsph(DensityMethod::continuity, Shifting::fickian);
                     s.solver.neighbor_skin = 0;
                     return s;
                   }},
        ResumeCase{"wcsph_artificial_stress", [] { return wcsph(DensityMethod::summation, Shifting::none, 0.1, 0.2); }},
        ResumeCase{"dfsph", [] { return incompressible(Scheme::dfsph, 0); }, 40},
        ResumeCase{"iisph", [] { return incompressible(Scheme::iisph, 0); }, 40},
        ResumeCase{"dfsph_with_skin", [] { return incompressible(Scheme::dfsph, 0.003); }, 40},
        ResumeCase{"dfsph_conjugate_gradients",
                   [] { return incompressible(Scheme::dfsph, 0, PressureSolver::conjugate_gradients); }, 40},
        // A closed flow: pressure of both signs, and DFSPH's divergence solve with the
        // energy-norm test.
        ResumeCase{"dfsph_conjugate_gradients_periodic",
                   [] {
                     scene::Scene s = periodic_box_2d();
                     s.fluid[0].velocity = scene::TaylorGreenVelocity{1, 0.2};
                     s.solver.clamp_negative_pressure = false;
                     s.solver.scheme = Scheme::dfsph;
                     s.solver.pressure_solver = PressureSolver::conjugate_gradients;
                     return s;
                   },
                   40},
        ResumeCase{"iisph_conjugate_gradients",
                   [] { return incompressible(Scheme::iisph, 0, PressureSolver::conjugate_gradients); }, 40},
        ResumeCase{"multiphase_csf", [] { return droplet(SurfaceTensionModel::csf); }},
        ResumeCase{"multiphase_akinci", [] { return droplet(SurfaceTensionModel::akinci); }},
        ResumeCase{"multiphase_pairwise", [] { return droplet(SurfaceTensionModel::pairwise); }},
        ResumeCase{"multiphase_dfsph",
                   [] {
                     scene::Scene s = test::rayleigh_taylor_scene(0.08);
                     s.solver.scheme = Scheme::dfsph;
                     return s;
                   },
                   40},
        ResumeCase{"inflow", [] { return test::inflow_channel_scene(1.0 / 40); }},
        ResumeCase{"moving_paddle_wcsph", [] { return with_paddle(Scheme::wcsph); }},
        ResumeCase{"moving_paddle_iisph", [] { return with_paddle(Scheme::iisph); }, 40},
        ResumeCase{"rigid_body", with_body}, ResumeCase{"crowd", crowd, 400}),
    [](const testing::TestParamInfo<ResumeCase>& info) { return info.param.name; });

}  // namespace
}  // namespace tide
