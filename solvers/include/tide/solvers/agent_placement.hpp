#pragma once

#include <cstddef>
#include <vector>

#include "tide/core/scene.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// The agents of a crowd at the start, in group order. A group placed on a `lattice` stands on the
/// rows of a square lattice centred in its region, filled row by row from the bottom, or, too
/// dense for a square lattice a body diameter apart, on a hexagonal one (rows sqrt(3)/2 of the
/// spacing apart, every other one shifted by half a spacing). A group placed at `random` stands
/// where random sequential addition puts it: uniformly in its region, a body diameter or more
/// from the agents before it, from a generator seeded with crowd.desired_speed.seed and the
/// group's index.
struct AgentStarts {
  std::vector<Vector<2>> positions;
  std::vector<std::size_t> groups;  // per agent, its index in crowd.agents
};

/// Throws scene::SceneError at /crowd/agents/k/count where two agents of a group would stand closer than
/// a body diameter (2 crowd.body_radius) to one another on either lattice, or where random
/// placement finds no free point for an agent in 10 000 draws.
AgentStarts place_agents(const scene::Scene& scene);

/// `count` desired speeds from crowd.desired_speed: normal by the Box–Muller transform of a
/// seeded 64-bit Mersenne Twister (the standard library's normal_distribution differs between
/// implementations), redrawn outside three deviations of the mean or at or below zero.
std::vector<Real> desired_speeds(const scene::DesiredSpeed& speed, std::size_t count);

}  // namespace tide
