#include "tide/solvers/agent_placement.hpp"

#include <array>
#include <cmath>
#include <cstdint>
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

// A uniform number in (0, 1] from the generator's 53 high bits: the same on every platform.
double uniform(std::mt19937_64& generator) { return (static_cast<double>(generator() >> 11) + 1) * 0x1.0p-53; }

// The agents placed so far, by cell of a grid a body diameter wide over the domain: whether a
// point lies a body diameter or more from all of them, across the periodic axes too.
class Occupancy {
 public:
  Occupancy(const scene::Scene& scene, double diameter) : diameter_(diameter), box_(scene.domain.box) {
    for (std::size_t axis = 0; axis < 2; ++axis) {
      const double length = box_.max[static_cast<int>(axis)] - box_.min[static_cast<int>(axis)];
      if (scene.domain.periodic[axis]) period_[axis] = length;
      cells_[axis] = static_cast<long>(std::max(1.0, std::ceil(length / diameter)));
    }
    grid_.resize(static_cast<std::size_t>(cells_[0] * cells_[1]));
  }

  bool free(const std::array<double, 2>& x) const {
    for (const double shift_x : {-period_[0], 0.0, period_[0]})
      for (const double shift_y : {-period_[1], 0.0, period_[1]}) {
        if ((shift_x != 0 && period_[0] == 0) || (shift_y != 0 && period_[1] == 0)) continue;
        const double sx = x[0] + shift_x, sy = x[1] + shift_y;
        for (long cx = cell(sx, 0) - 1; cx <= cell(sx, 0) + 1; ++cx)
          for (long cy = cell(sy, 1) - 1; cy <= cell(sy, 1) + 1; ++cy) {
            if (cx < 0 || cy < 0 || cx >= cells_[0] || cy >= cells_[1]) continue;
            for (const auto& y : grid_[static_cast<std::size_t>(cx * cells_[1] + cy)])
              if (std::hypot(sx - y[0], sy - y[1]) < diameter_) return false;
          }
      }
    return true;
  }

  void add(const std::array<double, 2>& x) {
    const long cx = std::clamp(cell(x[0], 0), 0L, cells_[0] - 1), cy = std::clamp(cell(x[1], 1), 0L, cells_[1] - 1);
    grid_[static_cast<std::size_t>(cx * cells_[1] + cy)].push_back(x);
  }

 private:
  long cell(double x, int axis) const { return static_cast<long>(std::floor((x - box_.min[axis]) / diameter_)); }

  double diameter_;
  scene::Box box_;
  std::array<double, 2> period_{};  // 0 on an axis that does not wrap
  std::array<long, 2> cells_{};
  std::vector<std::vector<std::array<double, 2>>> grid_;
};

// Random sequential addition (Feder 1980): each agent at a uniformly random point of the region
// that lies a body diameter or more from every agent placed before it, of any group, drawn again
// until one does. Its jamming limit covers 54.7% of the plane with discs, 2.8 persons/m² at r =
// 0.25 m; well below it an agent takes a few draws.
void place_random(const scene::Scene& scene, std::size_t k, Occupancy& occupancy, AgentStarts& starts) {
  const scene::Crowd& crowd = *scene.crowd;
  const scene::AgentGroup& group = crowd.agents[k];
  std::seed_seq seed{static_cast<std::uint32_t>(crowd.desired_speed.seed),
                     static_cast<std::uint32_t>(crowd.desired_speed.seed >> 32), static_cast<std::uint32_t>(k)};
  std::mt19937_64 generator(seed);
  constexpr int draws_per_agent = 10000;
  for (std::size_t n = 0; n < group.count; ++n) {
    int draws = 0;
    std::array<double, 2> x{};
    do {
      if (++draws > draws_per_agent) {
        throw scene::SceneError(scene.source, "/crowd/agents/" + std::to_string(k) + "/count",
                                "at most as many agents as random placement stands a body diameter apart in the "
                                "region (about 2.5 persons/m^2; placement \"lattice\" holds more)",
                                std::to_string(group.count) + ", of which " + std::to_string(n) + " placed");
      }
      for (int axis = 0; axis < 2; ++axis)
        x[static_cast<std::size_t>(axis)] =
            group.region.min[axis] + uniform(generator) * (group.region.max[axis] - group.region.min[axis]);
    } while (!occupancy.free(x));
    occupancy.add(x);
    starts.positions.emplace_back(static_cast<Real>(x[0]), static_cast<Real>(x[1]));
    starts.groups.push_back(k);
  }
}

// Group k on the largest square lattice centred in its region that holds its count, or, too
// dense for one a body diameter apart, on a hexagonal one.
void place_lattice(const scene::Scene& scene, std::size_t k, AgentStarts& starts) {
  const scene::Crowd& crowd = *scene.crowd;
  const scene::AgentGroup& group = crowd.agents[k];
  const double width = group.region.max[0] - group.region.min[0], height = group.region.max[1] - group.region.min[1];
  double spacing = std::sqrt(width * height / static_cast<double>(group.count));
  auto columns = static_cast<std::size_t>(std::floor(width / spacing));
  auto rows = static_cast<std::size_t>(std::floor(height / spacing));
  while (columns * rows < group.count) {
    spacing = std::min(width / static_cast<double>(columns + 1), height / static_cast<double>(rows + 1)) * (1 - 1e-12);
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
    return;
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

}  // namespace

AgentStarts place_agents(const scene::Scene& scene) {
  AgentStarts starts;
  const scene::Crowd& crowd = *scene.crowd;
  Occupancy occupancy(scene, 2 * crowd.body_radius);
  for (std::size_t k = 0; k < crowd.agents.size(); ++k) {
    if (crowd.agents[k].placement == scene::AgentPlacement::random) {
      place_random(scene, k, occupancy, starts);
      continue;
    }
    // A later group placed at random keeps clear of this one's agents too.
    const std::size_t first = starts.positions.size();
    place_lattice(scene, k, starts);
    for (std::size_t i = first; i < starts.positions.size(); ++i)
      occupancy.add({static_cast<double>(starts.positions[i][0]), static_cast<double>(starts.positions[i][1])});
  }
  return starts;
}

std::vector<Real> desired_speeds(const scene::DesiredSpeed& speed, std::size_t count) {
  std::mt19937_64 generator(speed.seed);
  std::vector<Real> speeds;
  speeds.reserve(count);
  while (speeds.size() < count) {
    const double u1 = uniform(generator), u2 = uniform(generator);
    const double normal = std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
    const double v = speed.mean + speed.deviation * normal;
    if (std::abs(normal) <= 3 && v > 0) speeds.push_back(static_cast<Real>(v));
  }
  return speeds;
}

}  // namespace tide
