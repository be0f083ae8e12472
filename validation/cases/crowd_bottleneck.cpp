// Case (b) of issue 36: the flow through a door against its width (docs/crowds.md,
// "Bottleneck"). Pedestrian experiments find the flow growing linearly with the width (Seyfried
// et al. 2009, Transportation Science 43; Liao et al. 2014, Transportation Research Procedia 2,
// up to 5 m) and the specific flow (per metre of width) constant once two or more people pass
// side by side (Kretz, Grünebohm & Schreckenberg 2006, J. Stat. Mech. P10014); the level against
// the measured flows of validation/data/bottleneck_flow_experiments.csv.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "../report_support.hpp"
#include "crowd_support.hpp"
#include "tide/solvers/crowd_sph.hpp"
#include "tide/validation/crowd_scenes.hpp"
#include "tide/validation/report.hpp"

namespace tide::validation {
namespace {

constexpr double widths[] = {1.6, 2.0, 2.4};  // m: three to four bodies (0.5 m) side by side
constexpr double end_time = 120;              // s

// The measured flows (persons/s) against the width: column 1 Seyfried et al. 2009, 2 Kretz et al.
// 2006, 3 Liddle et al. 2011, the one series that spans the widths above.
constexpr int seyfried_column = 1, kretz_column = 2, liddle_column = 3;
const Curve& measured(int column) {
  static const Curve curves[] = {read_reference("bottleneck_flow_experiments.csv", 0, seyfried_column),
                                 read_reference("bottleneck_flow_experiments.csv", 0, kretz_column),
                                 read_reference("bottleneck_flow_experiments.csv", 0, liddle_column)};
  return curves[column - 1];
}

std::string flow_metric(double width) { return "flow_" + metric_number(width) + "_per_s"; }
std::string specific_metric(double width) { return "specific_flow_" + metric_number(width) + "_per_m_s"; }
std::string error_metric(double width) { return "specific_flow_error_" + metric_number(width); }

// `agents` at random in the left 7 m of a 10 m × 8 m room leave through a door `width` wide in
// the middle of its right wall: the flow is the middle 60% of them over the time between the
// first and the last of those out, while a crowd waits at the door.
RunRecord run_bottleneck(int agents, const Variant& variant) {
  require_crowd_variant(variant);
  const auto first_counted = static_cast<std::size_t>(std::lround(0.2 * agents));
  const auto last_counted = static_cast<std::size_t>(std::lround(0.8 * agents));
  std::vector<Metric> flows, specific, errors;
  std::vector<double> specific_values;
  double squared_error = 0;
  double wall_seconds = 0;
  std::uint64_t steps = 0;
  for (const double width : widths) {
    CrowdRoom room;
    room.length = 10;
    room.width = 8;
    room.door = width;
    room.agents = R"([{"region": {"min": [0.5, 0.5], "max": [7.5, 7.5]}, "count": )" + std::to_string(agents) +
                  R"(, "placement": "random"}])";
    room.end = end_time;
    CrowdSph crowd(crowd_room(room));
    double first = -1, last = -1;
    const auto start = std::chrono::steady_clock::now();
    while (crowd.time() < end_time && last < 0) {
      crowd.step();
      const std::size_t out = crowd.exited()[0];
      if (first < 0 && out >= first_counted) first = crowd.time();
      if (out >= last_counted) last = crowd.time();
    }
    wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    steps += crowd.step_count();
    if (!(last > first && first >= 0))
      throw std::runtime_error("fewer than " + std::to_string(last_counted) + " agents out of the " +
                               format_shortest(width) + " m door by " + format_shortest(end_time) + " s");
    const double flow = static_cast<double>(last_counted - first_counted) / (last - first);
    flows.push_back({flow_metric(width), flow});
    specific.push_back({specific_metric(width), flow / width});
    specific_values.push_back(flow / width);
    // Against Liddle et al.'s flow at this width (linear between their widths 2.2 and 2.5 m for 2.4).
    const double error = flow / measured(liddle_column).at(width) - 1;
    errors.push_back({error_metric(width), error});
    squared_error += error * error;
  }
  const double mean = std::accumulate(specific_values.begin(), specific_values.end(), 0.0) /
                      static_cast<double>(specific_values.size());
  double spread = 0;
  for (const double value : specific_values) spread = std::max(spread, std::abs(value / mean - 1));
  std::vector<Metric> metrics{
      {"specific_flow_spread", spread},
      {"mean_specific_flow_per_m_s", mean},
      {"specific_flow_rms_error", std::sqrt(squared_error / static_cast<double>(std::size(widths)))}};
  metrics.insert(metrics.end(), errors.begin(), errors.end());
  metrics.insert(metrics.end(), specific.begin(), specific.end());
  metrics.insert(metrics.end(), flows.begin(), flows.end());
  return crowd_record("crowd_bottleneck", variant, agents, static_cast<std::size_t>(agents) * std::size(widths), steps,
                      wall_seconds, std::move(metrics));
}

// Flow against the door's width, with the line through zero at each run's mean specific flow, and
// the three measured series.
std::string flow_script(const std::string& output, const std::vector<RunRecord>& runs) {
  std::ostringstream script;
  script << png_terminal(output) << "set title 'Crowd: flow through a door against its width'\n"
         << "set xlabel 'door width (m)'\nset ylabel 'flow (persons/s)'\nset grid\nset key top left\n"
         << "set xrange [0:3]\nset yrange [0:*]\n";
  for (std::size_t r = 0; r < runs.size(); ++r)
    script << metric_block("flow" + std::to_string(r), runs[r], widths, flow_metric);
  const std::pair<int, const char*> series[] = {{seyfried_column, "Seyfried et al. 2009"},
                                                {kretz_column, "Kretz et al. 2006"},
                                                {liddle_column, "Liddle et al. 2011"}};
  for (const auto& [column, title] : series) {
    const Curve& curve = measured(column);
    script << "$measured" << column << " << EOD\n";
    for (std::size_t k = 0; k < curve.x.size(); ++k) script << curve.x[k] << ' ' << curve.y[k] << '\n';
    script << "EOD\n";
  }
  script << "plot ";
  for (const auto& [column, title] : series)
    script << "$measured" << column << " using 1:2 with points pointtype " << 4 + 2 * column << " title "
           << gnuplot_string(std::string(title) + " (measured)") << ", ";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const double mean = detail::metric_value(runs[r], "mean_specific_flow_per_m_s").value();
    script << (r > 0 ? ", " : "") << "$flow" << r << " using 1:2 with points pointtype 7 pointsize 1.5 title "
           << gnuplot_string(std::to_string(runs[r].resolution) + " agents") << ", " << mean << " * x with lines title "
           << gnuplot_string("flow = " + format_shortest(std::round(mean * 1000) / 1000) + " persons/(m s) × width");
  }
  script << '\n';
  return script.str();
}

}  // namespace

