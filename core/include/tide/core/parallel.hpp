#pragma once

// The parallel layer: the only part of TideSPH that knows which threading library runs the
// loops (oneTBB, in parallel.cpp). Every pass is written against these functions, so another
// backend (a GPU, MPI ranks) replaces this file pair and nothing else.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "tide/core/function_ref.hpp"

namespace tide {

/// Number of items per block in `reduce`. Fixed, so the combination order of partial results
/// never depends on the number of threads.
inline constexpr std::size_t reduce_block_size = 4096;

/// Runs body(begin, end) over disjoint blocks covering [0, n), in parallel.
void parallel_blocks(std::size_t n, std::size_t grain, FunctionRef<void(std::size_t, std::size_t)> body);

/// Runs f(i) for every i in [0, n) in parallel. f must only write data owned by item i
/// (gather-only passes, see DESIGN.md), so the result does not depend on scheduling.
template <class F>
void for_each_particle(std::size_t n, F&& f) {
  parallel_blocks(n, 256, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) f(i);
  });
}

/// Deterministic reduction: combine(map(0), map(1), ...) evaluated over fixed blocks of
/// `reduce_block_size` items whose partial results are combined in block order. The result
/// is bitwise identical for any thread count, also for non-associative floating-point sums.
template <class T, class Map, class Combine>
T reduce(std::size_t n, T identity, Map&& map, Combine&& combine) {
  const std::size_t blocks = (n + reduce_block_size - 1) / reduce_block_size;
  std::vector<T> partial(blocks, identity);
  parallel_blocks(blocks, 1, [&](std::size_t first_block, std::size_t last_block) {
    for (std::size_t b = first_block; b < last_block; ++b) {
      const std::size_t end = std::min(n, (b + 1) * reduce_block_size);
      T accumulated = identity;
      for (std::size_t i = b * reduce_block_size; i < end; ++i) accumulated = combine(accumulated, map(i));
      partial[b] = accumulated;
    }
  });
  T result = identity;
  for (const T& value : partial) result = combine(result, value);
  return result;
}

/// A sort key with the position it came from; `parallel_sort` orders by key, then position.
struct KeyIndex {
  std::uint64_t key = 0;
  std::uint32_t index = 0;
};

/// Parallel comparison sort (tbb::parallel_sort) by (key, index). Since indices are distinct
/// the order is total and the result does not depend on the thread count.
void parallel_sort(std::span<KeyIndex> items);

/// Number of worker threads the parallel layer uses at present.
int thread_count();

/// Caps the number of threads while it is alive (wraps tbb::global_control).
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  struct Control;
  std::unique_ptr<Control> control_;
};

}  // namespace tide
