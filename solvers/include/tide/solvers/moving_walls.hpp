#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "tide/core/parallel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/solvers/contact.hpp"
#include "tide/solvers/instability.hpp"
#include "tide/solvers/rigid_motion.hpp"

namespace tide {

/// Puts the particles of `contact` where the rigid motion `solid` has them: for each particle,
/// solid.point(x0) of its start position x0 (a field of the contact) gives its position, which is
/// wrapped into the domain on its periodic axes, its velocity (the contact's surface velocity)
/// and its acceleration. Throws InstabilityError with `what` and `hint` when a particle leaves
/// the domain on a non-periodic axis (the neighbour search would drop it).
template <int D, class Solid>
void place_rigid_particles(const GridDomain<D>& domain, Contact<D>& contact, VectorField start_field,
                           const Solid& solid, std::uint64_t step, double time, const std::string& what,
                           const std::string& hint) {
  ParticleSet<D>& set = contact.particles();
  const WallFields<D>& w = contact.fields();
  const auto start = std::as_const(set)[start_field];
  auto x = set[w.position];
  auto v = set[*w.surface_velocity];
  auto a = set[*w.acceleration];
  for_each_particle(set.size(), [&](std::size_t b) {
    Eigen::Vector3d x0 = Eigen::Vector3d::Zero();
    for (int d = 0; d < D; ++d) x0[d] = static_cast<double>(start.component[d][b]);
    const auto p = solid.point(x0);
    for (int d = 0; d < D; ++d) {
      Real coordinate = static_cast<Real>(p.position[d]);
      if (domain.periodic[d]) {  // into [lower, upper), as the neighbour grid keeps its particles
        const Real length = domain.upper[d] - domain.lower[d];
        coordinate -= length * std::floor((coordinate - domain.lower[d]) / length);
      }
      x.component[d][b] = coordinate;
      v.component[d][b] = static_cast<Real>(p.velocity[d]);
      a.component[d][b] = static_cast<Real>(p.acceleration[d]);
    }
  });
  const auto id = std::as_const(set)[set.id()];
  for (std::size_t b = 0; b < set.size(); ++b) {
    for (int d = 0; d < D; ++d) {
      if (domain.periodic[d]) continue;
      const Real coordinate = x.component[d][b];
      if (coordinate >= domain.lower[d] && coordinate < domain.upper[d]) continue;
      throw InstabilityError(id[b], "position", static_cast<double>(coordinate), step, time, what, hint);
    }
  }
}

/// The wall contacts whose particles follow a prescribed rigid motion (scene::Motion): a stage
/// of the step puts them where the motion has them at the step's end, with the velocity the
/// no-slip mirror and the continuity equation read (WallFields::surface_velocity) and the
/// acceleration of Adami, Hu & Adams 2012, eq. 27 (WallFields::acceleration). Each particle is
/// placed from its start position, so the poses do not drift however many steps are taken. A
/// steered wall (scene::Steered) heads for the displacement steer() last gave, at most its
/// max_speed, with that velocity over the step and no acceleration.
template <int D>
class MovingWalls {
 public:
  explicit MovingWalls(const GridDomain<D>& domain) : domain_(domain) {}

  /// Moves `contact` (a moving contact whose fields have a surface velocity and an acceleration)
  /// by `motion`; `start` holds each particle's position at τ = 0.
  void add(Contact<D>& contact, scene::Motion motion, VectorField start) {
    walls_.push_back({&contact, std::move(motion), start});
  }

  bool empty() const { return walls_.empty(); }

  /// Sends every steered wall towards being displaced by `target` from where the scene puts it,
  /// the target shortened along each axis so that the wall's particles stay a particle spacing
  /// `margin` inside the domain on its non-periodic axes. False when no wall is steered.
  bool steer(const Eigen::Vector3d& target, Real margin) {
    bool steered = false;
    for (Wall& wall : walls_) {
      if (!std::holds_alternative<scene::Steered>(wall.motion)) continue;
      steered = true;
      wall.steered_target = target;
      const ParticleSet<D>& set = wall.contact->particles();
      const auto start = set[wall.start];
      for (int d = 0; d < D; ++d) {
        if (domain_.periodic[d] || set.size() == 0) continue;
        const auto [low, high] = std::minmax_element(start.component[d], start.component[d] + set.size());
        const double least = static_cast<double>(domain_.lower[d] + margin - *low);
        const double most = static_cast<double>(domain_.upper[d] - margin - *high);
        wall.steered_target[d] = std::clamp(target[d], std::min(least, 0.0), std::max(most, 0.0));
      }
    }
    return steered;
  }

  /// Puts every moving wall where its motion has it at τ (the time since the start), wrapped
  /// into the domain on its periodic axes. Throws InstabilityError naming the contact when the
  /// motion carries a particle out of the domain on a non-periodic axis (the neighbour search
  /// would drop it).
  void move_to(double tau, std::uint64_t step, double time) {
    for (Wall& wall : walls_) move(wall, pose_of(wall, tau), step, time);
    max_particle_speed_ = 0;
    for (const Wall& wall : walls_) {
      const ParticleSet<D>& set = wall.contact->particles();
      const auto velocity = set[*wall.contact->fields().surface_velocity];
      for (std::size_t b = 0; b < set.size(); ++b)
        max_particle_speed_ = std::max(max_particle_speed_, velocity[b].norm());
    }
  }

  /// The largest speed of a moving wall's particle where move_to() last put them: the time step
  /// keeps it, as the fluid's, within cfl h of a step (a fan's tips outrunning the water).
  Real max_particle_speed() const { return max_particle_speed_; }

 private:
  struct Wall {
    Contact<D>* contact;
    scene::Motion motion;
    VectorField start;
    // A steered wall's target, its displacement at `steered_tau` and that τ.
    Eigen::Vector3d steered_target = Eigen::Vector3d::Zero();
    Eigen::Vector3d steered_displacement = Eigen::Vector3d::Zero();
    double steered_tau = 0;
  };

  static RigidPose pose_of(Wall& wall, double tau) {
    const auto* steered = std::get_if<scene::Steered>(&wall.motion);
    if (!steered) return pose_at(wall.motion, tau);
    RigidPose pose;
    const double dt = tau - wall.steered_tau;
    if (dt > 0) {
      Eigen::Vector3d move = wall.steered_target - wall.steered_displacement;
      const double reach = steered->max_speed * dt;
      if (move.norm() > reach) move *= reach / move.norm();
      wall.steered_displacement += move;
      wall.steered_tau = tau;
      pose.velocity = move / dt;
    }
    pose.displacement = wall.steered_displacement;
    return pose;
  }

  void move(const Wall& wall, const RigidPose& pose, std::uint64_t step, double time) const {
    place_rigid_particles<D>(
        domain_, *wall.contact, wall.start, pose, step, time,
        "its prescribed motion carries a particle of \"" + wall.contact->name() + "\" out of the domain",
        "Enlarge domain.box or change the obstacle's motion.");
  }

  GridDomain<D> domain_;
  std::vector<Wall> walls_;
  Real max_particle_speed_ = 0;
};

}  // namespace tide
