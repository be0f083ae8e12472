#include "crowd_setup.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "simulation_setup.hpp"
#include "tide/core/scene_error.hpp"

namespace tide::crowd_setup {
namespace {

std::string point_text(const Vector<2>& x) {
  return "[" + setup::format_number(static_cast<double>(x[0])) + ", " +
         setup::format_number(static_cast<double>(x[1])) + "]";
}

}  // namespace

NavigationField navigation_field(const scene::Scene& scene, const Interactions<2>& interactions) {
  const scene::Crowd& crowd = *scene.crowd;
  NavigationField::Grid grid;
  grid.cell = crowd.navigation_cell;
  for (int d = 0; d < 2; ++d) {
    grid.lower[d] = scene.domain.box.min[d];
    grid.cells[d] = static_cast<std::size_t>(
        std::max(1.0, std::ceil((scene.domain.box.max[d] - scene.domain.box.min[d]) / grid.cell - 1e-9)));
    grid.periodic[d] = scene.domain.periodic[d];
  }
  const std::size_t nx = grid.cells[0], ny = grid.cells[1];
  const auto centre = [&](std::size_t cx, std::size_t cy) {
    return std::array<double, 2>{grid.lower[0] + (static_cast<double>(cx) + 0.5) * grid.cell,
                                 grid.lower[1] + (static_cast<double>(cy) + 0.5) * grid.cell};
  };
  std::vector<bool> blocked(nx * ny, false), goal(nx * ny, false);
  const double reach = scene.particle_spacing / 2 + crowd.body_radius;
  const auto cell_range = [&](double low, double high, int d) {
    const double first = std::floor((low - grid.lower[d]) / grid.cell);
    const double last = std::floor((high - grid.lower[d]) / grid.cell);
    const double n = static_cast<double>(grid.cells[d]) - 1;
    return std::pair{static_cast<std::size_t>(std::clamp(first, 0.0, n)),
                     static_cast<std::size_t>(std::clamp(last, 0.0, n))};
  };
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const auto x = interactions.contact(k).positions();
    for (std::size_t b = 0; b < interactions.contact(k).particles().size(); ++b) {
      const double bx = static_cast<double>(x[b][0]), by = static_cast<double>(x[b][1]);
      const auto [x0, x1] = cell_range(bx - reach, bx + reach, 0);
      const auto [y0, y1] = cell_range(by - reach, by + reach, 1);
      for (std::size_t cy = y0; cy <= y1; ++cy) {
        for (std::size_t cx = x0; cx <= x1; ++cx) {
          const auto c = centre(cx, cy);
          if (std::hypot(c[0] - bx, c[1] - by) < reach) blocked[cy * nx + cx] = true;
        }
      }
    }
  }
  for (std::size_t e = 0; e < crowd.exits.size(); ++e) {
    const scene::CrowdExit& exit = crowd.exits[e];
    bool open = false;
    for (std::size_t cy = 0; cy < ny; ++cy) {
      for (std::size_t cx = 0; cx < nx; ++cx) {
        const auto c = centre(cx, cy);
        if (c[0] < exit.region.min[0] || c[0] > exit.region.max[0] || c[1] < exit.region.min[1] ||
            c[1] > exit.region.max[1])
          continue;
        goal[cy * nx + cx] = true;
        open = open || !blocked[cy * nx + cx];
      }
    }
    if (!open) {
      throw scene::SceneError(scene.source, "/crowd/exits/" + std::to_string(e),
                              "an exit region inside the domain with room for an agent (a navigation cell at least "
                              "crowd.body_radius from every wall)",
                              "none in the region");
    }
  }
  return NavigationField(grid, std::move(blocked), goal);
}

void check_agent_starts(const scene::Scene& scene, const AgentStarts& starts, const NavigationField& navigation) {
  for (std::size_t n = 0; n < starts.positions.size(); ++n) {
    const Vector<2>& x = starts.positions[n];
    const std::string path = "/crowd/agents/" + std::to_string(starts.groups[n]);
    if (navigation.blocked(x)) {
      throw scene::SceneError(
          scene.source, path,
          "a region whose agents stand inside the domain, at least crowd.body_radius from every wall",
          "an agent at " + point_text(x) + " inside or against a wall");
    }
    if (!scene.crowd->agents[starts.groups[n]].heading && !std::isfinite(navigation.distance(x))) {
      throw scene::SceneError(scene.source, path, "a region from which an exit (crowd.exits) can be reached",
                              "an agent at " + point_text(x) + " walled off from every exit");
    }
  }
}

}  // namespace tide::crowd_setup
