// 2D dam break in the Colagrossi–Landrini geometry: the pressure on the downstream wall at 0.2H
// against Buchner's 2002 measurement (Colagrossi & Landrini 2003, J. Comput. Phys. 191:448–475).

#include <cmath>

#include "case_support.hpp"
#include "impact_pressure.hpp"

namespace tide::validation {
namespace {

constexpr double gravity = 9.81;
constexpr double rest_density = 1000;
constexpr double height = 0.6;                  // H, the column's height
constexpr double tank_length = 5.366 * height;  // the probe's wall
constexpr double probe_height = 0.2 * height;

// Column H high and 2H long at the left end of a closed tank 5.366H long and 3H high, free-slip
// walls as in Colagrossi & Landrini; `cells` particles over H.
scene::Scene buchner_scene(int cells, const Variant& variant) {
  scene::Scene s;
  s.source = "2d dam break, Buchner pressure";
  s.dimension = 2;
  s.particle_spacing = height / cells;
  s.materials.push_back({"water", rest_density, 1e-6, std::nullopt, std::sqrt(2 * gravity * height)});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {2 * height, height, 0}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {tank_length, 3 * height, 0}}, false};
  s.walls.slip = scene::WallSlip::free_slip;
  apply_variant(s, variant);
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * s.particle_spacing, 2);
  s.gravity = {0, -gravity, 0};
  return s;
}

RunRecord run_buchner(int cells, const Variant& variant) {
  const auto simulation = make_simulation<2>(buchner_scene(cells, variant));
  return run_against_buchner<2>("dam_break_buchner", variant, cells, *simulation,
                                Vector<2>{Real(tank_length), Real(probe_height)}, height);
}

}  // namespace

Case dam_break_buchner_case() {
  Case c;
  c.name = "dam_break_buchner";
  c.title = "2D dam break, downstream-wall pressure";
  c.reference =
      "Buchner 2002 (digitised by the PySPH authors): p/(ρgH) against τ = t sqrt(g/H) at 0.2H on the downstream "
      "wall, H = 0.6 m column 2H long in a tank 5.366H long (Colagrossi & Landrini 2003)";
  c.resolution_meaning = "particles over the column height H";
  c.metric_notes = buchner_metric_notes();
  c.resolutions = {20, 40, 80};
  c.test_resolution = 40;
  c.run = run_buchner;
  return c;
}

}  // namespace tide::validation
