// Step benchmarks (issues 3 and 8): one full time step of each scheme (WCSPH, DFSPH, IISPH,
// through tide::make_simulation) on the dam-break set-up at 10^4 to 10^6 fluid particles (10^7
// with TIDE_BENCH_HUGE=1) in 2D and 3D, with 1 and 2 threads; the 3D reference scene of issue 8;
// the cost of each optional feature on and off; and whole 2D dam-break runs to T = 3.
//
// Names carry everything a number depends on:
//   BM_Step/<scheme>/<D>D/N:<n>/threads:<t>/<real>       N nominal fluid particles (exact: `fluid`)
//   BM_Reference3D/<scheme>/threads:<t>/<real>           1 x 1 x 1 m block (39^3 = 59 319 particles,
//                                                        spacing 0.025 m) in a 4 x 3 x 1.5 m tank,
//                                                        cubic spline, support 2 x spacing
//   BM_Feature/<feature>:<on|off>/3D/N:100000/threads:2/<real>
//   BM_DamBreak2D/<scheme>/a_dx:<k>/threads:2/<real>     the validation case dam_break_2d (Wendland
//                                                        C2, h = 1.7 dx) run to T = t sqrt(2g/a) = 3
// The thread count is imposed with tide::ThreadLimit, the precision is tide::Real (TIDE_REAL_NAME).
// All times are wall-clock (UseRealTime).
//
// The scenes (dam_break()): as scenes/dam_break_2d.json and scenes/dam_break_3d.json with only the
// spacing changed. 2D: Martin & Moyce, a column a x 2a (a = 0.05715 m) in a tank 5a x 3a, Wendland
// C2 with h = 1.3 dx, 3 wall layers. 3D: a cube of water in the corner of a 4 x 1.5 x 3 m tank (z
// up), cubic spline with h = dx (support 2 dx, the SPlisHSPlasH reference set-up), 2 wall layers.
// Both: free-slip walls, open top, Tait EOS, density summation, artificial viscosity alpha = 0.02,
// c0 = 10 x the expected maximum speed; incompressible schemes stop their density solve at a mean
// density error of 0.05% of rho0 (solver.max_density_error). The domain is the one io/ derives.
//
// Warm-up: the simulation is constructed and runs `warmup_steps` steps untimed; then every
// iteration is one step() (the column keeps collapsing, as in a run).
//
// Counters (per iteration = per step):
//   particle-steps/s  fluid particles / wall seconds per step (walls not counted)
//   ns/pair           wall time per step / (fluid-fluid + fluid-wall neighbour pairs, i itself
//                     included), counted once after the timed loop: the cost per particle-neighbour
//                     interaction of the whole step
//   B/particle        Simulation::bytes_per_particle(): fluid and wall fields (with their reorder
//                     workspace) plus every neighbour structure (grids, range tables, neighbour
//                     lists), per fluid particle
//                     (MemoryUsage: every buffer at its capacity, what it really holds)
//   B_fluid, B_walls, B_grids, B_lists   its parts, per fluid particle: fluid fields and wall
//                     fields (each with the reorder workspace of ParticleSet::permute), the two
//                     grids (sort workspace, cell tables, own range tables) and the rest
//                     (fluid-wall range tables and the three neighbour lists); bench/memory_report
//                     lists every item
//   RSS_B/particle    resident memory after the timed steps less that before the simulation was
//                     built (VmRSS), per fluid particle: the check of B/particle against the OS
//   peak_RSS_B/particle  the peak resident memory (VmHWM, reset after the warm-up) of the timed
//                     steps less the same baseline: B/particle plus what a step allocates and frees.
//                     Both are per process: filter one benchmark for a clean figure
//   f_nbr, f_density, f_wall, f_momentum, f_solve, f_integr, f_shift
//                     share of the step in each part, summed over the stages of
//                     Simulation::pipeline() (step_part): neighbour search (sort, reorder, cell
//                     tables, neighbour lists; for WCSPH with a skin and summation density also
//                     that density, one stage with the search as it lists the pairs), density
//                     (+ EOS; for the incompressible schemes + gradient cache and pressure factor),
//                     wall state, momentum (incompressible: the non-pressure forces), the pressure
//                     solves, integration (kicks, drift, inflow, time, state checks), particle
//                     shifting; f_other = 1 - their sum (surface tension, and the time step's choice)
//   density_iter, divergence_iter   mean iterations per step of the incompressible solves
//   sim_s/step        mean simulated seconds per step; wall_per_sim_s = wall seconds per simulated
//                     second (what a fixed-duration run costs)
//   neighbors         fluid and wall neighbours per fluid particle, itself included
//   fluid, walls/fluid, threads, cpu_util (process CPU time / (wall time x threads): near 1 when
//                     every thread had a core; a row well below is disturbed, re-run it)
//
// Reproduce: scripts/bench.sh (all suites, then docs/performance.md), or
//   cmake --build build --target step_bench && build/bench/step_bench --benchmark_filter=BM_Reference3D

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "dam_break_scenes.hpp"
#include "process_memory.hpp"
#include "tide/core/config.hpp"
#include "tide/core/large_block_release.hpp"
#include "tide/core/parallel.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/validation/case.hpp"

