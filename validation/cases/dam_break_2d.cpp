// Dam break: the surge front of a water column a wide and 2a high (a = 2.25 in) released in a
// tank 5a long, against the experiments of Martin & Moyce 1952 and Koshizuka & Oka 1996. In 2D,
// and in 3D as the same column a/2 deep between free-slip side walls: a plane flow computed by
// the 3D passes, so the same front and the same experiments apply.

#include <algorithm>
#include <cmath>

#include "case_support.hpp"

namespace tide::validation {
namespace {

constexpr double gravity = 9.81;
constexpr double column_width = 0.05715;  // a = 2.25 in
constexpr double first_compared = 0.4;    // T range compared (the front reaches the far wall at T ≈ 2.9)
constexpr double last_compared = 2.5;
constexpr double run_end = 3;  // T at which a run stops: the length of the timings issue 8 compares with

// x along the tank, the last axis up; in 3D the column is a/2 deep (y).
template <int D>
scene::Scene column_scene(int cells, const Variant& variant) {
  const double a = column_width;
  const double depth = D == 3 ? a / 2 : 0;
  const auto point = [](double along, double across, double up) {
    return D == 2 ? scene::Vec{along, up, 0} : scene::Vec{along, across, up};
  };
  scene::Scene s;
  s.source = D == 2 ? "2d dam break" : "3d dam break (plane column)";
  s.dimension = D;
  s.particle_spacing = a / cells;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, std::sqrt(2 * gravity * 2 * a)});
  s.fluid.push_back({0, scene::Box{point(0, 0, 0), point(a, depth, 2 * a)}});
  s.walls.container = scene::Container{scene::Box{point(0, 0, 0), point(5 * a, depth, 3 * a)}, true};
  s.walls.slip = scene::WallSlip::free_slip;
  apply_variant(s, variant);
  const double margin = s.walls.layers * s.particle_spacing;
  s.domain.box = {point(-margin, -margin, -margin), point(5 * a + margin, depth + margin, 6 * a)};
  s.gravity = point(0, 0, -gravity);
  return s;
}

/// The front Z = x_front/a against T = t sqrt(2g/a) until T = `end_T`; the front is the
/// rightmost particle plus half a spacing (the edge of its volume).
template <int D>
Curve dam_break_front(int cells, const Variant& variant, double end_T, double* wall_seconds, std::size_t* particles,
                      std::uint64_t* steps) {
  const scene::Scene s = column_scene<D>(cells, variant);
  const auto simulation_owner = make_simulation<D>(s);
  Simulation<D>& simulation = *simulation_owner;
  const double time_scale = std::sqrt(2 * gravity / column_width);
  Curve front;
  const auto track = [&](const Simulation<D>& sim) {
    const auto x = sim.fluid()[sim.fluid_fields().position];
    double x_front = 0;
    for (std::size_t i = 0; i < sim.fluid().size(); ++i) x_front = std::max<double>(x_front, x[i][0]);
    front.x.push_back(sim.time() * time_scale);
    front.y.push_back((x_front + s.particle_spacing / 2) / column_width);
  };
  *wall_seconds = run_until(simulation, end_T / time_scale, track);
  *particles = simulation.fluid().size();
  *steps = simulation.step_count();
  return front;
}

template <int D>
RunRecord run_column(int cells, const Variant& variant) {
  RunRecord record;
  const Curve front =
      dam_break_front<D>(cells, variant, run_end, &record.wall_seconds, &record.particles, &record.steps);
  const OffsetFit martin_moyce =
      fit_start_offset(front, read_reference("martin_moyce_1952_front.csv"), first_compared, last_compared);
  const OffsetFit koshizuka_oka =
      fit_start_offset(front, read_reference("koshizuka_oka_1996_front.csv"), first_compared, last_compared);
  record.case_name = D == 2 ? "dam_break_2d" : "dam_break_3d_front";
  record.scheme = variant.scheme;
  record.kernel = std::string(kernel_name(variant.kernel));
  record.resolution = cells;
  record.metrics = {{"front_error_after_offset", martin_moyce.error_after_offset},
                    {"front_raw_error", martin_moyce.raw_error},
                    {"start_offset", martin_moyce.offset},
                    {"front_error_after_offset_ko", koshizuka_oka.error_after_offset},
                    {"front_raw_error_ko", koshizuka_oka.raw_error},
                    {"start_offset_ko", koshizuka_oka.offset}};
  return record;
}

Case column_case() {
  Case c;
  c.reference =
      "Martin & Moyce 1952 (tables 2 and 6, a = 2.25 in) and Koshizuka & Oka 1996: front Z = x/a against "
      "T = t sqrt(2g/a)";
  c.resolution_meaning = "particles across the column width a";
  c.metric_notes = {
      "front_error_after_offset: mean |Z − Z_exp(T − δT)| / Z_exp over 0.4 ≤ T ≤ 2.5 against Martin & Moyce, after "
      "fitting one start offset δT for the experiment's gate",
      "front_raw_error: the same with δT = 0", "start_offset: the fitted δT",
      "front_error_after_offset_ko, front_raw_error_ko, start_offset_ko: the same against Koshizuka & Oka"};
  return c;
}

}  // namespace

Case dam_break_2d_case() {
  Case c = column_case();
  c.name = "dam_break_2d";
  c.title = "2D dam break, surge front";
  c.resolutions = {10, 20, 40, 80};
  c.test_resolution = 20;
  c.run = run_column<2>;
  return c;
}

// 20 particles across a: 20 × 10 × 40 = 8000 particles.
Case dam_break_3d_front_case() {
  Case c = column_case();
  c.name = "dam_break_3d_front";
  c.title = "3D dam break (the 2D column, a/2 deep between free-slip side walls), surge front";
  c.resolutions = {10, 20};
  c.test_resolution = 10;
  c.run = run_column<3>;
  return c;
}

}  // namespace tide::validation
