// Case (c) of issue 36: a single agent in an empty room walks to the door at its desired speed
// (docs/crowds.md, "What is measured").

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "crowd_support.hpp"
#include "tide/solvers/crowd_sph.hpp"
#include "tide/validation/crowd_scenes.hpp"

namespace tide::validation {
namespace {

constexpr double end_time = 20;  // s

// One agent crosses a 12 m × 6 m room to a 1.2 m door in the middle of its right wall, from off
// the door's axis, so that it must turn toward the door, not walk along a grid line; the
// navigation grid has `cells` cells per metre.
RunRecord run_single_agent(int cells, const Variant& variant) {
  require_crowd_variant(variant);
  CrowdRoom room;
  room.agents = R"([{"region": {"min": [1.5, 0.8], "max": [2.5, 1.8]}, "count": 1}])";
  room.end = end_time;
  scene::Scene scene = crowd_room(room);
  scene.crowd->navigation_cell = 1.0 / cells;
  CrowdSph crowd(scene);
  const ParticleSet<2>& agent = crowd.fluid();
  const FluidFields<2>& f = crowd.fluid_fields();
  const double v0 = static_cast<double>(agent[crowd.desired_speed()][0]);
  const Vector<2> start = agent[f.position][0];
  const double tau = scene.crowd->relaxation_time;
  double open_room_error = 0, door_error = 0, walked = 0, exit_time = -1;
  Vector<2> at = start;
  const auto clock_start = std::chrono::steady_clock::now();
  while (crowd.time() < end_time && exit_time < 0) {
    crowd.step();
    if (crowd.exited()[0] == 1) {
      exit_time = crowd.time();
      break;
    }
    const Vector<2> x = agent[f.position][0];
    walked += static_cast<double>((x - at).norm());
    at = x;
    // After five relaxation times (e^-5 = 0.67% of the start-up deficit left).
    if (crowd.time() < 5 * tau) continue;
    const double error = std::abs(static_cast<double>(agent[f.velocity][0].norm()) / v0 - 1);
    // In the open room, a metre or more from every wall, the walls' repulsion A/m exp(−(1 m − r)/B)
    // changes the speed by at most τ A/m e^(−9.4) = 1e-3 m/s; passing the door's edge it slows
    // the agent, which the walk's time includes.
    const double wall_gap = std::min({static_cast<double>(x[0]), room.length - static_cast<double>(x[0]),
                                      static_cast<double>(x[1]), room.width - static_cast<double>(x[1])});
    double& worst = wall_gap >= 1 ? open_room_error : door_error;
    worst = std::max(worst, error);
  }
  const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  if (exit_time < 0) throw std::runtime_error("the agent did not reach the door in " + std::to_string(end_time) + " s");
  // Relaxing from rest, v = v0 (1 − e^(−t/τ)), costs v0 τ of distance: a walk of length s at v0
  // takes s/v0 + τ.
  const double expected_time = walked / v0 + tau;
  const double straight = static_cast<double>((at - start).norm());
  return crowd_record("crowd_single_agent", variant, cells, 1, crowd.step_count(), wall_seconds,
                      {{"exit_time_error", std::abs(exit_time / expected_time - 1)},
                       {"open_room_speed_error", open_room_error},
                       {"door_speed_error", door_error},
                       {"path_excess", walked / straight - 1},
                       {"exit_time_s", exit_time}});
}

}  // namespace

Case crowd_single_agent_case() {
  Case c;
  c.name = "crowd_single_agent";
  c.title = "Crowd: one agent walks to the door";
  c.reference =
      "an agent alone walks at its desired speed v0 along the shortest path (issue 36: within 2%); relaxing from rest "
      "with time τ, a walk of length s takes s/v0 + τ. One agent crosses an empty 12 m × 6 m room to a 1.2 m door "
      "from off the door's axis";
  c.resolution_meaning = "navigation grid cells per metre";
  c.metric_notes = {"exit_time_error: |time to the exit / (s/v0 + τ) − 1|, s the length walked",
                    "open_room_speed_error: max |speed/v0 − 1| after 5τ, a metre or more from every wall",
                    "door_speed_error: the same within a metre of a wall (the door's edges slow the agent)",
                    "path_excess: length walked / straight line from start to exit − 1",
                    "exit_time_s: the time to the exit"};
  c.resolutions = {10, 20};
  c.test_resolution = 10;
  c.schemes = {std::string(crowd_scheme)};
  c.kernels = {KernelType::wendland_c2};
  c.run = run_single_agent;
  return c;
}

}  // namespace tide::validation
