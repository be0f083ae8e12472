#pragma once

// Small 2D scenes several test files run for a hundred steps or so.

#include <optional>

#include "tide/core/scene.hpp"

namespace tide {

// A 0.2 × 0.4 m water column at the left of an open 0.6 × 0.5 m tank, Δx = 1 cm, h = 1.7 Δx.
inline scene::Scene small_dam_break_2d() {
  scene::Scene s;
  s.source = "small dam break";
  s.particle_spacing = 0.01;
  s.smoothing_ratio = 1.7;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 2.0});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {0.2, 0.4, 0}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {0.6, 0.5, 0}}, true};
  s.domain.box = {{-0.03, -0.03, 0}, {0.63, 1.0, 0}};
  return s;
}

// The small dam break with a 12 × 3 cm paddle in its path, turning about its centre at 8 rad/s
// after a 0.05 s ramp (a moving wall contact).
inline scene::Scene small_dam_break_with_paddle_2d() {
  scene::Scene s = small_dam_break_2d();
  scene::Obstacle paddle;
  paddle.shape = scene::Box{{0.34, 0.08, 0}, {0.46, 0.11, 0}};
  paddle.motion = scene::Rotation{{0.4, 0.095, 0}, {0, 0, 1}, 8.0, 0.05};
  s.walls.obstacles.push_back(paddle);
  return s;
}

// A fully periodic 0.6 × 0.4 m box of water without walls or gravity, Δx = 2 cm, h = 1.7 Δx.
inline scene::Scene periodic_box_2d() {
  scene::Scene s;
  s.source = "periodic box";
  s.particle_spacing = 0.02;
  s.smoothing_ratio = 1.7;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 1.0});
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {0.6, 0.4, 0}}});
  s.domain.box = {{0, 0, 0}, {0.6, 0.4, 0}};
  s.domain.periodic = {true, true, false};
  s.gravity = {0, 0, 0};
  s.walls.layers = 0;
  return s;
}

}  // namespace tide
