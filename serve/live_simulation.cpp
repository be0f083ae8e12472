#include "tide/serve/live_simulation.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

#include "tide/serve/frame.hpp"
#include "tide/serve/frame_snapshot.hpp"
#include "tide/solvers/instability.hpp"

namespace tide::serve {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

std::string_view scheme_text(scene::Scheme scheme) { return scheme == scene::Scheme::dfsph ? "dfsph" : "wcsph"; }

}  // namespace

LiveSimulation::LiveSimulation(scene::Scene scene, LiveOptions options)
    : base_(std::move(scene)), options_(options), settings_(settings_of(base_, 0)) {
  simulation_ = make_simulation<2>(base_);
  base_particles_ = simulation_->fluid().size();
  if (base_particles_ == 0) throw std::invalid_argument(base_.source + ": the scene has no fluid particles");
  settings_.particles = base_particles_;
  rebuild();
  publish();
}

LiveSimulation::~LiveSimulation() { stop(); }

void LiveSimulation::start() {
  if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
}

void LiveSimulation::stop() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  command_ready_.notify_all();
  frame_ready_.notify_all();
  if (thread_.joinable()) thread_.join();
}

bool LiveSimulation::submit(const Command& command) {
  {
    const std::lock_guard lock(mutex_);
    if (const auto* target = std::get_if<MoveObstacle>(&command)) {
      obstacle_target_ = *target;
    } else {
      if (commands_.size() >= queue_limit) return false;
      commands_.push_back(command);
    }
  }
  command_ready_.notify_all();
  return true;
}

PublishedFrame LiveSimulation::wait_for_frame(std::uint64_t after, Clock::time_point until) const {
  std::unique_lock lock(mutex_);
  frame_ready_.wait_until(lock, until, [&] { return stopping_ || newest_.number > after; });
  return newest_;
}

std::string LiveSimulation::state_json() const {
  const std::lock_guard lock(mutex_);
  return state_;
}

void LiveSimulation::run() {
  while (true) {
    std::vector<Command> commands;
    std::optional<MoveObstacle> target;
    {
      std::unique_lock lock(mutex_);
      const bool idle = settings_.paused && !step_requested_;
      if (idle) {
        command_ready_.wait_for(lock, std::chrono::milliseconds(50),
                                [&] { return stopping_ || !commands_.empty() || obstacle_target_; });
      }
      if (stopping_) return;
      commands.swap(commands_);
      target = std::exchange(obstacle_target_, std::nullopt);
    }
    for (const Command& command : commands) apply(command);
    if (target) apply(*target);
    const bool stepping = !settings_.paused || step_requested_;
    if (stepping) step_once();
    step_requested_ = false;
    const Clock::time_point now = Clock::now();
    if (seconds(now - last_publish_) * options_.frame_rate >= 1 || !commands.empty() || target) publish();
    if (!stepping || options_.pace <= 0) continue;
    // Ahead of the wall clock: wait, waking for a command. Far behind: pace from now on.
    const double ahead = (simulation_->time() - pace_start_time_) / options_.pace - seconds(now - pace_start_);
    if (ahead < -0.25) {
      pace_start_ = now;
      pace_start_time_ = simulation_->time();
    } else if (ahead > 0) {
      std::unique_lock lock(mutex_);
      command_ready_.wait_for(lock, std::chrono::duration<double>(std::min(ahead, 0.05)),
                              [&] { return stopping_ || !commands_.empty() || obstacle_target_; });
    }
  }
}

void LiveSimulation::rebuild() {
  const scene::Scene scene = live_scene(base_, base_particles_, settings_);
  simulation_ = make_simulation<2>(scene);
  const Frame frame = snapshot(*simulation_, settings_.colour);
  const FluidSummary summary = summarise(frame, *simulation_);
  obstacle_home_ = {summary.obstacle_x, summary.obstacle_y};
  if (scene.walls.container && !frame.obstacle.empty()) {
    Eigen::Vector2d low = Eigen::Vector2d::Constant(1e30), high = Eigen::Vector2d::Constant(-1e30);
    for (std::size_t i = 0; i < frame.obstacle.size(); i += 2) {
      const Eigen::Vector2d x(frame.obstacle[i], frame.obstacle[i + 1]);
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
    }
    const scene::Box& inner = scene.walls.container->inner;
    const double margin = 2 * scene.particle_spacing;
    for (int d = 0; d < 2; ++d) {
      obstacle_least_[d] = inner.min[d] + margin + (obstacle_home_[d] - low[d]);
      obstacle_most_[d] = inner.max[d] - margin - (high[d] - obstacle_home_[d]);
    }
  }
  pace_start_ = window_start_ = Clock::now();
  pace_start_time_ = window_time_ = simulation_->time();
  window_steps_ = 0;
}

