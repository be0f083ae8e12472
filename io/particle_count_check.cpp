#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "geometry_checks.hpp"
#include "scene_text.hpp"
#include "tide/core/scene_error.hpp"

namespace tide::io {
namespace {

// The fewest bytes a particle holds in a run: memory_report's 352 B per fluid particle of the 3D
// dam break without a neighbour skin (docs/performance.md). A scene implying more particles than
// physical memory holds at that rate cannot run here, whatever its settings.
constexpr double bytes_per_particle = 352;

// Particle indices and counts are 32-bit in places (neighbour lists); beyond 2^31 − 1 particles
// nothing would run anyway.
constexpr double largest_index = std::numeric_limits<std::int32_t>::max();

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return std::numeric_limits<double>::infinity();
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

/// The lattice points anchor + (k + 1/2) spacing the sampling (solvers/particle_sampling.cpp)
/// visits for a shape bounded by `box`: from floor((lower − anchor)/spacing − 1/2) to
/// ceil((upper − anchor)/spacing − 1/2) on each axis. In doubles, so that absurd extents give huge
/// counts (or infinity) rather than overflow.
struct LatticeRange {
  double points = 1;
  double farthest_index = 0;  // of a bound from the anchor, in spacings
};

LatticeRange lattice_range(const scene::Box& box, const scene::Vec& anchor, double spacing, int dimension) {
  LatticeRange range;
  for (int d = 0; d < dimension; ++d) {
    const double first = std::floor((box.min[d] - anchor[d]) / spacing - 0.5);
    const double last = std::ceil((box.max[d] - anchor[d]) / spacing - 0.5);
    range.points *= last - first + 1;
    range.farthest_index = std::max({range.farthest_index, std::abs(first), std::abs(last)});
  }
  return range;
}

scene::Box bounds_of(const scene::Ball& ball) {
  scene::Box box;
  for (int d = 0; d < 3; ++d) {
    box.min[d] = ball.centre[d] - ball.radius;
    box.max[d] = ball.centre[d] + ball.radius;
  }
  return box;
}

/// What the sampling visits for an obstacle: its bounding box; a plane's is the domain.
scene::Box bounds_of(const scene::Obstacle& obstacle, const scene::Box& domain) {
  if (const auto* box = std::get_if<scene::Box>(&obstacle.shape)) return *box;
  if (const auto* ball = std::get_if<scene::Ball>(&obstacle.shape)) return bounds_of(*ball);
  if (const auto* mesh = std::get_if<scene::Mesh>(&obstacle.shape)) return mesh->bounds;
  return domain;
}

/// The region whose lattice points outside the inner box are the container's wall particles.
scene::Box bounds_of(const scene::Container& container, double thickness, int dimension) {
  scene::Box box = container.inner;
  for (int d = 0; d < dimension; ++d) {
    box.min[d] -= thickness;
    box.max[d] += thickness;
  }
  if (container.open_top) box.max[dimension - 1] = container.inner.max[dimension - 1];
  return box;
}

class CountCheck {
 public:
  explicit CountCheck(const scene::Scene& scene)
      : scene_(scene),
        anchor_(scene.walls.container ? scene.walls.container->inner.min : scene.domain.box.min),
        cap_(static_cast<double>(largest_particle_count())) {}

  void add(const scene::Box& bounds, const std::string& path) {
    const LatticeRange range = lattice_range(bounds, anchor_, scene_.particle_spacing, scene_.dimension);
    if (!(range.farthest_index <= largest_index)) {
      refuse(path,
             "a shape within " + format_number(largest_index) + " particle spacings of the lattice anchor " +
                 format_vector(anchor_, scene_.dimension),
             "a bound " + format_number(range.farthest_index) + " spacings from it");
    }
    if (!(range.points <= cap_)) refuse_count(path, range.points);
    total_ += range.points;
  }

  void check_total() const {
    if (!(total_ <= cap_)) refuse_count("/particle_spacing", total_);
  }

 private:
  [[noreturn]] void refuse(const std::string& path, std::string expected, std::string found) const {
    throw scene::SceneError(scene_.source, path, std::move(expected), std::move(found));
  }

  [[noreturn]] void refuse_count(const std::string& path, double count) const {
    refuse(path,
           "a scene of at most " + format_number(cap_) + " particles at spacing " +
               format_number(scene_.particle_spacing) + " (2^31 - 1, or physical memory / " +
               format_number(bytes_per_particle) + " B per particle)",
           format_number(count) + " particles (lattice points to visit)");
  }

  const scene::Scene& scene_;
  scene::Vec anchor_;
  double cap_;
  double total_ = 0;
};

}  // namespace

std::int64_t largest_particle_count() {
  return static_cast<std::int64_t>(std::min(largest_index, std::floor(physical_memory_bytes() / bytes_per_particle)));
}

void check_particle_count(const scene::Scene& scene) {
  CountCheck count(scene);
  for (std::size_t k = 0; k < scene.fluid.size(); ++k) {
    const auto& shape = scene.fluid[k].shape;
    if (const auto* box = std::get_if<scene::Box>(&shape)) {
      count.add(*box, "/fluid/" + std::to_string(k) + "/box");
    } else {
      count.add(bounds_of(std::get<scene::Ball>(shape)), "/fluid/" + std::to_string(k) + "/ball");
    }
  }
  if (scene.walls.container) {
    count.add(bounds_of(*scene.walls.container, scene.walls.layers * scene.particle_spacing, scene.dimension),
              "/walls/container");
  }
  const auto& obstacles = scene.walls.obstacles;
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const char* shape = std::holds_alternative<scene::Box>(obstacles[k].shape)    ? "/box"
                        : std::holds_alternative<scene::Ball>(obstacles[k].shape) ? "/ball"
                        : std::holds_alternative<scene::Mesh>(obstacles[k].shape) ? "/mesh"
                                                                                  : "/plane";
    count.add(bounds_of(obstacles[k], scene.domain.box), "/walls/obstacles/" + std::to_string(k) + shape);
  }
  count.check_total();
}

}  // namespace tide::io
