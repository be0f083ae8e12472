// Lid-driven cavity: the unit square, closed, its lid (y = 1) sliding at U = 1 in +x, ν = U L / Re,
// started from rest and run to a steady state; the centre-line velocities against Ghia, Ghia &
// Shin 1982 (J. Comput. Phys. 48, Tables I and II): u along x = 0.5 and v along y = 0.5.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "case_support.hpp"

namespace tide::validation {
namespace {

constexpr double lid_speed = 1;  // U, m/s
constexpr double side = 1;       // L, m

// Per Reynolds number: Ghia's column in the reference tables, the simulated time span and the
// resolutions. The end times are where the time-averaged centre lines have settled (measured with
// Wendland C2, summation density): at Re = 100 they change by 0.002–0.004 U over the last time unit
// from t = 8 on, below a quarter of the error at 40 particles; at Re = 1000 (50 particles) the change
// falls to 0.003–0.006 U by t = 26–30 while the error still drifts down by about 1% of U over those
// four units — a longer run would not fit the study's budget (its ladder runs 4 variants).
struct CavitySetup {
  int reynolds;
  int reference_column;  // u_Re* in Table I and v_Re* in Table II
  double end_time;       // s
  std::vector<int> resolutions;
  int test_resolution;
};

CavitySetup setup_for(int reynolds) {
  if (reynolds == 100) return {100, 1, 10.0, {20, 40, 80}, 40};
  if (reynolds == 1000) return {1000, 3, 30.0, {25, 50}, 25};
  throw std::invalid_argument("lid-driven cavity: Ghia et al.'s tables used here hold Re = 100 and 1000 only");
}

scene::Scene cavity_scene(const CavitySetup& setup, int cells, const Variant& variant) {
  scene::Scene s;
  s.source = "lid-driven cavity";
  s.dimension = 2;
  s.particle_spacing = side / cells;
  // c0 = 10 U (max_speed = U): the lid is the fastest thing in the flow.
  s.materials.push_back({"fluid", 1.0, lid_speed * side / setup.reynolds, std::nullopt, lid_speed});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {side, side, 0}}});
  // The open-top container gives the floor and side walls; a plane obstacle at y = L, moving at U,
  // closes it as the lid (its wall particles span the corners above the side walls too).
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {side, side, 0}}, true};
  s.walls.obstacles.push_back(
      {scene::Plane{{0, side, 0}, {0, -1, 0}}, {lid_speed, 0, 0}, std::nullopt, std::nullopt, std::nullopt});
  apply_variant(s, variant);
  const double thickness = s.walls.layers * s.particle_spacing;
  s.domain.box = {{-thickness, -thickness, 0}, {side + thickness, side + thickness, 0}};
  s.gravity = {0, 0, 0};
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  // No background pressure: pressures go negative in the vortex and at the upstream lid corner
  // (down to −1.6 ρ0U² at Re = 1000), but a background pressure p_b turns the particles' disorder
  // into force noise, p_b Σ m_j (1/ρ_i² + 1/ρ_j²) ∇W_ij ≠ 0, which the flow feels as extra
  // dissipation. Measured without shifting (Re = 1000, 50 particles, t = 30, u RMS error): 0.055
  // with p_b = 0, 0.080 with p_b = ρ0U², 0.131 with p_b = 3ρ0U² (the least that keeps every pressure
  // positive); at Re = 100 and 25 particles, p_b = ρ0c0² leaves less than half of the vortex.
  // Fickian shifting keeps the particles from pairing under the negative pressures; measured with
  // and without it (Wendland C2, summation density): Re = 100 at 40 particles, u error 0.0137 and
  // 0.0183 U, vortex minimum 2.0% and 5.8% weak; Re = 1000 at 25, u 0.093 and 0.120 U, vortex 32% and
  // 42% weak; Re = 1000 at 50, u 0.064 and 0.055 U but vortex 12% and 17% weak.
  s.solver.background_pressure = 0;
  s.solver.shifting = scene::Shifting::fickian;
  return s;
}

// Ghia's points strictly inside the cavity (the end points are the wall velocities themselves).
Curve interior(const Curve& table) {
  Curve inside;
  for (std::size_t k = 0; k < table.x.size(); ++k) {
    if (table.x[k] <= 0 || table.x[k] >= side) continue;
    inside.x.push_back(table.x[k]);
    inside.y.push_back(table.y[k]);
  }
  return inside;
}

// What is sampled on the centre lines, by Shepard interpolation: u at (L/2, y) for Table I's y, v
// at (x, L/2) for Table II's x, then u at (L/2, k L/200), k = 1 ... 199, where its minimum is sought.
constexpr int minimum_search_points = 199;

