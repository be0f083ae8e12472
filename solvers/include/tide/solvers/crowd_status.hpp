#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace tide {

/// The largest kernel-summed density an agent has had so far, where and when: the crush-risk
/// indicator (docs/crowds.md, "Output"), flagged above crush_density.
struct CrowdPeak {
  double density = 0;                // persons/m²
  std::array<double, 2> position{};  // m, of the agent
  double time = 0;                   // s
};

/// A crowd's state now, as crowd.csv records it (docs/crowds.md, "Output").
struct CrowdStatus {
  std::size_t inside = 0;        // agents still in the domain
  std::vector<std::size_t> out;  // per exit (crowd.exits order), agents that left through it
  double mean_density = 0;       // persons/m², the kernel-summed density averaged over the agents
  double mean_speed = 0;         // m/s, over the agents
  CrowdPeak peak;                // since the start
};

/// The start of G. K. Still's "congested" density band (5 persons/m² and more), which issue 36
/// asks to flag as a crush risk.
inline constexpr double crush_density = 5;

}  // namespace tide
