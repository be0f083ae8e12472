#pragma once

// What the validation cases share: applying a variant to a scene, timing the stepping, reading
// reference tables, sampling the velocity field and building the run record.

#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "tide/core/scene.hpp"
#include "tide/solvers/front_offset_fit.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/validation/case.hpp"

namespace tide::validation {

/// h/Δx used with each kernel: 1.7 for the Wendland kernels (Dehnen & Aly 2012 recommend
/// h/Δx ≥ 1.5 against pairing), 1.3 for the B-splines (Monaghan 2005).
double smoothing_ratio_for(KernelType kernel);

/// Sets the scheme and kernel of `variant` on the scene, with h/Δx and wall layers to match.
/// Throws std::invalid_argument for an unknown scheme.
void apply_variant(scene::Scene& scene, const Variant& variant);

/// Water (`water`) `depth` deep at rest in an open tank `width` wide (square in 3D) with walls
/// `rim` high, under gravity 9.81 m/s² down the last axis, spacing `spacing`, the variant applied,
/// the domain round the walls and Monaghan α = 0.1 against the start-up waves.
scene::Scene water_tank(int dimension, double width, double depth, double rim, double spacing,
                        const scene::Material& water, const Variant& variant);

/// Reads columns `x_column` and `y_column` of a reference CSV in validation/data ('#' lines are
/// its source header; the first other line names the columns; an empty field is a missing value,
/// whose row `y_column` skips).
Curve read_reference(const std::string& file, int x_column = 0, int y_column = 1);

/// The pressure-solve sweeps of a run: evaluations of the pressure's velocity and density error,
/// DFSPH's density and divergence solves together (SolveReport::sweeps; WCSPH has none).
struct SweepCount {
  std::uint64_t sweeps = 0;
  std::uint64_t steps = 0;
  double per_step() const { return steps > 0 ? static_cast<double>(sweeps) / static_cast<double>(steps) : 0; }
};

/// Steps `simulation` until its time reaches `end`, calling `observe(simulation)` after each
/// step; returns the wall seconds spent stepping (observers included, which are cheap). Counts
/// the sweeps into `count` where given.
template <int D, class Observer>
double run_until(Simulation<D>& simulation, double end, Observer&& observe, SweepCount* count = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  while (simulation.time() < end * (1 - 1e-12)) {
    const StepReport report = simulation.step();
    if (count) {
      ++count->steps;
      if (report.density_solve) count->sweeps += static_cast<std::uint64_t>(report.density_solve->sweeps);
      if (report.divergence_solve) count->sweeps += static_cast<std::uint64_t>(report.divergence_solve->sweeps);
    }
    observe(simulation);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <int D>
RunRecord make_record(const std::string& case_name, const Variant& variant, int resolution,
                      const Simulation<D>& simulation, double wall_seconds, std::vector<Metric> metrics) {
  RunRecord record;
  record.case_name = case_name;
  record.scheme = variant.scheme;
  record.kernel = std::string(kernel_name(variant.kernel));
  record.resolution = resolution;
  record.particles = simulation.fluid().size();
  record.steps = simulation.step_count();
  record.wall_seconds = wall_seconds;
  record.metrics = std::move(metrics);
  return record;
}

/// sqrt(Σ (a_i − b_i)²) / sqrt(Σ b_i²) accumulated one pair at a time.
class RelativeL2 {
 public:
  void add(double computed, double reference) {
    difference_ += (computed - reference) * (computed - reference);
    norm_ += reference * reference;
  }
  double value() const { return norm_ > 0 ? std::sqrt(difference_ / norm_) : 0; }

 private:
  double difference_ = 0;
  double norm_ = 0;
};

/// Velocity at `point` by Shepard interpolation over the fluid particles within the kernel
/// support: Σ_j V_j v_j W(x − x_j) / Σ_j V_j W(x − x_j), V_j = m_j/ρ_j (Shepard 1968: the SPH
/// interpolant normalised so that it reproduces a uniform field exactly, also beside a wall). NaN
/// when no fluid particle lies within the support, so that a void at a probe shows in the metrics.
template <int D>
Vector<D> shepard_velocity(const Simulation<D>& simulation, const Vector<D>& point);

// Each case, built in its own file.
Case hydrostatic_case(int dimension);
Case poiseuille_case();
Case couette_case();
Case taylor_green_case();
Case dam_break_2d_case();
Case dam_break_3d_front_case();
Case dam_break_buchner_case();
Case dam_break_3d_case();
Case lid_driven_cavity_case(int reynolds);
Case floating_box_case(int dimension);
Case neutral_body_case(bool ball);
Case settling_cylinder_case();
Case rising_block_case();
Case crowd_fundamental_diagram_case();
Case crowd_bottleneck_case();
Case crowd_single_agent_case();
Case crowd_lanes_case();

}  // namespace tide::validation
