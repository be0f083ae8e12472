#pragma once

#include <cstddef>
#include <vector>

namespace tide {

/// A crowd's state now, as crowd.csv records it (docs/crowds.md, "Output").
struct CrowdStatus {
  std::size_t inside = 0;        // agents still in the domain
  std::vector<std::size_t> out;  // per exit (crowd.exits order), agents that left through it
  double mean_density = 0;       // persons/m², the kernel-summed density averaged over the agents
  double mean_speed = 0;         // m/s, over the agents
};

}  // namespace tide
