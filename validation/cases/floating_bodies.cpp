// Rigid bodies in water at rest: Archimedes' floating box and a neutrally buoyant ball.

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "case_support.hpp"

namespace tide::validation {
namespace {

constexpr double gravity = 9.81;
constexpr double water_density = 1000;

// Water `depth` deep in a tank `width` wide (square in 3D) and twice as high.
scene::Scene tank(int dimension, double width, double depth, double spacing, double sound_speed,
                  const Variant& variant) {
  return water_tank(dimension, width, depth, 2 * depth, spacing,
                    {"water", water_density, 1e-6, sound_speed, std::nullopt}, variant);
}

// The box: B wide, H = B/2 high, ρ_b/ρ_f = 1/2, so its metacentric height
// GM = d/2 + B²/(12 d) − H/2 is B/6 − B/4 + B/3 > 0 at the draft d = H/2: upright is stable
// (for a square section in 2D, a square footprint in 3D).
constexpr double box_width = 0.2, box_height = 0.1, density_ratio = 0.5;
constexpr double sample_interval = 0.005;  // s, between the draft's samples once settled

struct FloatingBoxSetup {
  double tank_width, water_depth, settle_start, end;
};

FloatingBoxSetup floating_box_setup(int dimension) {
  return dimension == 2 ? FloatingBoxSetup{0.6, 0.3, 2.0, 3.0} : FloatingBoxSetup{0.4, 0.15, 1.0, 1.5};
}

// The box let go upright and at rest with its bottom 3 cm under the still water, 2 cm above its
// draft.
scene::Scene floating_box_scene(int dimension, int rows, const Variant& variant) {
  const FloatingBoxSetup setup = floating_box_setup(dimension);
  scene::Scene s = tank(dimension, setup.tank_width, setup.water_depth, box_height / rows, 20.0, variant);
  s.source = "floating box";
  const int up = dimension - 1;
  const double low = (setup.tank_width - box_width) / 2;
  scene::Box box{{low, low, low}, {low + box_width, low + box_width, low + box_width}};
  box.min[up] = setup.water_depth - 0.03;
  box.max[up] = box.min[up] + box_height;
  if (dimension == 2) box.min[2] = box.max[2] = 0;
  scene::Obstacle obstacle;
  obstacle.shape = box;
  obstacle.body = scene::Body{density_ratio * water_density, {}};
  s.walls.obstacles.push_back(obstacle);
  return s;
}

// Where the still water's surface is away from the body, two ways, over the fluid particles in
// the columns (cells of Δx across the floor) whose centres lie at least `clearance` outside the
// body's footprint: `top`, the mean height of each column's topmost particle plus half a spacing
// (that particle's share), and `hydrostatic`, the height y + p/(ρ g) at which the pressure of the
// particles deeper than one kernel support below `top` would fall to zero. The free surface of SPH
// is fuzzy by about a spacing (the density summation is short of neighbours there); the second is
// the level the pressure under the body is measured from.
struct WaterLevel {
  double top = 0;
  double hydrostatic = 0;
};

template <int D>
WaterLevel water_level(const Simulation<D>& simulation, const Eigen::Vector3d& footprint_centre, double footprint_half,
                       double clearance) {
  const double spacing = simulation.scene().particle_spacing;
  const auto& fluid = simulation.fluid();
  const auto x = fluid[simulation.fluid_fields().position];
  const auto p = fluid[simulation.fluid_fields().pressure];
  const auto rho = fluid[simulation.fluid_fields().density];
  const auto column = [&](std::size_t i) {
    return std::pair<long, long>{std::lround(std::floor(x[i][0] / spacing)),
                                 D == 3 ? std::lround(std::floor(x[i][1] / spacing)) : 0};
  };
  const auto clear = [&](const std::pair<long, long>& cell) {
    double outside = 0;
    for (int d = 0; d < D - 1; ++d) {
      const double centre = ((d == 0 ? cell.first : cell.second) + 0.5) * spacing;
      const double gap = std::abs(centre - footprint_centre[d]) - footprint_half;
      outside += gap > 0 ? gap * gap : 0;
    }
    return std::sqrt(outside) >= clearance;
  };
  std::map<std::pair<long, long>, double> top;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const auto [entry, added] = top.try_emplace(column(i), x[i][D - 1]);
    if (!added) entry->second = std::max(entry->second, static_cast<double>(x[i][D - 1]));
  }
  WaterLevel level;
  int columns = 0;
  for (const auto& [cell, height] : top) {
    if (!clear(cell)) continue;
    level.top += height;
    ++columns;
  }
  if (columns == 0) throw std::runtime_error("floating box: no water column clear of the box");
  level.top = level.top / columns + spacing / 2;
  const double support = kernel_support_factor(simulation.scene().kernel) * simulation.smoothing_length();
  const double g = simulation.gravity().norm();
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (x[i][D - 1] > level.top - support || !clear(column(i))) continue;
    sum += x[i][D - 1] + p[i] / (rho[i] * g);
    ++count;
  }
  level.hydrostatic = sum / count;
  return level;
}

