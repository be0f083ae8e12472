// A wooden block let go on the floor of a water tank rises, overshoots and bobs at the surface:
// its height against the experiment of Qiu, Liu & Han 2017, §3.3 (validation/data/
// qiu_2017_floating_block_centre_height.csv, which gives the source and the set-up).

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "case_support.hpp"
#include "crowd_support.hpp"
#include "tide/validation/report.hpp"

namespace tide::validation {
namespace {

// The section of the experiment: a tank 0.15 m wide, water 0.052 m deep with the block on its
// floor, the block 0.049 × 0.024 m of density 800.52 kg/m³ centred across the tank. The block
// starts as many spacings above the floor as the wall layers (the kernel's support rounded up, 4 Δx
// at h = 1.7 Δx), with water under it: the fluid's force on a body is the reaction to what the
// fluid particles get from it, and within a kernel support of the floor the floor's particles stand
// where fluid would push the body, so that a block one spacing above the floor, over a film of
// water at the hydrostatic 490 Pa, was measured to feel 6.1 N/m of its 11.5 N/m buoyancy
// (Δx = 3 mm) and sank into the film. So the run starts higher than the experiment, by an offset
// that shrinks with Δx.
constexpr double tank_width = 0.15, water_depth = 0.052, block_width = 0.049, block_height = 0.024;
constexpr double block_density = 800.52, water_density = 1000, sound_speed = 10;
constexpr double end_time = 1.5;  // s, the experiment's record, from the block's release
// Summation density starts the water without pressure: gravity is raised over the first 0.1 s and
// the block held until 0.25 s, when the water round it and the film under it have settled to
// hydrostatic pressure (let go at once, the block sinks into the film before its pressure builds
// up and squeezes the water out from under itself). The experiment's clock starts at the release.
constexpr double gravity_ramp = 0.1, release_time = 0.25;
// Monaghan's α: the tank's 0.1 acts as a kinematic viscosity α h c0 / 8 = 4e-4 m²/s at 12 rows,
// 400 times water's, and the block creeps up to its floating height without overshooting; at 0.02
// it overshoots by a third of the measured overshoot, at 0.01 (used) by half, at 0.005 it bobs
// alike (12 rows, Δx = 2 mm).
constexpr double artificial_viscosity = 0.01;
// After the first trough the block bobs about its floating height: the mean is taken from here.
constexpr double bobbing_from = 0.55;
// The simulated heights the figure draws, 20 a second (k / 20.0 is the double nearest k × 0.05).
constexpr int figure_samples_per_second = 20;

const Curve& experiment() {
  static const Curve curve = read_reference("qiu_2017_floating_block_centre_height.csv");
  return curve;
}

// How far the experiment's block rose from its start to its highest point: the scale of the errors.
double experiment_rise() {
  const Curve& e = experiment();
  return *std::max_element(e.y.begin(), e.y.end()) - e.y.front();
}

std::vector<double> figure_times() {
  std::vector<double> times;
  for (int k = 0; k <= end_time * figure_samples_per_second; ++k)
    times.push_back(k / double{figure_samples_per_second});
  return times;
}

std::string height_metric(double time) { return "height_" + metric_number(time) + "_s_m"; }

struct Extremum {
  double time = 0, height = 0;
};

// The first peak, the trough after it and the second peak of a trajectory: an extremum counts once
// the height has moved away from it by 1 mm, 2.5% of the experiment's rise (the digitised points
// scatter by about 0.3 mm about a smooth curve; the simulated height is smooth).
struct Swing {
  std::optional<Extremum> first_peak, trough, second_peak;
};

Swing find_swing(const Curve& trajectory) {
  constexpr double prominence = 0.001;
  Swing swing;
  std::optional<Extremum>* found[] = {&swing.first_peak, &swing.trough, &swing.second_peak};
  int stage = 0;
  Extremum candidate{trajectory.x.front(), trajectory.y.front()};
  for (std::size_t k = 0; k < trajectory.x.size() && stage < 3; ++k) {
    const double t = trajectory.x[k], y = trajectory.y[k];
    const bool looking_for_peak = stage != 1;
    if (looking_for_peak ? y > candidate.height : y < candidate.height) candidate = {t, y};
    if (looking_for_peak ? y < candidate.height - prominence : y > candidate.height + prominence) {
      *found[stage++] = candidate;
      candidate = {t, y};
    }
  }
  return swing;
}

// The time average of a trajectory over [from, its end], by the trapezoidal rule.
double mean_from(const Curve& trajectory, double from) {
  double area = 0, start = 0;
  bool started = false;
  for (std::size_t k = 1; k < trajectory.x.size(); ++k) {
    if (trajectory.x[k - 1] < from) continue;
    if (!started) start = trajectory.x[k - 1];
    started = true;
    area += (trajectory.x[k] - trajectory.x[k - 1]) * (trajectory.y[k] + trajectory.y[k - 1]) / 2;
  }
  if (!started || trajectory.x.back() <= start) throw std::runtime_error("rising_block: no samples to average");
  return area / (trajectory.x.back() - start);
}

scene::Scene rising_block_scene(int rows, const Variant& variant) {
  const double spacing = block_height / rows;
  scene::Scene s = water_tank(2, tank_width, water_depth, 2 * water_depth, spacing,
                              {"water", water_density, 1e-6, sound_speed, std::nullopt}, variant);
  s.source = "rising block";
  s.solver.gravity_ramp_time = gravity_ramp;
  s.solver.alpha = artificial_viscosity;
  const double left = (tank_width - block_width) / 2;
  scene::Obstacle block;
  const double clearance = s.walls.layers * spacing;
  block.shape = scene::Box{{left, clearance, 0}, {left + block_width, clearance + block_height, 0}};
  block.body = scene::Body{block_density, {}, release_time};
  s.walls.obstacles.push_back(block);
  return s;
}

RunRecord run_rising_block(int rows, const Variant& variant) {
  const auto simulation_owner = make_simulation<2>(rising_block_scene(rows, variant));
  Simulation<2>& simulation = *simulation_owner;
  if (simulation.bodies() == nullptr || simulation.bodies()->size() != 1)
    throw std::runtime_error("rising_block: the scheme did not take the block as a body");
  const RigidBody& block = simulation.bodies()->body(0);
  Curve trajectory;
  const double wall_seconds = run_until(simulation, release_time + end_time, [&](const Simulation<2>& s) {
    if (s.time() < release_time * (1 - 1e-12)) return;
    trajectory.x.push_back(s.time() - release_time);
    trajectory.y.push_back(block.centre().y());
  });

  const Curve& e = experiment();
  const double rise = experiment_rise();
  double squared = 0;
  for (std::size_t k = 0; k < e.x.size(); ++k) squared += std::pow(trajectory.at(e.x[k]) - e.y[k], 2);
  const Swing simulated = find_swing(trajectory), measured = find_swing(e);
  if (!measured.second_peak) throw std::runtime_error("rising_block: the experiment's swing was not found");
  // A swing the run does not make counts as its end time (first peak) or as no period at all.
  const Extremum first_peak = simulated.first_peak.value_or(Extremum{end_time, trajectory.y.back()});
  const double period = simulated.second_peak ? simulated.second_peak->time - first_peak.time : 0;
  const double measured_period = measured.second_peak->time - measured.first_peak->time;

  std::vector<Metric> metrics{
      {"height_rms_error", std::sqrt(squared / static_cast<double>(e.x.size())) / rise},
      {"first_peak_delay_s", first_peak.time - measured.first_peak->time},
      {"first_peak_height_error", (first_peak.height - measured.first_peak->height) / rise},
      {"period_error", period / measured_period - 1},
      {"mean_height_error", (mean_from(trajectory, bobbing_from) - mean_from(e, bobbing_from)) / rise}};
  for (const double t : figure_times()) metrics.push_back({height_metric(t), trajectory.at(t)});
  return make_record("rising_block", variant, rows, simulation, wall_seconds, std::move(metrics));
}

// The block's height against time: the experiment's points and each run's curve.
std::string height_script(const std::string& output, const std::vector<RunRecord>& runs) {
  std::ostringstream script;
  script << png_terminal(output) << "set title 'Block rising from the floor and floating (Qiu et al. 2017, §3.3)'\n"
         << "set xlabel 'time (s)'\nset ylabel 'height of the block centre above the floor (m)'\n"
         << "set grid\nset key bottom right\nset xrange [0:1.5]\n$experiment << EOD\n";
  const Curve& e = experiment();
  for (std::size_t k = 0; k < e.x.size(); ++k) script << e.x[k] << ' ' << e.y[k] << '\n';
  script << "EOD\n";
  const std::vector<double> times = figure_times();
  for (std::size_t r = 0; r < runs.size(); ++r)
    script << metric_block("run" + std::to_string(r), runs[r], times, height_metric);
  script << "plot $experiment using 1:2 with points pointtype 7 title 'experiment'";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    script << ", $run" << r << " using 1:2 with lines linewidth 2 title "
           << gnuplot_string(runs[r].scheme + ", " + std::to_string(runs[r].resolution) + " rows");
  }
  script << '\n';
  return script.str();
}

}  // namespace

