#pragma once

// The readers of the top-level keys whose values are sections (objects or arrays of objects),
// each built on its section's key table; the top-level table (scene_keys_top_level.cpp) calls
// them in order, so each sees the sections before it in values.scene().

#include "scene_json.hpp"
#include "scene_values.hpp"
#include "tide/core/scene.hpp"

namespace tide::io {

/// Also sets the walls' default layer count, which the kernel's support decides.
void read_kernel(const ValueReader& values, const Node& node, scene::Scene& scene);
/// solver.scheme "crowd": the agents, exits and model parameters (docs/crowds.md).
void read_crowd(const ValueReader& values, const Node& node, scene::Scene& scene);
/// Required unless the scene has a crowd (read before them), which has none.
void read_materials(const ValueReader& values, const Node& node, scene::Scene& scene);
/// Required unless the scene has a crowd, which has none.
void read_fluid(const ValueReader& values, const Node& node, scene::Scene& scene);
void read_walls(const ValueReader& values, const Node& node, scene::Scene& scene);

/// An obstacle's `motion`: an object with exactly one of "rotation", "oscillation", "flap", "table".
scene::Motion read_motion(const ValueReader& values, const Node& node);
/// Absent: derived from the container.
void read_domain(const ValueReader& values, const Node& node, scene::Scene& scene);
void read_solver(const ValueReader& values, const Node& node, scene::Scene& scene);
void read_time(const ValueReader& values, const Node& node, scene::Scene& scene);
/// Absent or not: the probe interval defaults to the time's output interval.
void read_output(const ValueReader& values, const Node& node, scene::Scene& scene);
void read_probes(const ValueReader& values, const Node& node, scene::Scene& scene);

}  // namespace tide::io
