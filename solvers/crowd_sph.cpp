#include "tide/solvers/crowd_sph.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "crowd_setup.hpp"
#include "passes/crowd_forces.hpp"
#include "passes/density_summation.hpp"
#include "simulation_setup.hpp"
#include "start_edit.hpp"
#include "state_check.hpp"
#include "tide/core/log.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/agent_placement.hpp"
#include "tide/solvers/capabilities.hpp"

namespace tide {
namespace {

Real support_radius(const scene::Scene& scene) {
  return kernel_support_factor(scene.kernel) * static_cast<Real>(scene.smoothing_ratio * scene.particle_spacing);
}

// The neighbour search reaches the kernel's support and the headway range of the fastest agent
// (desired speeds are truncated at three deviations above the mean): an agent ahead within
// ℓ + T v0 of one slows it (passes::CrowdForceSettings::headway_speed).
Real search_radius(const scene::Scene& scene) {
  const scene::DesiredSpeed& speed = scene.crowd->desired_speed;
  const Real fastest = static_cast<Real>(speed.mean + 3 * speed.deviation);
  return std::max(support_radius(scene), passes::CrowdForceSettings::of(scene).headway_range(fastest));
}

const scene::Scene& checked(const scene::Scene& scene) {
  check_capabilities(scene);
  return scene;
}

// The scene's walls as contacts of `interactions`, massless so that the crowd density counts
// people only, then the navigation field around their particles.
NavigationField walls_and_navigation(const scene::Scene& scene, Interactions<2>& interactions, MovingWalls<2>& moving) {
  setup::add_wall_contacts<2>(scene, 0, 1, interactions, moving, nullptr);
  return crowd_setup::navigation_field(scene, interactions);
}

}  // namespace

CrowdSph::CrowdSph(const scene::Scene& scene)
    : scene_(checked(scene)),
      smoothing_length_(static_cast<Real>(scene.smoothing_ratio * scene.particle_spacing)),
      kernel_(make_kernel<2>(scene.kernel, smoothing_length_)),
      interactions_(setup::grid_domain<2>(scene), search_radius(scene),
                    setup::neighbor_skin(scene, search_radius(scene))),
      moving_walls_(setup::grid_domain<2>(scene)),
      navigation_(walls_and_navigation(scene, interactions_, moving_walls_)),
      exited_(scene.crowd->exits.size(), 0) {
  const scene::Crowd& crowd = *scene.crowd;
  const AgentStarts starts = place_agents(scene);
  crowd_setup::check_agent_starts(scene, starts, navigation_);
  agents_.append(starts.positions.size());
  fields_ = {agents_.position(),
             agents_.add_vector("velocity"),
             agents_.add_vector("acceleration"),
             agents_.add_scalar("mass"),
             agents_.add_scalar("density"),
             agents_.add_scalar("pressure"),
             std::nullopt,
             std::nullopt,
             std::nullopt,
             std::nullopt,
             std::nullopt};
  desired_speed_ = agents_.add_scalar("desired_speed");
  const bool any_heading = std::any_of(crowd.agents.begin(), crowd.agents.end(),
                                       [](const scene::AgentGroup& group) { return group.heading.has_value(); });
  if (any_heading) heading_ = agents_.add_vector("heading");
  auto x = agents_[fields_.position];
  const std::vector<Real> speeds = desired_speeds(crowd.desired_speed, starts.positions.size());
  for (std::size_t i = 0; i < starts.positions.size(); ++i) {
    x.set(i, starts.positions[i]);
    agents_[fields_.mass][i] = 1;  // one person: ρ = Σ_j W_ij is persons/m²
    agents_[desired_speed_][i] = speeds[i];
    if (const auto& heading = crowd.agents[starts.groups[i]].heading)
      agents_[*heading_].set(i, Vector<2>(static_cast<Real>((*heading)[0]), static_cast<Real>((*heading)[1])));
  }

  // The acoustic limit with c = sqrt(K), the speed of a small density disturbance in the
  // uneasiness equation of state, and the force limit, as WCSPH takes them.
  time_step_rule_.smoothing_length = smoothing_length_;
  time_step_rule_.sound_speed = std::sqrt(static_cast<Real>(crowd.stiffness));
  time_step_rule_.cfl = static_cast<Real>(scene.solver.cfl);
  time_step_rule_.force_number = static_cast<Real>(scene.solver.force_number);
  // Symplectic Euler resolves the relaxation (τ/10) and the period 2π sqrt(m/k) of two bodies
  // pressed together (0.2 sqrt(m/k): 31 steps a period) before they touch, which the force
  // limit, reading the accelerations of the step before, sees only once they do.
  time_step_cap_ =
      static_cast<Real>(std::min(crowd.relaxation_time / 10, 0.2 * std::sqrt(crowd.agent_mass / crowd.body_stiffness)));
  time_ = scene.time.start;

  start();
  pipeline_ = build_pipeline();
}

void CrowdSph::start() {
  search_and_sum_density();
  compute_acceleration();
  check_state();
  record_peak();
}

void CrowdSph::edit_start(FunctionRef<void(ParticleSet<2>&)> edit) {
  setup::edit_start_fields<2>(step_count_, agents_, edit);
  peak_ = {};
  start();
}

Pipeline CrowdSph::build_pipeline() {
  std::vector<Stage> stages;
  stages.push_back({"kick_drift", [this](StepContext& c) { kick_drift(c.dt); }});
  if (!scene_.crowd->exits.empty()) stages.push_back({"exits", [this](StepContext&) { remove_exited(); }});
  stages.push_back(
      {"neighbor_search+crowd_density", [this](StepContext& c) { c.report.removed = search_and_sum_density(); }});
  stages.push_back({"crowd_forces", [this](StepContext&) { compute_acceleration(); }});
  stages.push_back({"advance_time", [this](StepContext& c) {
                      time_ += c.dt;
                      ++step_count_;
                    }});
  stages.push_back({"state_check", [this](StepContext&) { check_state(); }});
  stages.push_back({"density_peak", [this](StepContext&) { record_peak(); }});
  return Pipeline(std::move(stages));
}

StepReport CrowdSph::step() {
  StepContext context;
  context.report.time_step = choose_time_step(time_step_rule_, max_speed_, max_acceleration_);
  if (time_step_cap_ < context.report.time_step.dt) context.report.time_step = {time_step_cap_, TimeStepLimit::force};
  context.dt = context.report.time_step.dt;
  pipeline_.run(context);
  return context.report;
}

std::size_t CrowdSph::search_and_sum_density() {
  const std::size_t removed = interactions_.update(agents_);
  auto pressure = agents_[fields_.pressure];
  const Real comfortable = static_cast<Real>(scene_.crowd->comfortable_density);
  const Real stiffness = static_cast<Real>(scene_.crowd->stiffness);
  // The agent's own term of ρ_i, m_i W(0) with m_i = 1 person (2.2 persons/m² for Wendland C2 at
  // h = 0.5 m, above ρ_c): the density of the others, ρ_i − W(0), is what the equation of state
  // sees, so that an agent alone or in a sparse crowd feels no uneasiness. For agents at
  // independent uniform places of density n its mean is n ∫W = n (Campbell's theorem for the
  // Poisson field seen from one of its points, Slivnyak–Mecke), where ρ_i itself reads n + W(0).
  const Real own = kernel_.value(0);
  // Uneasiness: none up to the comfortable density, rising linearly above it (the clamped
  // linear equation of state of WCSPH, p = c² (ρ − ρ0) with p ≥ 0, Monaghan 1994, here with the
  // comfortable density as ρ0, after van Toll et al. 2021, Sec. 4.2).
  passes::density_summation<2>(kernel_, agents_, fields_, interactions_, [&](std::size_t i, Real rho) {
    pressure[i] = stiffness * std::max(rho - own - comfortable, Real(0));
  });
  return removed;
}

void CrowdSph::compute_acceleration() {
  const passes::CrowdForceSettings settings = passes::CrowdForceSettings::of(scene_);
  auto acceleration = agents_[fields_.acceleration];
  const auto toward_exit = [&](std::size_t, const Vector<2>& x) { return navigation_.direction(x); };
  if (!heading_) {
    passes::crowd_acceleration(kernel_, settings, toward_exit, agents_, fields_, desired_speed_, interactions_,
                               acceleration);
    return;
  }
  // A group with a heading walks along it; the others (a zero heading) toward their exit.
  const auto heading = std::as_const(agents_)[*heading_];
  const auto headed = [&](std::size_t i, const Vector<2>& x) {
    const Vector<2> e = heading[i];
    return e.squaredNorm() > 0 ? e : toward_exit(i, x);
  };
  passes::crowd_acceleration(kernel_, settings, headed, agents_, fields_, desired_speed_, interactions_, acceleration);
}

void CrowdSph::kick_drift(Real dt) {
  // Symplectic Euler: the velocity first, then the position with the new velocity.
  auto x = agents_[fields_.position];
  auto v = agents_[fields_.velocity];
  const auto a = std::as_const(agents_)[fields_.acceleration];
  for_each_particle(agents_.size(), [&](std::size_t i) {
    const Vector<2> velocity = v[i] + dt * a[i];
    v.set(i, velocity);
    x.set(i, x[i] + dt * velocity);
  });
}

void CrowdSph::remove_exited() {
  const std::vector<scene::CrowdExit>& exits = scene_.crowd->exits;
  const auto x = std::as_const(agents_)[fields_.position];
  const auto inside = [](const Vector<2>& p, const scene::Box& box) {
    return p[0] >= box.min[0] && p[0] <= box.max[0] && p[1] >= box.min[1] && p[1] <= box.max[1];
  };
  // In index order, so the agents kept keep their order and each leaver counts at the first
  // exit that holds it.
  std::vector<Index> kept;
  kept.reserve(agents_.size());
  for (std::size_t i = 0; i < agents_.size(); ++i) {
    const Vector<2> p = x[i];
    const auto exit =
        std::find_if(exits.begin(), exits.end(), [&](const scene::CrowdExit& e) { return inside(p, e.region); });
    if (exit == exits.end()) {
      kept.push_back(static_cast<Index>(i));
    } else {
      ++exited_[static_cast<std::size_t>(exit - exits.begin())];
    }
  }
  if (kept.size() == agents_.size()) return;
  const std::span<Real> scratch = interactions_.pass_scratch(
      (ParticleSet<2>::permute_scratch_bytes(kept.size()) + sizeof(Real) - 1) / sizeof(Real));
  agents_.permute(kept, std::as_writable_bytes(scratch));
}

void CrowdSph::check_state() {
  const scene::Crowd& crowd = *scene_.crowd;
  StateLimits limits;
  // Discs of radius r overlapping by half a radius everywhere: 1/r² persons/m², beyond any crowd.
  limits.max_density = static_cast<Real>(1 / (crowd.body_radius * crowd.body_radius));
  limits.density_band = "above 1/r^2 persons/m^2 (crowd.body_radius)";
  const double fastest = crowd.desired_speed.mean + 3 * crowd.desired_speed.deviation;
  limits.max_speed = static_cast<Real>(3 * fastest);
  limits.speed_bound = "faster than three times the fastest desired speed, " + setup::format_number(3 * fastest) +
                       " m/s (crowd.desired_speed)";
  const StateMaxima maxima = check_fluid_state<2>(agents_, fields_, limits, step_count_, time_);
  max_speed_ = maxima.speed;
  max_acceleration_ = maxima.acceleration;
}

void CrowdSph::record_peak() {
  struct Largest {
    Real density = -1;
    std::size_t agent = 0;
  };
  const auto rho = agents_[fields_.density];
  // Ties go to the lower index, so the agent found does not depend on the thread count.
  const Largest largest = reduce(
      agents_.size(), Largest{},
      [&](std::size_t i) {
        return Largest{rho[i], i};
      },
      [](const Largest& a, const Largest& b) { return b.density > a.density ? b : a; });
  if (!(static_cast<double>(largest.density) > peak_.density)) return;
  const bool first_crush = peak_.density <= crush_density && largest.density > crush_density;
  const Vector<2> x = agents_[fields_.position][largest.agent];
  peak_ = {static_cast<double>(largest.density), {static_cast<double>(x[0]), static_cast<double>(x[1])}, time_};
  if (first_crush) {
    log_warning("crowd density " + setup::format_number(peak_.density) + " persons/m^2 at [" +
                setup::format_number(peak_.position[0]) + ", " + setup::format_number(peak_.position[1]) +
                "], t = " + setup::format_number(time_) + " s: above " + setup::format_number(crush_density) +
                " persons/m^2, a crush risk");
  }
}

double CrowdSph::bytes_per_particle() const { return setup::bytes_per_particle<2>(agents_, interactions_); }

std::optional<CrowdStatus> CrowdSph::crowd_status() const {
  CrowdStatus status;
  status.inside = agents_.size();
  status.out = exited_;
  status.peak = peak_;
  const auto rho = agents_[fields_.density];
  const auto v = agents_[fields_.velocity];
  const auto sum = [&](auto value) {
    return reduce(
        agents_.size(), 0.0, [&](std::size_t i) { return static_cast<double>(value(i)); },
        [](double a, double b) { return a + b; });
  };
  if (status.inside > 0) {
    const auto n = static_cast<double>(status.inside);
    status.mean_density = sum([&](std::size_t i) { return rho[i]; }) / n;
    status.mean_speed = sum([&](std::size_t i) { return v[i].norm(); }) / n;
  }
  return status;
}

}  // namespace tide
