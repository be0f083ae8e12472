#pragma once

#include <string>
#include <vector>

#include "tide/solvers/pipeline.hpp"

namespace tide {

/// Each stage's share of the seconds of all `times` in tenths of a percent, in their order,
/// rounded by largest remainders so that the shares add to exactly 1000; all 0 while no time was
/// taken.
std::vector<int> stage_shares_permille(const std::vector<StageTime>& times);

/// Every stage with its share, "kick_drift 3.1%, neighbor_search 40.2%, …", adding to 100%.
std::string format_stage_shares(const std::vector<StageTime>& times);

}  // namespace tide
