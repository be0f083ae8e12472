#pragma once

// What CrowdSph builds from its scene once: the navigation field around the wall particles, and
// the check that every agent starts clear of the walls with an exit it can reach.

#include "tide/core/scene.hpp"
#include "tide/solvers/agent_placement.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/navigation_field.hpp"

namespace tide::crowd_setup {

/// The distance field to crowd.exits on cells of crowd.navigation_cell over the domain box,
/// blocked where a cell's centre is closer than a body radius to a wall surface (half a spacing
/// beyond a wall particle). Throws scene::SceneError at /crowd/exits/k for an exit with no open
/// cell in it.
NavigationField navigation_field(const scene::Scene& scene, const Interactions<2>& interactions);

/// Throws scene::SceneError at /crowd/agents/k for the first agent inside or within a body radius
/// of a wall (a blocked cell), or, in a group without a heading, with no exit it can reach.
void check_agent_starts(const scene::Scene& scene, const AgentStarts& starts, const NavigationField& navigation);

}  // namespace tide::crowd_setup
