#include <algorithm>

#include "cases/case_support.hpp"
#include "tide/validation/case.hpp"

namespace tide::validation {

const std::vector<Case>& cases() {
  static const std::vector<Case> all{hydrostatic_case(2),
                                     hydrostatic_case(3),
                                     poiseuille_case(),
                                     couette_case(),
                                     taylor_green_case(),
                                     dam_break_2d_case(),
                                     dam_break_3d_front_case(),
                                     dam_break_buchner_case(),
                                     dam_break_3d_case(),
                                     lid_driven_cavity_case(100),
                                     lid_driven_cavity_case(1000),
                                     floating_box_case(2),
                                     floating_box_case(3),
                                     neutral_body_case(false),
                                     neutral_body_case(true),
                                     settling_cylinder_case(),
                                     rising_block_case(),
                                     crowd_fundamental_diagram_case(),
                                     crowd_bottleneck_case(),
                                     crowd_single_agent_case(),
                                     crowd_lanes_case()};
  return all;
}

const Case* find_case(std::string_view name) {
  const auto& all = cases();
  const auto found = std::find_if(all.begin(), all.end(), [&](const Case& c) { return c.name == name; });
  return found == all.end() ? nullptr : &*found;
}

const std::vector<std::string>& scheme_names() {
  static const std::vector<std::string> names{
      "wcsph", "wcsph_continuity", "wcsph_riemann", "wcsph_riemann_kgc",      "dfsph",
      "iisph", "dfsph_cg",         "iisph_cg",      std::string(crowd_scheme)};
  return names;
}

const std::vector<std::string>& default_scheme_names() {
  static const std::vector<std::string> names{"wcsph", "wcsph_continuity", "dfsph", "iisph", std::string(crowd_scheme)};
  return names;
}

}  // namespace tide::validation