void LiveSimulation::apply(const Command& command) {
  // A setting that needs a new simulation: kept only if the simulation can be built with it.
  const auto rebuild_with = [&](auto change) {
    const LiveSettings before = settings_;
    change(settings_);
    try {
      rebuild();
    } catch (const std::exception& error) {
      settings_ = before;
      rebuild();
      notice(std::string("refused: ") + error.what());
    }
  };
  std::visit(
      [&](const auto& c) {
        using C = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<C, SetViscosity>) {
          if (simulation_->set_kinematic_viscosity(static_cast<Real>(c.kinematic_viscosity))) {
            settings_.kinematic_viscosity = c.kinematic_viscosity;
          } else {
            notice("viscosity: this scene's viscosity is not laminar with one fluid, so it cannot be changed");
          }
        } else if constexpr (std::is_same_v<C, SetGravity>) {
          settings_.gravity = c.magnitude;
          settings_.tilt = c.tilt;
          const scene::Vec g = gravity_vector(settings_);
          simulation_->set_gravity(Vector<2>(static_cast<Real>(g[0]), static_cast<Real>(g[1])));
        } else if constexpr (std::is_same_v<C, SetParticleCount>) {
          rebuild_with([&](LiveSettings& s) { s.particles = static_cast<std::size_t>(c.count); });
        } else if constexpr (std::is_same_v<C, SetSurfaceTension>) {
          if (c.on && settings_.scheme != scene::Scheme::wcsph) {
            notice("surface tension runs with WCSPH only: choose the WCSPH scheme first");
          } else {
            rebuild_with([&](LiveSettings& s) { s.surface_tension = c.on; });
          }
        } else if constexpr (std::is_same_v<C, SetScheme>) {
          if (c.scheme != scene::Scheme::wcsph && settings_.surface_tension) {
            notice("DFSPH runs without surface tension: switch surface tension off first");
          } else {
            rebuild_with([&](LiveSettings& s) { s.scheme = c.scheme; });
          }
        } else if constexpr (std::is_same_v<C, SetColour>) {
          settings_.colour = c.field;
        } else if constexpr (std::is_same_v<C, Pause>) {
          settings_.paused = c.paused;
          pace_start_ = Clock::now();
          pace_start_time_ = simulation_->time();
        } else if constexpr (std::is_same_v<C, Step>) {
          step_requested_ = settings_.paused;
        } else if constexpr (std::is_same_v<C, Reset>) {
          rebuild();
        } else if constexpr (std::is_same_v<C, MoveObstacle>) {
          const Eigen::Vector2d target =
              Eigen::Vector2d(c.x, c.y).cwiseMax(obstacle_least_).cwiseMin(obstacle_most_) - obstacle_home_;
          if (!simulation_->steer(Eigen::Vector3d(target.x(), target.y(), 0)))
            notice("obstacle: this scene has no steered obstacle (docs/serve.md)");
        }
      },
      command);
}

void LiveSimulation::step_once() {
  try {
    simulation_->step();
  } catch (const InstabilityError& error) {
    notice(std::string("the simulation went unstable and was restarted: ") + error.what());
    rebuild();
  }
}

void LiveSimulation::publish() {
  const Clock::time_point now = Clock::now();
  last_publish_ = now;
  const double window = seconds(now - window_start_);
  if (window >= 1) {
    steps_per_second_ = static_cast<double>(simulation_->step_count() - window_steps_) / window;
    sim_seconds_per_second_ = (simulation_->time() - window_time_) / window;
    frames_per_second_ = static_cast<double>(newest_.number - window_frames_) / window;
    window_start_ = now;
    window_steps_ = simulation_->step_count();
    window_time_ = simulation_->time();
    window_frames_ = newest_.number;
  }
  Frame frame = snapshot(*simulation_, settings_.colour);
  frame.number = static_cast<std::uint32_t>(newest_.number + 1);
  auto message = std::make_shared<const std::string>(encode_frame(frame));
  const FluidSummary summary = summarise(frame, *simulation_);
  nlohmann::json state{{"time", simulation_->time()},
                       {"steps", simulation_->step_count()},
                       {"particles", simulation_->fluid().size()},
                       {"wall_particles", simulation_->interactions().contact_particle_count()},
                       {"scheme", scheme_text(settings_.scheme)},
                       {"surface_tension", settings_.surface_tension},
                       {"viscosity", settings_.kinematic_viscosity},
                       {"gravity", settings_.gravity},
                       {"tilt", settings_.tilt},
                       {"colour", colour_field_name(settings_.colour)},
                       {"paused", settings_.paused},
                       {"pace", options_.pace},
                       {"steps_per_second", steps_per_second_},
                       {"sim_seconds_per_second", sim_seconds_per_second_},
                       {"frames_per_second", frames_per_second_},
                       {"frame", frame.number},
                       {"mean_x", summary.mean_x},
                       {"mean_y", summary.mean_y},
                       {"mean_speed", summary.mean_speed},
                       {"max_speed", summary.max_speed},
                       {"obstacle_x", summary.obstacle_x},
                       {"obstacle_y", summary.obstacle_y}};
  {
    const std::lock_guard lock(mutex_);
    state["notice"] = notice_;
    state["notices"] = notices_;
    newest_ = {frame.number, std::move(message)};
    state_ = state.dump();
  }
  frame_ready_.notify_all();
}

void LiveSimulation::notice(std::string text) {
  const std::lock_guard lock(mutex_);
  notice_ = std::move(text);
  ++notices_;
}

}  // namespace tide::serve