namespace {

using tide::Real;
using tide::bench::reference_3d;
using tide::bench::sized_dam_break;
namespace scene = tide::scene;

constexpr int warmup_steps = 20;

// The f_* counter a stage of Simulation::pipeline() counts in; null for f_other.
const char* step_part(std::string_view stage) {
  const auto any_of = [&](std::initializer_list<std::string_view> names) {
    return std::find(names.begin(), names.end(), stage) != names.end();
  };
  if (stage.starts_with("neighbor_search")) return "f_nbr";
  if (any_of({"continuity", "equation_of_state", "density_summation", "number_density", "gradient_cache",
              "pressure_factor"}))
    return "f_density";
  if (stage == "wall_state") return "f_wall";
  if (any_of({"momentum", "non_pressure_momentum"})) return "f_momentum";
  if (any_of({"density_solve", "divergence_solve"})) return "f_solve";
  if (any_of({"kick_drift", "inflow_drift", "inflow_phase", "kick", "inflow_velocity", "predict_velocity", "drift",
              "advance_time", "state_check_before_drift", "state_check"}))
    return "f_integr";
  if (stage == "particle_shifting") return "f_shift";
  return nullptr;
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// Fluid-fluid plus fluid-contact pairs (i itself included) at the current positions.
template <int D>
std::size_t count_pairs(const tide::Simulation<D>& simulation) {
  const tide::ConstVectorView<D> x = simulation.fluid()[simulation.fluid_fields().position];
  const tide::Interactions<D>& interactions = simulation.interactions();
  return tide::reduce(
      simulation.fluid().size(), std::size_t(0),
      [&](std::size_t i) {
        std::size_t count = 0;
        const auto add = [&](tide::Index, const tide::Vector<D>&, Real) { ++count; };
        interactions.fluid_grid().for_each_neighbor(i, x, add);
        for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
          const tide::Contact<D>& contact = interactions.contact(k);
          contact.grid().for_each_neighbor_of(x[i], contact.positions(), add);
        }
        return count;
      },
      [](std::size_t a, std::size_t b) { return a + b; });
}

template <int D>
void time_steps(benchmark::State& state, const scene::Scene& s, int threads, double warmup_time = 0) {
  tide::ThreadLimit limit(threads);
  const std::size_t baseline = tide::bench::resident_memory().current;
  try {
    const std::unique_ptr<tide::Simulation<D>> owner = tide::make_simulation<D>(s);
    tide::Simulation<D>& simulation = *owner;
    for (int step = 0; step < warmup_steps || simulation.time() < warmup_time; ++step) simulation.step();
    const bool peak_reset = tide::bench::reset_peak_resident_memory();
    const std::size_t builds_before = simulation.neighbor_builds();

    const std::vector<tide::StageTime> before = simulation.pipeline().times();
    const double time_before = simulation.time();
    std::size_t density_iterations = 0;
    std::size_t divergence_iterations = 0;
    const double cpu_start = process_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
      const tide::StepReport report = simulation.step();
      if (report.density_solve) density_iterations += std::size_t(report.density_solve->iterations);
      if (report.divergence_solve) divergence_iterations += std::size_t(report.divergence_solve->iterations);
      benchmark::ClobberMemory();
    }
    const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu_seconds = process_cpu_seconds() - cpu_start;
    const tide::bench::ResidentMemory resident = tide::bench::resident_memory();
    const std::vector<tide::StageTime> after = simulation.pipeline().times();
    if (simulation.removed_total() != 0) {
      state.SkipWithError("particles left the domain");
      return;
    }
    const double steps = double(state.iterations());
    const double fluid = double(simulation.fluid().size());
    const double pairs = double(count_pairs(simulation));
    using benchmark::Counter;
    state.counters["particle-steps/s"] = Counter(fluid, Counter::kIsIterationInvariantRate);
    state.counters["ns/pair"] = Counter(1e9 * wall_seconds / (steps * pairs));
    state.counters["B/particle"] = Counter(simulation.bytes_per_particle());
    double fluid_fields = 0, wall_fields = 0, grids = 0, rest = 0;
    const tide::MemoryUsage usage = simulation.memory_usage();
    for (const tide::MemoryItem& item : usage.items()) {
      const auto starts = [&](const char* prefix) { return item.name.rfind(prefix, 0) == 0; };
      double& part = starts("fluid.")                                 ? fluid_fields
                     : starts("walls.")                               ? wall_fields
                     : starts("fluid grid.") || starts("walls grid.") ? grids
                                                                      : rest;
      part += double(item.bytes);
    }
    state.counters["B_fluid"] = Counter(fluid_fields / fluid);
    state.counters["B_walls"] = Counter(wall_fields / fluid);
    state.counters["B_grids"] = Counter(grids / fluid);
    state.counters["B_lists"] = Counter(rest / fluid);
    state.counters["RSS_B/particle"] = Counter((double(resident.current) - double(baseline)) / fluid);
    if (peak_reset) state.counters["peak_RSS_B/particle"] = Counter((double(resident.peak) - double(baseline)) / fluid);
    for (const char* part : {"f_nbr", "f_density", "f_wall", "f_momentum", "f_solve", "f_integr", "f_shift"})
      state.counters[part] = Counter(0);
    double accounted = 0;
    for (std::size_t k = 0; k < after.size(); ++k) {
      const char* part = step_part(after[k].name);
      if (part == nullptr) continue;
      const double f = (after[k].seconds - before[k].seconds) / wall_seconds;
      state.counters[part].value += f;
      accounted += f;
    }
    state.counters["f_other"] = Counter(1 - accounted);
    state.counters["density_iter"] = Counter(double(density_iterations) / steps);
    state.counters["divergence_iter"] = Counter(double(divergence_iterations) / steps);
    const double simulated = simulation.time() - time_before;
    state.counters["sim_s/step"] = Counter(simulated / steps);
    state.counters["wall_per_sim_s"] = Counter(wall_seconds / simulated);
    state.counters["neighbors"] = Counter(pairs / fluid);
    state.counters["builds/step"] = Counter(double(simulation.neighbor_builds() - builds_before) / steps);
    state.counters["fluid"] = Counter(fluid);
    state.counters["walls/fluid"] = Counter(double(simulation.interactions().contact_particle_count()) / fluid);
    // What a body costs per body particle: (1/rate_on − 1/rate_off) × fluid / body_particles
    // between a feature's rows (docs/performance.md).
    double body_particles = 0;
    if (const auto* bodies = simulation.bodies())
      for (std::size_t k = 0; k < bodies->size(); ++k) body_particles += double(bodies->contact(k).particles().size());
    state.counters["body_particles"] = Counter(body_particles);
    state.counters["threads"] = Counter(double(tide::thread_count()));
    state.counters["cpu_util"] = Counter(cpu_seconds / (wall_seconds * threads));
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
  }
}