// The angle between the body's up axis and the vertical.
double tilt(const RigidBody& body, int dimension) {
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  up[dimension - 1] = 1;
  return std::acos(std::clamp((body.orientation() * up).dot(up), -1.0, 1.0));
}

template <int D>
RunRecord run_floating_box(const std::string& name, int rows, const Variant& variant) {
  const FloatingBoxSetup setup = floating_box_setup(D);
  const auto simulation_owner = make_simulation<D>(floating_box_scene(D, rows, variant));
  Simulation<D>& simulation = *simulation_owner;
  if (simulation.bodies() == nullptr || simulation.bodies()->size() != 1)
    throw std::runtime_error(name + ": the scheme did not take the box as a body");
  const RigidBody& box = simulation.bodies()->body(0);
  const Eigen::Vector3d footprint = box.centre();
  double draft_sum = 0, surface_draft_sum = 0, worst_tilt = 0, late_speed = 0, next_sample = setup.settle_start;
  int samples = 0;
  const double wall_seconds = run_until(simulation, setup.end, [&](const Simulation<D>& s) {
    worst_tilt = std::max(worst_tilt, tilt(box, D));
    if (s.time() < setup.settle_start) return;
    late_speed = std::max(late_speed, box.velocity().norm());
    if (s.time() < next_sample) return;
    next_sample += sample_interval;
    const WaterLevel level = water_level(s, footprint, box_width / 2, box_width / 2);
    const double bottom = box.centre()[D - 1] - box_height / 2;
    draft_sum += level.hydrostatic - bottom;
    surface_draft_sum += level.top - bottom;
    ++samples;
  });
  const double expected = density_ratio * box_height;
  const double draft = draft_sum / samples, surface_draft = surface_draft_sum / samples;
  return make_record(name, variant, rows, simulation, wall_seconds,
                     {{"draft_error", std::abs(draft - expected) / expected},
                      {"draft_over_expected", draft / expected},
                      {"surface_draft_over_expected", surface_draft / expected},
                      {"max_tilt_rad", worst_tilt},
                      {"late_speed_m_per_s", late_speed}});
}

// A body at the middle of water 0.4 m deep, of the density the water has there under the
// equation of state (Tait, ρ = ρ0 (1 + γ p/(ρ0 c0²))^(1/γ) with p = ρ0 g d: 1.019 ρ0 at this d and
// c0 = 10 m/s): a ball 0.1 m across, or a box 0.2 m wide and 0.1 m high on the fluid's lattice.
// Gravity is raised over the first second and the body held until the second second
// (scene::Body::release_time), so that the water has settled round it; its drift is measured
// over the two seconds after.
constexpr double neutral_depth = 0.4, body_size = 0.1, release_time = 2.0, drift_time = 2.0;

