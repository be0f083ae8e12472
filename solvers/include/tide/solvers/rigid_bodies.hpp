#pragma once

#include <algorithm>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tide/core/particle_set.hpp"
#include "tide/core/state_archive.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/solvers/body_contacts.hpp"
#include "tide/solvers/contact.hpp"
#include "tide/solvers/instability.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/moving_walls.hpp"
#include "tide/solvers/rigid_body.hpp"

namespace tide {

/// The wall contacts that are rigid bodies moved by the fluid (scene::Body): each is a moving
/// wall contact whose particles carry the force the fluid exerts on them (passes/body_force.hpp)
/// and the force of the solids they touch (touch(), body_contacts.hpp), each summed over the body
/// in the particles' order, which the neighbour sort fixes for any thread count, into a force and
/// a torque about the body's reference point. Gravity acts at the centre of mass. The bodies step
/// by velocity Verlet with the fluid: kick_drift at the step's start (half a kick with the forces
/// of the last step's end, then the drift, placing the particles at the step's end), kick at its
/// end with the forces there.
template <int D>
class RigidBodies {
 public:
  explicit RigidBodies(const GridDomain<D>& domain) : domain_(domain) {}

  /// Moves `contact` (a moving contact whose fields have a surface velocity and an acceleration)
  /// as `body`, from `release_time` on (it is held in the steps that begin before), with
  /// `applied_force` at its centre of mass besides gravity; `start` holds each particle's position
  /// at the start, `force` receives the fluid's force on it and `contact_force` that of the solids
  /// it touches.
  void add(Contact<D>& contact, RigidBody body, double release_time, const Eigen::Vector3d& applied_force,
           VectorField start, VectorField force, VectorField contact_force) {
    const Eigen::Vector3d applied_acceleration = applied_force / body.mass_properties().mass;
    bodies_.push_back(
        {&contact, std::move(body), release_time, applied_acceleration, start, force, contact_force, {}, {}});
  }

  bool empty() const { return bodies_.empty(); }
  std::size_t size() const { return bodies_.size(); }
  const RigidBody& body(std::size_t k) const { return bodies_[k].body; }
  const Contact<D>& contact(std::size_t k) const { return *bodies_[k].contact; }
  /// The fluid's force on body k and its torque about the reference point, as last summed.
  const Eigen::Vector3d& fluid_force(std::size_t k) const { return bodies_[k].fluid.force; }
  const Eigen::Vector3d& fluid_torque(std::size_t k) const { return bodies_[k].fluid.torque; }
  /// The force of the solids body k touches and its torque, as last summed.
  const Eigen::Vector3d& contact_force(std::size_t k) const { return bodies_[k].solids.force; }
  const Eigen::Vector3d& contact_torque(std::size_t k) const { return bodies_[k].solids.torque; }

  /// Where each body's fluid force goes: f(contact, force view) for every body, e.g. the
  /// body_force pass.
  template <class F>
  void for_each_force_field(F&& f) {
    for (Entry& entry : bodies_) f(std::as_const(*entry.contact), entry.contact->particles()[entry.force_field]);
  }

  /// Sums each body's particle forces from the fluid into its fluid force and torque (after
  /// the body_force pass).
  void sum_forces() {
    for (Entry& entry : bodies_) entry.fluid = sum(entry, entry.force_field);
  }