// The sized dam breaks are timed from rest (a developed flow at 10^7 particles would take hours
// to reach), where lists with a skin would hardly ever be rebuilt: these rows sort and rebuild
// every step, the cost of a step that does. The reference rows run the developed flow with the
// scheme's default skin.
scene::Scene rebuilt_every_step(scene::Scene s) {
  s.solver.neighbor_skin = 0;
  return s;
}

// Fixed per size: a few seconds of timed steps per row on 2 cores.
benchmark::IterationCount iterations(std::size_t n, scene::Scheme scheme) {
  const benchmark::IterationCount explicit_steps = n >= 10'000'000 ? 2 : n >= 1'000'000 ? 5 : n >= 100'000 ? 20 : 200;
  return scheme == scene::Scheme::wcsph ? explicit_steps : std::max<benchmark::IterationCount>(explicit_steps / 2, 2);
}

std::string suffix(int threads) { return "/threads:" + std::to_string(threads) + "/" + TIDE_REAL_NAME; }

void add(const std::string& name, benchmark::IterationCount steps, std::function<void(benchmark::State&)> run) {
  benchmark::RegisterBenchmark(name.c_str(), std::move(run))
      ->UseRealTime()
      ->Unit(benchmark::kMillisecond)
      ->Iterations(steps);
}

constexpr scene::Scheme schemes[] = {scene::Scheme::wcsph, scene::Scheme::dfsph, scene::Scheme::iisph};

