// 3D dam break: the shipped scene in Lobovsky et al.'s 2014 geometry (scenes/dam_break_3d_lobovsky.json)
// at low resolution. Its column and tank have the proportions of Colagrossi & Landrini's 2D case
// and the column spans the tank's width, so the flow is quasi-2D and its end-wall pressure at
// 0.2H, p/(ρgH) against t sqrt(g/H), is compared with Buchner's 2002 measurement like the 2D case's.

#include <algorithm>
#include <stdexcept>

#include "case_support.hpp"
#include "impact_pressure.hpp"
#include "tide/io/scene_reader.hpp"
#include "tide/solvers/particle_sampling.hpp"

namespace tide::validation {
namespace {

constexpr double height = 0.3;  // H, Lobovsky's column
constexpr char buchner_probe[] = "p_60mm";

scene::Scene lobovsky_scene(int cells, const Variant& variant) {
  scene::Scene s = io::read_scene_file(std::string(TIDE_SCENES_DIR) + "/dam_break_3d_lobovsky.json");
  s.particle_spacing = height / cells;
  apply_variant(s, variant);
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * s.particle_spacing, 3);
  return s;
}

RunRecord run_lobovsky(int cells, const Variant& variant) {
  const scene::Scene s = lobovsky_scene(cells, variant);
  const auto probe =
      std::find_if(s.probes.begin(), s.probes.end(), [](const scene::Probe& p) { return p.name == buchner_probe; });
  if (probe == s.probes.end()) throw std::runtime_error(s.source + ": no probe \"" + buchner_probe + "\"");
  const auto simulation = make_simulation<3>(s);
  return run_against_buchner<3>("dam_break_3d", variant, cells, *simulation, to_vector<3>(probe->position), height);
}

}  // namespace

Case dam_break_3d_case() {
  Case c;
  c.name = "dam_break_3d";
  c.title = "3D dam break (Lobovsky geometry), end-wall pressure";
  c.reference =
      "scenes/dam_break_3d_lobovsky.json (Lobovsky et al. 2014, H = 0.3 m, column across the 0.15 m width): the "
      "end-wall pressure at 0.2H and mid-width against Buchner 2002, p/(ρgH) against t sqrt(g/H), the same "
      "proportions as the 2D dam_break_buchner case";
  c.resolution_meaning = "particles over the column height H (the width holds half as many)";
  c.metric_notes = buchner_metric_notes();
  // 24 particles over H take 15 minutes per variant (the narrow tank has 4–8 wall particles per
  // fluid particle): the study runs 12 and 16; `--resolutions 24` runs the finer one.
  c.resolutions = {12, 16};
  c.test_resolution = 12;
  c.run = run_lobovsky;
  return c;
}

}  // namespace tide::validation
