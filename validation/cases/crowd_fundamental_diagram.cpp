// Case (a) of issue 36: the fundamental diagram of walking, the crowd's mean speed against its
// density in a periodic corridor, against Weidmann 1993 (docs/crowds.md, "Fundamental diagram").

#include <cmath>
#include <sstream>

#include "crowd_support.hpp"
#include "tide/solvers/crowd_sph.hpp"
#include "tide/validation/crowd_scenes.hpp"
#include "tide/validation/report.hpp"

namespace tide::validation {
namespace {

constexpr double corridor_width = 4;  // m, between the walls
constexpr double settle_time = 15;    // s: 30 relaxation times before the speeds are averaged
constexpr double end_time = 30;       // s
// Up to 2 persons/m² the agents start at random places (random sequential addition slows near
// its jamming limit, 4.4 persons/m² for bodies 0.4 m across), above it on the square or
// hexagonal lattice (docs/crowds.md, "Agents").
constexpr double densities[] = {0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0};  // persons/m²
constexpr double random_start_up_to = 2;

const Curve& weidmann() {
  static const Curve curve = read_reference("weidmann_1993_speed_density.csv");
  return curve;
}

std::string speed_metric(double density) { return "mean_speed_" + metric_number(density) + "_m_per_s"; }
std::string error_metric(double density) { return "speed_error_" + metric_number(density); }

// The mean over settle_time..end_time of the agents' mean velocity along the corridor.
RunRecord run_diagram(int length, const Variant& variant) {
  require_crowd_variant(variant);
  std::vector<Metric> speeds, errors;
  double squared_error = 0, wall_seconds = 0;
  std::size_t agents = 0;
  std::uint64_t steps = 0;
  for (const double density : densities) {
    const auto count = static_cast<std::size_t>(std::lround(density * length * corridor_width));
    CrowdSph crowd(
        crowd_corridor(count, length, corridor_width, end_time, density <= random_start_up_to ? "random" : "lattice"));
    const ParticleSet<2>& walkers = crowd.fluid();
    double speed_sum = 0;
    long samples = 0;
    wall_seconds += run_until(crowd, end_time, [&](const Simulation<2>& simulation) {
      if (simulation.time() < settle_time) return;
      const auto v = walkers[crowd.fluid_fields().velocity];
      double along = 0;
      for (std::size_t i = 0; i < walkers.size(); ++i) along += static_cast<double>(v[i][0]);
      speed_sum += along / static_cast<double>(walkers.size());
      ++samples;
    });
    const double speed = speed_sum / static_cast<double>(samples);
    const double error = speed / weidmann().at(density) - 1;
    squared_error += error * error;
    speeds.push_back({speed_metric(density), speed});
    errors.push_back({error_metric(density), error});
    agents += count;
    steps += crowd.step_count();
  }
  std::vector<Metric> metrics{
      {"speed_rms_error", std::sqrt(squared_error / static_cast<double>(std::size(densities)))}};
  metrics.insert(metrics.end(), errors.begin(), errors.end());
  metrics.insert(metrics.end(), speeds.begin(), speeds.end());
  return crowd_record("crowd_fundamental_diagram", variant, length, agents, steps, wall_seconds, std::move(metrics));
}

// Mean speed against density: each run's points and Weidmann's curve.
std::string diagram_script(const std::string& output, const std::vector<RunRecord>& runs) {
  std::ostringstream script;
  script << png_terminal(output) << "set title 'Fundamental diagram, periodic corridor 4 m wide'\n"
         << "set xlabel 'density (persons/m^2)'\nset ylabel 'mean speed along the corridor (m/s)'\n"
         << "set grid\nset key top right\nset xrange [0:5.5]\nset yrange [0:1.5]\n$weidmann << EOD\n";
  const Curve& reference = weidmann();
  for (std::size_t k = 0; k < reference.x.size(); ++k) script << reference.x[k] << ' ' << reference.y[k] << '\n';
  script << "EOD\n";
  for (std::size_t r = 0; r < runs.size(); ++r)
    script << metric_block("model" + std::to_string(r), runs[r], densities, speed_metric);
  script << "plot $weidmann using 1:2 with lines linewidth 2 title 'Weidmann 1993, v0 = 1.34 m/s'";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    script << ", $model" << r << " using 1:2 with linespoints pointtype 7 title "
           << gnuplot_string("TideSPH crowd, corridor " + std::to_string(runs[r].resolution) + " m");
  }
  script << '\n';
  return script.str();
}

}  // namespace

Case crowd_fundamental_diagram_case() {
  Case c;
  c.name = "crowd_fundamental_diagram";
  c.title = "Crowd: fundamental diagram in a periodic corridor";
  c.reference =
      "Weidmann 1993, v(ρ) = v0 (1 − exp(−γ (1/ρ − 1/ρ_max))), γ = 1.913 m⁻², ρ_max = 5.4 persons/m², v0 = 1.34 m/s "
      "(validation/data/weidmann_1993_speed_density.csv): the mean speed along a corridor 4 m wide, periodic along "
      "its length, everyone walking the same way, averaged over 15–30 s, at 0.5–5 persons/m²";
  c.resolution_meaning = "the corridor's length in metres (agents: density × length × 4 m)";
  c.metric_notes = {"speed_rms_error: sqrt(mean over the densities of speed_error²)",
                    "speed_error_ρ: mean speed / Weidmann's speed − 1 at density ρ persons/m² (0_5 is 0.5)",
                    "mean_speed_ρ_m_per_s: the crowd's mean speed along the corridor at density ρ"};
  c.resolutions = {20};
  c.test_resolution = 10;
  c.schemes = {std::string(crowd_scheme)};
  c.kernels = {KernelType::wendland_c2};
  c.figures = {{"crowd_fundamental_diagram_speed.png", "Crowd: mean speed against density, against Weidmann 1993",
                diagram_script}};
  c.run = run_diagram;
  return c;
}

}  // namespace tide::validation
