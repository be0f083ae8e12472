// Case (d) of issue 36: counter-flow in a periodic corridor, measured by the lane order parameter
// of Rex & Löwen 2007 (docs/crowds.md, "Counter-flow lanes").

#include <chrono>
#include <cmath>
#include <sstream>

#include "crowd_support.hpp"
#include "tide/solvers/crowd_sph.hpp"
#include "tide/validation/crowd_scenes.hpp"
#include "tide/validation/report.hpp"

namespace tide::validation {
namespace {

constexpr double corridor_length = 20, corridor_width = 4;  // m
constexpr double end_time = 60;                             // s
constexpr double sample_interval = 5;                       // s
constexpr double late_from = 40;                            // s: the order averaged over the last third

std::string order_metric(double time) { return "lane_order_" + metric_number(time) + "_s"; }

// φ of Rex & Löwen 2007, eq. 2, over the agents of `crowd` now; an agent with nobody within a
// body radius of its lateral position is in a lane of its own (φ_j = 1).
double lane_order(const CrowdSph& crowd) {
  const ParticleSet<2>& agents = crowd.fluid();
  const auto x = agents[crowd.fluid_fields().position];
  const auto heading = agents[*crowd.heading()];
  const Real band = static_cast<Real>(crowd.scene().crowd->body_radius);
  double sum = 0;
  for (std::size_t j = 0; j < agents.size(); ++j) {
    double same = 0, opposite = 0;
    for (std::size_t i = 0; i < agents.size(); ++i) {
      if (i == j || std::abs(x[i][1] - x[j][1]) >= band) continue;
      (heading[i].dot(heading[j]) > 0 ? same : opposite) += 1;
    }
    const double total = same + opposite;
    sum += total > 0 ? (same - opposite) * (same - opposite) / (total * total) : 1;
  }
  return agents.size() > 0 ? sum / static_cast<double>(agents.size()) : 0;
}

// `agents` walking +x and as many −x, all at random over the corridor (1 person/m² for 40 + 40).
RunRecord run_lanes(int agents, const Variant& variant) {
  require_crowd_variant(variant);
  CrowdSph crowd(crowd_counterflow(static_cast<std::size_t>(agents) / 2, corridor_length, corridor_width, end_time));
  std::vector<Metric> series{{order_metric(0), lane_order(crowd)}};
  double late_sum = 0;
  int late_samples = 0;
  double next_sample = sample_interval;
  const auto start = std::chrono::steady_clock::now();
  while (crowd.time() < end_time * (1 - 1e-12)) {
    crowd.step();
    if (crowd.time() < next_sample * (1 - 1e-12)) continue;
    const double phi = lane_order(crowd);
    series.push_back({order_metric(next_sample), phi});
    if (next_sample >= late_from) {
      late_sum += phi;
      ++late_samples;
    }
    next_sample += sample_interval;
  }
  const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<Metric> metrics{{"lane_order", late_sum / late_samples}, {"lane_order_start", series.front().value}};
  metrics.insert(metrics.end(), series.begin(), series.end());
  return crowd_record("crowd_lanes", variant, agents, static_cast<std::size_t>(agents), crowd.step_count(),
                      wall_seconds, std::move(metrics));
}

std::string order_script(const std::string& output, const std::vector<RunRecord>& runs) {
  std::ostringstream script;
  script << png_terminal(output) << "set title 'Crowd: counter-flow in a periodic corridor, lane order'\n"
         << "set xlabel 'time (s)'\nset ylabel 'lane order parameter (Rex & Loewen 2007)'\nset grid\n"
         << "set key top left\nset yrange [0:1]\n";
  std::vector<double> times;
  for (double time = 0; time <= end_time + 1e-9; time += sample_interval) times.push_back(time);
  for (std::size_t r = 0; r < runs.size(); ++r)
    script << metric_block("order" + std::to_string(r), runs[r], times, order_metric);
  script << "plot 1 with lines dashtype 2 title 'lanes'";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    script << ", $order" << r << " using 1:2 with linespoints pointtype 7 title "
           << gnuplot_string(std::to_string(runs[r].resolution) + " agents");
  }
  script << '\n';
  return script.str();
}

}  // namespace

Case crowd_lanes_case() {
  Case c;
  c.name = "crowd_lanes";
  c.title = "Crowd: counter-flow lanes in a periodic corridor";
  c.reference =
      "the lane order parameter of Rex & Löwen 2007 (Phys. Rev. E 75, 051402, eq. 2), φ = mean over the agents of "
      "((n_same − n_opposite)/(n_same + n_opposite))², n counting the other agents whose lateral position is within a "
      "body radius of the agent's along the whole corridor, walking its way or the other: 1 in lanes, about "
      "1/n at random (0.106 at the random start here). Lanes: φ ≥ 0.5 over 40–60 s, an agent's band holding on average "
      "at least "
      "(1 + √0.5)/2 = 85% agents walking its way, beyond the 0.07–0.42 that samples of runs without lanes wander "
      "over. Half the agents walk +x, half −x, all placed at random over a corridor 20 m × 4 m periodic "
      "along its length, 60 s";
  c.resolution_meaning = "agents in the corridor (half each way)";
  c.metric_notes = {"lane_order: φ averaged over 40–60 s (sampled every 5 s)",
                    "lane_order_start: φ of the random start, the random-mixing value", "lane_order_t_s: φ at t s"};
  c.resolutions = {80};
  c.test_resolution = 80;
  c.schemes = {std::string(crowd_scheme)};
  c.kernels = {KernelType::wendland_c2};
  c.figures = {{"crowd_lanes_order.png", "Crowd: lane order against time", order_script}};
  c.run = run_lanes;
  return c;
}

}  // namespace tide::validation
