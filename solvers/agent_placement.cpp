#include "tide/solvers/agent_placement.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "simulation_setup.hpp"
#include "tide/core/scene_error.hpp"

namespace tide {

AgentStarts place_agents(const scene::Scene& scene) {
  AgentStarts starts;
  const scene::Crowd& crowd = *scene.crowd;
  for (std::size_t k = 0; k < crowd.agents.size(); ++k) {
    const scene::AgentGroup& group = crowd.agents[k];
    const double width = group.region.max[0] - group.region.min[0], height = group.region.max[1] - group.region.min[1];
    // The largest square lattice whose columns × rows hold the count.
    double spacing = std::sqrt(width * height / static_cast<double>(group.count));
    auto columns = static_cast<std::size_t>(std::floor(width / spacing));
    auto rows = static_cast<std::size_t>(std::floor(height / spacing));
    while (columns * rows < group.count) {
      spacing =
          std::min(width / static_cast<double>(columns + 1), height / static_cast<double>(rows + 1)) * (1 - 1e-12);
      columns = static_cast<std::size_t>(std::floor(width / spacing));
      rows = static_cast<std::size_t>(std::floor(height / spacing));
    }
    if (group.count > 1 && spacing < 2 * crowd.body_radius) {
      throw scene::SceneError(scene.source, "/crowd/agents/" + std::to_string(k) + "/count",
                              "at most as many agents as stand a body diameter (2 crowd.body_radius = " +
                                  setup::format_number(2 * crowd.body_radius) + " m) apart in the region",
                              std::to_string(group.count) + ", " + setup::format_number(spacing) + " m apart");
    }
    const double x0 = group.region.min[0] + (width - static_cast<double>(columns - 1) * spacing) / 2;
    const double y0 = group.region.min[1] + (height - static_cast<double>(rows - 1) * spacing) / 2;
    for (std::size_t n = 0; n < group.count; ++n) {
      const double x = x0 + static_cast<double>(n % columns) * spacing;
      const double y = y0 + static_cast<double>(n / columns) * spacing;
      starts.positions.emplace_back(static_cast<Real>(x), static_cast<Real>(y));
      starts.groups.push_back(k);
    }
  }
  return starts;
}

std::vector<Real> desired_speeds(const scene::DesiredSpeed& speed, std::size_t count) {
  std::mt19937_64 generator(speed.seed);
  // A uniform number in (0, 1] from the generator's 53 high bits: the same on every platform.
  const auto uniform = [&] { return (static_cast<double>(generator() >> 11) + 1) * 0x1.0p-53; };
  std::vector<Real> speeds;
  speeds.reserve(count);
  while (speeds.size() < count) {
    const double u1 = uniform(), u2 = uniform();
    const double normal = std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
    const double v = speed.mean + speed.deviation * normal;
    if (std::abs(normal) <= 3 && v > 0) speeds.push_back(static_cast<Real>(v));
  }
  return speeds;
}

}  // namespace tide