Case rising_block_case() {
  Case c;
  c.name = "rising_block";
  c.title = "Wooden block rising from a tank's floor and floating, 2D (experiment)";
  c.reference =
      "the experiment of Qiu, Liu & Han 2017 (Math. Probl. Eng. 2017:3174904, §3.3; validation/data/"
      "qiu_2017_floating_block_centre_height.csv): a block 0.049 × 0.024 m of 800.52 kg/m³ let go on the floor of "
      "water 0.052 m deep in a tank 0.15 m wide, its centre's height over 1.5 s. The run's block starts four "
      "spacings above the floor, a kernel support clear of it (docs/bodies.md, Limits), and α = 0.01";
  c.resolution_meaning = "particle rows over the block's height (0.024 m)";
  c.metric_notes = {
      "height_rms_error: the root mean square of the simulated minus the measured height at the experiment's "
      "points, over the experiment's rise R = 0.039 m (start to highest point)",
      "first_peak_delay_s: the time of the first peak, simulated less measured (0.376 s)",
      "first_peak_height_error: the first peak's height, simulated less measured (0.0512 m), over R",
      "period_error: the time from the first to the second peak over the measured one (0.356 s), less 1",
      "mean_height_error: the mean height from 0.55 s on, simulated less measured (0.0433 m), over R",
      "height_t_s_m: the simulated height at t s (t = 0_35 is 0.35 s), for the figure"};
  c.resolutions = {8, 12, 16};
  c.test_resolution = 6;
  c.schemes = {"wcsph", "wcsph_continuity"};
  c.figures = {{"rising_block_height.png", "Block rising and floating: height against time, against the experiment",
                height_script}};
  c.run = run_rising_block;
  return c;
}

}  // namespace tide::validation