template <int D>
void register_steps(bool huge) {
  std::vector<std::size_t> sizes{10'000, 100'000, 1'000'000};
  if (huge && D == 3) sizes.push_back(10'000'000);
  for (scene::Scheme scheme : schemes) {
    for (std::size_t n : sizes) {
      for (int threads : {1, 2}) {
        const std::string name = "BM_Step/" + std::string(tide::scheme_name(scheme)) + "/" + std::to_string(D) +
                                 "D/N:" + std::to_string(n) + suffix(threads);
        add(name, iterations(n, scheme), [=](benchmark::State& state) {
          time_steps<D>(state, rebuilt_every_step(sized_dam_break(D, n, scheme)), threads);
        });
      }
    }
  }
}

// The reference rows are timed once the front runs (t = 0.25 s, the water at up to about 2 m/s),
// not from rest: a step then takes longer (more wall contacts and cells), and lists with a skin
// (solver.neighbor_skin) are rebuilt as often as they ever are; from rest they would hold for
// tens of steps.
constexpr double reference_start = 0.25;

void register_reference() {
  for (scene::Scheme scheme : schemes) {
    for (int threads : {1, 2}) {
      const std::string name = "BM_Reference3D/" + std::string(tide::scheme_name(scheme)) + suffix(threads);
      add(name, scheme == scene::Scheme::wcsph ? 100 : 40,
          [=](benchmark::State& state) { time_steps<3>(state, reference_3d(scheme), threads, reference_start); });
    }
  }
}

// The neighbour lists' skin, in particle spacings, on the reference 3D dam break.
void register_skins() {
  for (scene::Scheme scheme : {scene::Scheme::wcsph, scene::Scheme::dfsph}) {
    for (const double skin : {0.0, 0.1, 0.2, 0.3, 0.4, 0.5}) {
      char value[16];
      std::snprintf(value, sizeof value, "%.1f", skin);
      const std::string name =
          "BM_Skin/" + std::string(tide::scheme_name(scheme)) + "/skin:" + value + "/reference3D" + suffix(2);
      add(name, scheme == scene::Scheme::wcsph ? 100 : 40, [=](benchmark::State& state) {
        scene::Scene s = reference_3d(scheme);
        s.solver.neighbor_skin = skin;
        time_steps<3>(state, s, 2, reference_start);
      });
    }
  }
}

// The dam break's water block as two fluid materials of the same properties, one half each: the
// multiphase step (phase field, number density, per-phase equation of state) on the same flow.
void split_into_two_fluids(scene::Scene& s) {
  scene::Material second = s.materials.front();
  second.name = "second water";
  s.materials.push_back(second);
  const scene::Box block = std::get<scene::Box>(s.fluid.front().shape);
  scene::Box first_half = block, second_half = block;
  first_half.max[0] = second_half.min[0] = 0.5 * (block.min[0] + block.max[0]);
  s.fluid = {{0, first_half}, {1, second_half}};
}

// A support of 4 spacings (h = 2Δx with the cubic spline) and the wall layers that cover it:
// what the pairwise forces need to stay stable (docs/multiphase.md). The domain grows with the
// walls, which would otherwise leave it.
void widen_support(scene::Scene& s) {
  constexpr int layers = 4;
  const double extra = (layers - s.walls.layers) * s.particle_spacing;
  s.smoothing_ratio = 2;
  s.walls.layers = layers;
  for (int d = 0; d < s.dimension; ++d) {
    s.domain.box.min[d] -= extra;
    s.domain.box.max[d] += extra;
  }
}

// A cube of 0.2 m inside the water column of the 3D dam break (1 m high), half the water's
// density: a rigid body the water moves, or (`body` false) the same cube fixed, with the same wall
// particles, so that the difference between the two is what a body costs.
void add_cube(scene::Scene& s, bool body) {
  scene::Obstacle cube;
  cube.shape = scene::Box{{0.4, 0.4, 0.6}, {0.6, 0.6, 0.8}};
  if (body) cube.body = scene::Body{500, {}};
  s.walls.obstacles.push_back(cube);
}

// Each optional feature of the WCSPH step, on and off, on the 3D dam break at 10^5 particles.
// Where a feature needs more than a switch (two fluids for csf, a wider support for the pairwise
// forces), off is the same scene without the feature.
struct Feature {
  const char* name;
  std::function<void(scene::Scene&)> on;
  std::function<void(scene::Scene&)> off;
};

