// tide serve's live simulation (tide/serve/live_simulation.hpp): commands reach the simulation
// thread and change what it steps, and the frames it publishes hold its particles.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "tide/serve/frame.hpp"
#include "tide/serve/live_simulation.hpp"

namespace tide::serve {
namespace {

using namespace std::chrono_literals;

// Water 0.1 m deep in a closed tank 0.4 m wide, with a steered disc above it; 200 particles.
scene::Scene small_tank() {
  scene::Scene s;
  s.source = "small tank";
  s.dimension = 2;
  s.particle_spacing = 0.01;
  s.materials.push_back({"water", 1000, 1e-4, std::nullopt, 2.0});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {0.2, 0.1, 0}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {0.4, 0.3, 0}}, false};
  scene::Obstacle disc;
  disc.shape = scene::Ball{{0.3, 0.2, 0}, 0.03};
  disc.motion = scene::Steered{1};
  s.walls.obstacles.push_back(disc);
  s.domain.box = {{-0.03, -0.03, 0}, {0.43, 0.33, 0}};
  s.solver.scheme = scene::Scheme::dfsph;
  s.solver.viscosity = scene::ViscosityModel::laminar;
  return s;
}

nlohmann::json state_of(const LiveSimulation& live) { return nlohmann::json::parse(live.state_json()); }

// The state once `holds` is true of it, within 20 s.
nlohmann::json wait_for(const LiveSimulation& live, const std::function<bool(const nlohmann::json&)>& holds) {
  const auto end = std::chrono::steady_clock::now() + 20s;
  nlohmann::json state = state_of(live);
  while (!holds(state) && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(10ms);
    state = state_of(live);
  }
  EXPECT_TRUE(holds(state)) << state.dump();
  return state;
}

TEST(LiveSimulation, CommandsChangeTheRunningSimulation) {
  LiveSimulation live(small_tank(), {0, 60});
  const nlohmann::json first = state_of(live);
  EXPECT_EQ(first["particles"], 200);
  EXPECT_EQ(first["scheme"], "dfsph");
  live.start();

  live.submit(Pause{true});
  const nlohmann::json paused = wait_for(live, [](const nlohmann::json& s) { return s["paused"] == true; });
  live.submit(Step{});
  wait_for(live, [&](const nlohmann::json& s) { return s["steps"] == paused["steps"].get<int>() + 1; });
  live.submit(Pause{false});

  live.submit(SetGravity{5, 90});
  wait_for(live, [](const nlohmann::json& s) { return s["gravity"] == 5 && s["tilt"] == 90; });
  live.submit(SetViscosity{1e-3});
  wait_for(live, [](const nlohmann::json& s) { return s["viscosity"] == 1e-3; });

  // The obstacle goes where it is sent, kept inside the tank (while DFSPH's long steps
  // take it there soon, under the sanitizers too).
  live.submit(MoveObstacle{-5, 0.2});
  const nlohmann::json moved = wait_for(live, [](const nlohmann::json& s) { return s["obstacle_x"] < 0.1; });
  EXPECT_GT(moved["obstacle_x"].get<double>(), 0.03) << "clear of the left wall";

  // Four times the particles: half the spacing, and the settings kept.
  live.submit(SetParticleCount{800});
  const nlohmann::json refilled = wait_for(live, [](const nlohmann::json& s) { return s["particles"] == 800; });
  EXPECT_EQ(refilled["gravity"], 5);
  EXPECT_EQ(refilled["viscosity"], 1e-3);

  live.submit(SetSurfaceTension{true});
  const nlohmann::json refused = wait_for(live, [](const nlohmann::json& s) { return s["notices"] == 1; });
  EXPECT_NE(refused["notice"].get<std::string>().find("WCSPH only"), std::string::npos);
  EXPECT_EQ(refused["surface_tension"], false);
  live.submit(SetScheme{scene::Scheme::wcsph});
  live.submit(SetSurfaceTension{true});
  wait_for(live, [](const nlohmann::json& s) { return s["scheme"] == "wcsph" && s["surface_tension"] == true; });
}

TEST(LiveSimulation, FramesHoldTheParticlesAndAreNotQueued) {
  LiveSimulation live(small_tank(), {0, 1000});
  live.start();
  const PublishedFrame first = live.wait_for_frame(0, std::chrono::steady_clock::now() + 10s);
  ASSERT_TRUE(first.message);
  std::uint32_t fluid = 0, obstacle = 0;
  std::memcpy(&fluid, first.message->data() + 8, 4);
  std::memcpy(&obstacle, first.message->data() + 16, 4);
  EXPECT_EQ(fluid, 200u);
  EXPECT_GT(obstacle, 0u);
  // A watcher that waits gets the newest frame, whatever it missed.
  std::this_thread::sleep_for(200ms);
  const PublishedFrame later = live.wait_for_frame(first.number, std::chrono::steady_clock::now() + 10s);
  EXPECT_GT(later.number, first.number + 1);
}

TEST(LiveSimulation, RefusesA3DScene) {
  scene::Scene s = small_tank();
  s.dimension = 3;
  EXPECT_THROW(LiveSimulation(s, {}), std::invalid_argument);
}

}  // namespace
}  // namespace tide::serve