scene::Scene neutral_body_scene(bool ball, int rows, const Variant& variant) {
  scene::Scene s = tank(2, neutral_depth, neutral_depth, body_size / rows, 10.0, variant);
  s.source = ball ? "neutrally buoyant ball" : "neutrally buoyant box";
  s.solver.gravity_ramp_time = 1.0;
  const double c0 = *s.materials[0].sound_speed, gamma = s.solver.tait_exponent;
  const double depth = neutral_depth / 2, centre = neutral_depth / 2;
  const double density = water_density * std::pow(1 + gamma * gravity * depth / (c0 * c0), 1 / gamma);
  scene::Obstacle body;
  if (ball) {
    body.shape = scene::Ball{{centre, centre, 0}, body_size / 2};
  } else {
    body.shape =
        scene::Box{{centre - body_size, centre - body_size / 2, 0}, {centre + body_size, centre + body_size / 2, 0}};
  }
  body.body = scene::Body{density, {}, release_time};
  s.walls.obstacles.push_back(body);
  return s;
}

RunRecord run_neutral_body(bool ball, int rows, const Variant& variant) {
  const std::string name = ball ? "neutral_ball" : "neutral_box";
  const auto simulation_owner = make_simulation<2>(neutral_body_scene(ball, rows, variant));
  Simulation<2>& simulation = *simulation_owner;
  if (simulation.bodies() == nullptr || simulation.bodies()->size() != 1)
    throw std::runtime_error(name + ": the scheme did not take the body");
  const RigidBody& body = simulation.bodies()->body(0);
  const Eigen::Vector3d start = body.centre();
  double drift = 0, rise = 0;
  const double wall_seconds = run_until(simulation, release_time + drift_time, [&](const Simulation<2>&) {
    drift = std::max(drift, (body.centre() - start).norm());
    rise = body.centre().y() - start.y();
  });
  const double spacing = simulation.scene().particle_spacing;
  return make_record(name, variant, rows, simulation, wall_seconds,
                     {{"drift_over_spacing", drift / spacing},
                      {"rise_over_spacing", rise / spacing},
                      {"end_speed_m_per_s", body.velocity().norm()}});
}

}  // namespace

Case floating_box_case(int dimension) {
  Case c;
  c.name = dimension == 2 ? "floating_box_2d" : "floating_box_3d";
  c.title = dimension == 2 ? "Archimedes' floating box, 2D" : "Archimedes' floating box, 3D";
  c.reference = "a box of half the water's density floats upright at the draft ρ_b/ρ_f × H (Archimedes)";
  c.resolution_meaning = "particle rows over the box's height H = 0.1 m";
  c.metric_notes = {
      "draft_error: |d − d₀| / d₀, d the mean draft once settled below the still water's hydrostatic "
      "level (y + p/(ρ g) of the particles away from the box), d₀ = H/2",
      "draft_over_expected: d / d₀",
      "surface_draft_over_expected: the same below the still water's top particles plus Δx/2",
      "max_tilt_rad: the largest angle between the box's up axis and the vertical",
      "late_speed_m_per_s: the box's largest speed once settled"};
  c.schemes = {"wcsph", "wcsph_continuity"};
  if (dimension == 2) {
    c.resolutions = {10, 20};
    c.test_resolution = 10;
    c.run = [](int rows, const Variant& variant) { return run_floating_box<2>("floating_box_2d", rows, variant); };
  } else {
    c.resolutions = {5, 10};
    c.test_resolution = 5;
    c.run = [](int rows, const Variant& variant) { return run_floating_box<3>("floating_box_3d", rows, variant); };
  }
  return c;
}

Case neutral_body_case(bool ball) {
  Case c;
  c.name = ball ? "neutral_ball" : "neutral_box";
  c.title = ball ? "Neutrally buoyant ball in water at rest, 2D" : "Neutrally buoyant box in water at rest, 2D";
  c.reference = "a body of the density of the water round it stays where it is let go (drift < 0.1 Δx over 2 s)";
  c.resolution_meaning = ball ? "particles across the ball's diameter" : "particle rows over the box's height";
  c.metric_notes = {
      "drift_over_spacing: the centre's largest distance from where it was let go, over the 2 s "
      "after, over Δx",
      "rise_over_spacing: the centre's height at the end above where it was let go, over Δx",
      "end_speed_m_per_s: the body's speed at the end"};
  c.schemes = {"wcsph", "wcsph_continuity"};
  c.resolutions = {10, 20};
  c.test_resolution = 10;
  c.run = [ball](int rows, const Variant& variant) { return run_neutral_body(ball, rows, variant); };
  return c;
}

}  // namespace tide::validation