  /// The contact forces of `law` on every body's particles from the other bodies and the walls
  /// of `interactions` (every wall contact), summed per body.
  void touch(const ContactLaw& law, const Interactions<D>& interactions) {
    std::vector<SolidParticles<D>> solids;
    std::vector<std::size_t> body_sets(bodies_.size());
    for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
      const Contact<D>& contact = interactions.contact(k);
      if (contact.role() != ContactRole::wall) continue;
      const ParticleSet<D>& set = contact.particles();
      const WallFields<D>& w = contact.fields();
      SolidParticles<D> solid{set[w.position], w.surface_velocity ? set[*w.surface_velocity] : ConstVectorView<D>{},
                              set.size(), std::numeric_limits<Real>::infinity()};
      for (std::size_t b = 0; b < bodies_.size(); ++b) {
        if (bodies_[b].contact != &contact) continue;
        solid.mass_share = static_cast<Real>(bodies_[b].body.mass_properties().mass / static_cast<double>(set.size()));
        body_sets[b] = solids.size();
      }
      solids.push_back(solid);
    }
    cells_.build(solids, body_sets, law.distance);
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      Entry& entry = bodies_[k];
      contact_forces<D>(law, cells_, solids, body_sets[k], entry.contact->particles()[entry.contact_force_field]);
      entry.solids = sum(entry, entry.contact_force_field);
    }
  }

  /// Half a kick (dt/2) with the last summed forces and gravity g, then the drift by dt, for the
  /// step that begins at `start_time`; places the particles. Throws InstabilityError naming the
  /// body when one leaves the domain.
  void kick_drift(double dt, const Eigen::Vector3d& g, std::uint64_t step, double start_time) {
    for (Entry& entry : bodies_) {
      if (start_time < entry.release_time) continue;
      kick_body(entry, dt / 2, g);
      entry.body.drift(dt);
      place(entry, step, start_time + dt);
    }
  }

  /// Half a kick (dt/2) with the last summed forces and gravity g, ending the step that began at
  /// `start_time`.
  void kick(double dt, const Eigen::Vector3d& g, double start_time) {
    for (Entry& entry : bodies_)
      if (start_time >= entry.release_time) kick_body(entry, dt / 2, g);
  }

  /// Places every body's particles where the body is, with its velocities and accelerations.
  void place(std::uint64_t step, double time) {
    for (Entry& entry : bodies_) place(entry, step, time);
  }

  /// The largest speed of a body particle, as last placed: the time step keeps it, as the
  /// fluid's, within cfl h of a step. Throws InstabilityError naming the body when a particle's
  /// speed exceeds `limit` (`bound` says which bound that is) or is not a number.
  Real checked_max_particle_speed(Real limit, const std::string& bound, std::uint64_t step, double time) const {
    Real fastest = 0;
    for (const Entry& entry : bodies_) {
      const ParticleSet<D>& set = entry.contact->particles();
      const auto velocity = set[*entry.contact->fields().surface_velocity];
      const auto id = set[set.id()];
      for (std::size_t b = 0; b < set.size(); ++b) {
        const Real speed = velocity[b].norm();
        if (!(speed <= limit)) {
          throw InstabilityError(id[b], "speed", static_cast<double>(speed), step, time,
                                 "a particle of the body \"" + entry.contact->name() + "\" moves " + bound,
                                 "Check the body's density and the time step (solver.cfl).");
        }
        fastest = std::max(fastest, speed);
      }
    }
    return fastest;
  }

  /// Each body's motion and last summed loads, under "bodies/<k>" (its particles are a contact's:
  /// Interactions::save).
  void save(StateArchive& archive) const {
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      const Entry& entry = bodies_[k];
      archive.put_doubles(path(k) + "/motion", entry.body.motion_state());
      std::vector<double> loads;
      for (const Load* load : {&entry.fluid, &entry.solids})
        for (const Eigen::Vector3d* v : {&load->force, &load->torque})
          loads.insert(loads.end(), v->data(), v->data() + 3);
      archive.put_doubles(path(k) + "/loads", loads);
    }
  }

  /// Takes back what save() put.
  void restore(const StateArchive& archive) {
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      Entry& entry = bodies_[k];
      entry.body.restore_motion_state(archive.doubles(path(k) + "/motion"));
      const std::span<const double> loads = archive.doubles(path(k) + "/loads");
      if (loads.size() != 12) throw std::runtime_error("checkpoint entry '" + path(k) + "/loads': expected 12 values");
      std::size_t i = 0;
      for (Load* load : {&entry.fluid, &entry.solids}) {
        for (Eigen::Vector3d* v : {&load->force, &load->torque}) {
          *v = Eigen::Vector3d(loads[i], loads[i + 1], loads[i + 2]);
          i += 3;
        }
      }
    }
  }

 private:
  static std::string path(std::size_t k) { return "bodies/" + std::to_string(k); }

  // A force and its torque about the body's reference point.
  struct Load {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  };
  struct Entry {
    Contact<D>* contact;
    RigidBody body;
    double release_time;
    Eigen::Vector3d applied_acceleration;  // the applied force over the mass: it acts as gravity does
    VectorField start;
    VectorField force_field;
    VectorField contact_force_field;
    Load fluid;   // from the fluid
    Load solids;  // from the bodies and walls it touches
  };

  // The particle forces of `field` summed over the body in particle order, with their torque.
  static Load sum(const Entry& entry, VectorField field) {
    const ParticleSet<D>& set = entry.contact->particles();
    const auto force = set[field];
    const auto start = set[entry.start];
    const RigidBody::Kinematics motion = entry.body.kinematics();
    Load load;
    for (std::size_t b = 0; b < set.size(); ++b) {
      Eigen::Vector3d f = Eigen::Vector3d::Zero(), x0 = Eigen::Vector3d::Zero();
      for (int d = 0; d < D; ++d) {
        f[d] = static_cast<double>(force.component[d][b]);
        x0[d] = static_cast<double>(start.component[d][b]);
      }
      // The lever from the reference point, from the start position: no periodic image.
      const Eigen::Vector3d lever = motion.lever(x0);
      load.force += f;
      load.torque += lever.cross(f);
    }
    return load;
  }

  static void kick_body(Entry& entry, double half_dt, const Eigen::Vector3d& g) {
    const Eigen::Vector3d pull = g + entry.applied_acceleration;
    entry.body.kick(entry.fluid.force + entry.solids.force + entry.body.gravity_force(pull),
                    entry.fluid.torque + entry.solids.torque + entry.body.gravity_torque(pull), half_dt);
  }

  void place(Entry& entry, std::uint64_t step, double time) const {
    place_rigid_particles<D>(domain_, *entry.contact, entry.start, entry.body.kinematics(), step, time,
                             "the body \"" + entry.contact->name() + "\" left the domain",
                             "Enlarge domain.box, or check the body's density and the time step.");
  }

  GridDomain<D> domain_;
  std::vector<Entry> bodies_;
  SolidCells<D> cells_;  // kept between steps for its storage
};

}  // namespace tide
