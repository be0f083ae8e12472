#pragma once

// The simulation `tide serve` shows: a 2D scene stepped in a thread of its own, the page's
// commands applied between steps, and the newest frame kept for the pages to take. Frames are
// published at most `frame_rate` times a second of wall time; a page that is slower misses
// frames: none is queued.

#include <Eigen/Core>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tide/core/scene.hpp"
#include "tide/serve/command.hpp"
#include "tide/serve/live_scene.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide::serve {

struct LiveOptions {
  double pace = 1;         // simulated seconds per wall second at most; 0: as fast as it runs
  double frame_rate = 60;  // frames published per wall second at most
};

/// A published frame: its number (counting from 1) and its encoded message.
struct PublishedFrame {
  std::uint64_t number = 0;
  std::shared_ptr<const std::string> message;
};

class LiveSimulation {
 public:
  /// Builds the simulation of `scene` (2D, wcsph or dfsph; std::invalid_argument otherwise, or
  /// InstabilityError); the thread starts with start().
  LiveSimulation(scene::Scene scene, LiveOptions options);
  ~LiveSimulation();
  LiveSimulation(const LiveSimulation&) = delete;
  LiveSimulation& operator=(const LiveSimulation&) = delete;

  void start();
  void stop();

  /// Queues a command for the simulation thread; an obstacle target replaces the last one not
  /// yet taken. False, with nothing queued, when `queue_limit` commands are waiting.
  bool submit(const Command& command);
  static constexpr std::size_t queue_limit = 64;

  /// The newest frame once its number is above `after` or `until` has passed (then the newest,
  /// whatever its number, or none before the first), or once stop() is called.
  PublishedFrame wait_for_frame(std::uint64_t after, std::chrono::steady_clock::time_point until) const;

  /// The state as a JSON object (docs/serve.md, "State"): time, steps, particles, settings,
  /// rates, the fluid's means, the last notice.
  std::string state_json() const;

 private:
  void run();
  void rebuild();
  void apply(const Command& command);
  void step_once();
  void publish();
  void notice(std::string text);

  const scene::Scene base_;
  std::size_t base_particles_ = 0;
  LiveOptions options_;
  LiveSettings settings_;
  std::unique_ptr<Simulation<2>> simulation_;                // the simulation thread's alone once started
  Eigen::Vector2d obstacle_home_ = Eigen::Vector2d::Zero();  // the obstacle's centroid where the scene puts it
  // Where that centroid may go: inside the container, the obstacle two particle spacings from its
  // walls, so that it cannot crush the fluid against them.
  Eigen::Vector2d obstacle_least_ = Eigen::Vector2d::Constant(-1e30), obstacle_most_ = Eigen::Vector2d::Constant(1e30);
  bool step_requested_ = false;

  // The wall clock the simulated time is paced against, and the window the rates are measured over.
  std::chrono::steady_clock::time_point pace_start_;
  double pace_start_time_ = 0;
  std::chrono::steady_clock::time_point last_publish_;
  std::chrono::steady_clock::time_point window_start_;
  std::uint64_t window_steps_ = 0;
  double window_time_ = 0;
  std::uint64_t window_frames_ = 0;
  double steps_per_second_ = 0, sim_seconds_per_second_ = 0, frames_per_second_ = 0;

  mutable std::mutex mutex_;  // guards what follows
  mutable std::condition_variable frame_ready_;
  std::condition_variable command_ready_;
  std::vector<Command> commands_;
  std::optional<MoveObstacle> obstacle_target_;
  PublishedFrame newest_;
  std::string state_;
  std::string notice_;
  std::uint64_t notices_ = 0;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace tide::serve