void register_features() {
  const std::vector<Feature> features{
      {"laminar_viscosity", [](scene::Scene& s) { s.solver.viscosity = scene::ViscosityModel::laminar; },
       [](scene::Scene& s) { s.solver.viscosity = scene::ViscosityModel::artificial; }},
      {"no_slip_walls", [](scene::Scene& s) { s.walls.slip = scene::WallSlip::no_slip; },
       [](scene::Scene& s) { s.walls.slip = scene::WallSlip::free_slip; }},
      {"artificial_stress", [](scene::Scene& s) { s.solver.artificial_stress = 0.2; },
       [](scene::Scene& s) { s.solver.artificial_stress = 0; }},
      {"continuity_delta_sph",
       [](scene::Scene& s) {
         s.solver.density = scene::DensityMethod::continuity;
         s.solver.delta_sph = 0.1;
       },
       [](scene::Scene& s) {
         s.solver.density = scene::DensityMethod::continuity;
         s.solver.delta_sph = 0;
       }},
      {"continuity_density", [](scene::Scene& s) { s.solver.density = scene::DensityMethod::continuity; },
       [](scene::Scene& s) { s.solver.density = scene::DensityMethod::summation; }},
      {"shifting", [](scene::Scene& s) { s.solver.shifting = scene::Shifting::fickian; },
       [](scene::Scene& s) { s.solver.shifting = scene::Shifting::none; }},
      {"multiple_phases", split_into_two_fluids, [](scene::Scene&) {}},
      {"rigid_body", [](scene::Scene& s) { add_cube(s, true); }, [](scene::Scene& s) { add_cube(s, false); }},
      {"surface_tension_akinci",
       [](scene::Scene& s) {
         s.solver.surface_tension.model = scene::SurfaceTensionModel::akinci;
         s.solver.surface_tension.coefficient = 1;
         s.solver.surface_tension.adhesion = 1;
       },
       [](scene::Scene&) {}},
      {"surface_tension_csf",
       [](scene::Scene& s) {
         split_into_two_fluids(s);
         s.solver.surface_tension.model = scene::SurfaceTensionModel::csf;
         s.solver.surface_tension.coefficient = 0.0728;
       },
       split_into_two_fluids},
      {"surface_tension_pairwise",
       [](scene::Scene& s) {
         widen_support(s);
         s.solver.surface_tension.model = scene::SurfaceTensionModel::pairwise;
         s.solver.surface_tension.coefficient = 0.0728;
       },
       widen_support},
  };
  constexpr std::size_t n = 100'000;
  for (const Feature& feature : features) {
    for (bool on : {false, true}) {
      const std::string name =
          std::string("BM_Feature/") + feature.name + (on ? ":on" : ":off") + "/3D/N:" + std::to_string(n) + suffix(2);
      const auto configure = on ? feature.on : feature.off;
      add(name, iterations(n, scene::Scheme::wcsph), [=](benchmark::State& state) {
        scene::Scene s = rebuilt_every_step(sized_dam_break(3, n, scene::Scheme::wcsph));
        configure(s);
        time_steps<3>(state, s, 2);
      });
    }
  }
}

// The validation case dam_break_2d (Martin & Moyce) run to T = 3: wall seconds of the stepping
// and the front error after the start-time offset.
void register_dam_break_runs() {
  for (const char* scheme : {"wcsph", "dfsph", "iisph"}) {
    for (int resolution : {40, 80}) {
      const std::string name =
          std::string("BM_DamBreak2D/") + scheme + "/a_dx:" + std::to_string(resolution) + suffix(2);
      benchmark::RegisterBenchmark(name.c_str(),
                                   [=](benchmark::State& state) {
                                     tide::ThreadLimit limit(2);
                                     const tide::validation::Case* c = tide::validation::find_case("dam_break_2d");
                                     tide::validation::RunRecord record;
                                     for (auto _ : state)
                                       record = c->run(resolution, {scheme, tide::KernelType::wendland_c2});
                                     using benchmark::Counter;
                                     state.counters["wall_s"] = Counter(record.wall_seconds);
                                     state.counters["steps"] = Counter(double(record.steps));
                                     state.counters["fluid"] = Counter(double(record.particles));
                                     for (const auto& metric : record.metrics)
                                       if (metric.name == "front_error_after_offset")
                                         state.counters["front_error"] = Counter(metric.value);
                                   })
          ->UseRealTime()
          ->Unit(benchmark::kSecond)
          ->Iterations(1);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  tide::release_large_blocks_to_the_system();  // as the `tide` app: RSS_B/particle then follows B/particle
  const char* huge = std::getenv("TIDE_BENCH_HUGE");
  register_reference();
  register_skins();
  register_steps<2>(false);
  register_steps<3>(huge != nullptr && std::string(huge) == "1");
  register_features();
  register_dam_break_runs();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
