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

/// The arrays of a sort, lent by the caller (a NeighborGrid takes them from a ScratchArena), all
/// of the same length n; the histogram is the sort's own, small and kept between sorts.
struct PairSortWorkspace {
  std::span<std::uint64_t> keys;
  std::span<Index> order;
  std::span<std::uint64_t> key_scratch;
  std::span<Index> order_scratch;
  std::vector<std::size_t> histogram;
};

/// Sorts the particle indices 0..n-1 by the codes the caller put in `workspace.keys` (one per
/// particle, n = keys.size()). On return `workspace.order` is the permutation (order[k] = index
/// of the particle that goes to slot k) and `workspace.keys` the sorted codes; the sort may have
/// swapped the spans with their scratch, which then holds what is free. Equal codes keep
/// increasing index order, so the result is unique.
void sort_pairs(SortAlgorithm algorithm, PairSortWorkspace& workspace);

}  // namespace tide
