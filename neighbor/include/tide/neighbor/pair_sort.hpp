#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "tide/core/types.hpp"

namespace tide {

/// How the neighbour grid sorts (cell code, particle index) pairs. Both are deterministic for
/// any thread count; bench/neighbor_bench measures them against each other.
enum class SortAlgorithm {
  radix,      ///< parallel least-significant-digit radix sort, 8-bit digits, stable
  comparison  ///< tbb::parallel_sort on (code, index), index breaking ties
};

std::string_view sort_algorithm_name(SortAlgorithm algorithm);

/// Scratch memory kept between sorts so that a step allocates nothing once sizes settle.
struct PairSortWorkspace {
  std::vector<std::uint64_t> keys;
  std::vector<Index> order;
  std::vector<std::uint64_t> key_scratch;
  std::vector<Index> order_scratch;
  std::vector<std::size_t> histogram;
};

/// Sorts the particle indices 0..n-1 by the codes the caller put in `workspace.keys` (one per
/// particle, n = keys.size()), in place. On return `workspace.order` is the permutation
/// (order[k] = index of the particle that goes to slot k) and `workspace.keys` the sorted codes.
/// Equal codes keep increasing index order, so the result is unique.
void sort_pairs(SortAlgorithm algorithm, PairSortWorkspace& workspace);

}  // namespace tide
