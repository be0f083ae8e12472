#include "tide/solvers/agent_placement.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "simulation_setup.hpp"
#include "tide/core/scene_error.hpp"

namespace tide {

namespace {

struct HexagonalLattice {
  double spacing;       // between neighbours, in a row and across rows
  std::size_t columns;  // per row
  std::size_t rows;     // sqrt(3)/2 spacing apart, every other one shifted by half a spacing
};

// The largest hexagonal lattice whose columns × rows hold `count` in width × height, each row
// with its half-spacing shift inside the width.
HexagonalLattice hexagonal_lattice(double width, double height, std::size_t count) {
  const double pitch = std::sqrt(3.0) / 2;  // row spacing over spacing
  const auto fit = [&](double spacing) {
    const auto columns = static_cast<std::size_t>(std::floor(width / spacing - 0.5));
    const auto rows = static_cast<std::size_t>(std::floor(height / (pitch * spacing)));
    return HexagonalLattice{spacing, columns, rows};
  };
  HexagonalLattice lattice = fit(std::sqrt(width * height / (pitch * static_cast<double>(count))));
  // Down the spacings at which a column or a row more fits, the larger first.
  while (lattice.columns * lattice.rows < count) {
    lattice = fit(std::max(width / (static_cast<double>(lattice.columns + 1) + 0.5),
                           height / (pitch * static_cast<double>(lattice.rows + 1))) *
                  (1 - 1e-12));
  }
  return lattice;
}

void place_hexagonal(const scene::Box& region, const HexagonalLattice& lattice, std::size_t count, std::size_t group,
                     AgentStarts& starts) {
  const double width = region.max[0] - region.min[0], height = region.max[1] - region.min[1];
  const double d = lattice.spacing, row_spacing = std::sqrt(3.0) / 2 * d;
  const double x0 = region.min[0] + (width - (static_cast<double>(lattice.columns) - 0.5) * d) / 2;
  const double y0 = region.min[1] + (height - static_cast<double>(lattice.rows - 1) * row_spacing) / 2;
  for (std::size_t n = 0; n < count; ++n) {
    const std::size_t row = n / lattice.columns;
    const double x = x0 + static_cast<double>(n % lattice.columns) * d + (row % 2 == 1 ? d / 2 : 0);
    const double y = y0 + static_cast<double>(row) * row_spacing;
    starts.positions.emplace_back(static_cast<Real>(x), static_cast<Real>(y));
    starts.groups.push_back(group);
  }
}

}  // namespace

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
      // Too dense for a square lattice a body diameter apart: a hexagonal one, the densest
      // packing of discs (2/(sqrt(3) d²) against 1/d²), at the largest spacing that holds them.
      const HexagonalLattice hexagonal = hexagonal_lattice(width, height, group.count);
      if (hexagonal.spacing < 2 * crowd.body_radius) {
        throw scene::SceneError(
            scene.source, "/crowd/agents/" + std::to_string(k) + "/count",
            "at most as many agents as stand a body diameter (2 crowd.body_radius = " +
                setup::format_number(2 * crowd.body_radius) + " m) apart in the region",
            std::to_string(group.count) + ", " + setup::format_number(hexagonal.spacing) + " m apart");
      }
      place_hexagonal(group.region, hexagonal, group.count, k, starts);
      continue;
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