Case crowd_bottleneck_case() {
  Case c;
  c.name = "crowd_bottleneck";
  c.title = "Crowd: flow through a door against its width";
  c.reference =
      "the shape the experiments find: flow growing linearly with the width through zero, a constant specific "
      "flow, once two or more people pass side by side (Seyfried et al. 2009; Liao et al. 2014; Kretz, Grünebohm & "
      "Schreckenberg 2006), and the level against the flows measured by Liddle et al. 2011 at 0.9–2.5 m "
      "(validation/data/bottleneck_flow_experiments.csv, with Seyfried et al.'s and Kretz et al.'s up to 1.2 m in "
      "the plot). A 10 m × 8 m room, the agents at random in its left 7 m, a door 0.3 m deep, 1.6, 2.0 and 2.4 m wide; "
      "the flow over the middle 60% of the agents out";
  c.resolution_meaning = "agents in the room";
  c.metric_notes = {"specific_flow_spread: max over the widths of |specific flow / their mean − 1|",
                    "mean_specific_flow_per_m_s: the mean of the specific flows, persons/(m s)",
                    "specific_flow_rms_error: sqrt(mean over the widths of specific_flow_error²)",
                    "specific_flow_error_b: flow / Liddle et al. 2011's measured flow − 1 at width b (linear "
                    "between their widths)",
                    "specific_flow_b_per_m_s: flow / width through the door b m wide (1_6 is 1.6 m)",
                    "flow_b_per_s: the flow through it, persons/s"};
  c.resolutions = {100};
  c.test_resolution = 100;
  c.schemes = {std::string(crowd_scheme)};
  c.kernels = {KernelType::wendland_c2};
  c.figures = {{"crowd_bottleneck_flow.png", "Crowd: flow against the door's width", flow_script}};
  c.run = run_bottleneck;
  return c;
}

}  // namespace tide::validation