std::vector<double> centreline_samples(const Simulation<2>& simulation, const Curve& u_table, const Curve& v_table) {
  std::vector<double> values;
  for (double y : u_table.x) values.push_back(shepard_velocity<2>(simulation, Vector<2>(side / 2, y))[0]);
  for (double x : v_table.x) values.push_back(shepard_velocity<2>(simulation, Vector<2>(x, side / 2))[1]);
  for (int k = 1; k <= minimum_search_points; ++k)
    values.push_back(shepard_velocity<2>(simulation, Vector<2>(side / 2, side * k / (minimum_search_points + 1)))[0]);
  return values;
}

// The centre-line samples averaged over one time unit ending at `end`, ten instants 0.1 apart: the
// steady state, without the particle noise of a single instant.
std::vector<double> time_averaged_samples(Simulation<2>& simulation, double end, const Curve& u_table,
                                          const Curve& v_table, double& wall_seconds) {
  constexpr int instants = 10;
  std::vector<double> mean;
  for (int k = instants - 1; k >= 0; --k) {
    wall_seconds += run_until(simulation, end - 0.1 * k, [](const Simulation<2>&) {});
    const std::vector<double> values = centreline_samples(simulation, u_table, v_table);
    mean.resize(values.size(), 0.0);
    for (std::size_t i = 0; i < values.size(); ++i) mean[i] += values[i] / instants;
  }
  return mean;
}

// sqrt(mean (a_k − b_k)²) / U over the entries [first, last) of two sample vectors.
double rms_difference(const std::vector<double>& a, const std::vector<double>& b, std::size_t first, std::size_t last) {
  double sum = 0;
  for (std::size_t k = first; k < last; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sum / static_cast<double>(last - first)) / lid_speed;
}

RunRecord run_cavity(const CavitySetup& setup, int cells, const Variant& variant) {
  const Curve u_table = interior(read_reference("ghia_1982_u_vertical_centreline.csv", 0, setup.reference_column));
  const Curve v_table = interior(read_reference("ghia_1982_v_horizontal_centreline.csv", 0, setup.reference_column));
  const std::size_t u_count = u_table.x.size();
  const std::size_t table_count = u_count + v_table.x.size();
  std::vector<double> reference = u_table.y;
  reference.insert(reference.end(), v_table.y.begin(), v_table.y.end());

  const auto simulation_owner = make_simulation<2>(cavity_scene(setup, cells, variant));
  Simulation<2>& simulation = *simulation_owner;
  double wall_seconds = 0;
  std::vector<double> previous;
  std::vector<double> last;
  for (int t = static_cast<int>(setup.end_time) - 1; t <= static_cast<int>(setup.end_time); ++t) {
    previous = last;
    last = time_averaged_samples(simulation, t, u_table, v_table, wall_seconds);
  }
  const double minimum = *std::min_element(last.begin() + static_cast<std::ptrdiff_t>(table_count), last.end());
  const double reference_minimum = *std::min_element(u_table.y.begin(), u_table.y.end());
  return make_record("cavity_re" + std::to_string(setup.reynolds), variant, cells, simulation, wall_seconds,
                     {{"u_centreline_rms_error", rms_difference(last, reference, 0, u_count)},
                      {"v_centreline_rms_error", rms_difference(last, reference, u_count, table_count)},
                      {"u_min_error", std::abs(minimum - reference_minimum) / std::abs(reference_minimum)},
                      {"last_unit_change", rms_difference(last, previous, 0, table_count)}});
}

}  // namespace

Case lid_driven_cavity_case(int reynolds) {
  const CavitySetup setup = setup_for(reynolds);
  Case c;
  c.name = "cavity_re" + std::to_string(reynolds);
  c.title = "Lid-driven cavity, Re = " + std::to_string(reynolds);
  c.reference = "the centre-line velocities of Ghia, Ghia & Shin 1982 (Tables I and II), unit square, lid speed 1";
  c.resolution_meaning = "particles across the cavity";
  c.metric_notes = {
      "u_centreline_rms_error: RMS of (u − u_Ghia)/U at Ghia's 15 interior points on x = 0.5, u sampled by Shepard "
      "interpolation and averaged over the last time unit (10 instants)",
      "v_centreline_rms_error: the same for v at Ghia's 15 interior points on y = 0.5",
      "u_min_error: |min u − min u_Ghia| / |min u_Ghia| on x = 0.5, the primary vortex's return flow (u averaged as "
      "above, its minimum sought every L/200)",
      "last_unit_change: RMS over both centre lines of the change of the time-averaged u, v from the time unit "
      "before the last to the last, /U (how steady the end state is)"};
  c.resolutions = setup.resolutions;
  c.test_resolution = setup.test_resolution;
  c.run = [setup](int cells, const Variant& variant) { return run_cavity(setup, cells, variant); };
  return c;
}

}  // namespace tide::validation
