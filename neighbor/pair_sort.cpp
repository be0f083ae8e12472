#include "tide/neighbor/pair_sort.hpp"

#include <algorithm>
#include <bit>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "tide/core/parallel.hpp"

namespace tide {
namespace {

constexpr int digit_bits = 8;
constexpr std::size_t digit_count = std::size_t(1) << digit_bits;
// Items per radix block: fixed, so the scatter layout never depends on the thread count.
constexpr std::size_t radix_block = std::size_t(1) << 14;

void radix_sort(PairSortWorkspace& w) {
  const std::size_t n = w.keys.size();
  const std::uint64_t max_key = reduce(
      n, std::uint64_t(0), [&](std::size_t i) { return w.keys[i]; },
      [](std::uint64_t a, std::uint64_t b) { return std::max(a, b); });
  const int passes = (std::bit_width(max_key) + digit_bits - 1) / digit_bits;
  const std::size_t blocks = (n + radix_block - 1) / radix_block;
  w.histogram.resize(blocks * digit_count);

  for (int pass = 0; pass < passes; ++pass) {
    const int shift = pass * digit_bits;
    auto digit = [shift](std::uint64_t key) { return static_cast<std::size_t>((key >> shift) & (digit_count - 1)); };
    parallel_blocks(blocks, 1, [&](std::size_t first, std::size_t last) {
      for (std::size_t b = first; b < last; ++b) {
        std::size_t* count = &w.histogram[b * digit_count];
        std::fill(count, count + digit_count, std::size_t(0));
        const std::size_t end = std::min(n, (b + 1) * radix_block);
        for (std::size_t i = b * radix_block; i < end; ++i) ++count[digit(w.keys[i])];
      }
    });
    // Exclusive prefix in (digit, block) order: the stable destination of each block's items.
    std::size_t running = 0;
    for (std::size_t d = 0; d < digit_count; ++d) {
      for (std::size_t b = 0; b < blocks; ++b) {
        const std::size_t count = w.histogram[b * digit_count + d];
        w.histogram[b * digit_count + d] = running;
        running += count;
      }
    }
    parallel_blocks(blocks, 1, [&](std::size_t first, std::size_t last) {
      for (std::size_t b = first; b < last; ++b) {
        std::size_t* next = &w.histogram[b * digit_count];
        const std::size_t end = std::min(n, (b + 1) * radix_block);
        for (std::size_t i = b * radix_block; i < end; ++i) {
          const std::size_t destination = next[digit(w.keys[i])]++;
          w.key_scratch[destination] = w.keys[i];
          w.order_scratch[destination] = w.order[i];
        }
      }
    });
    std::swap(w.keys, w.key_scratch);
    std::swap(w.order, w.order_scratch);
  }
}

void comparison_sort(PairSortWorkspace& w) {
  const std::size_t n = w.keys.size();
  std::vector<KeyIndex> items(n);
  for_each_particle(n, [&](std::size_t i) { items[i] = {w.keys[i], w.order[i]}; });
  parallel_sort(items);
  for_each_particle(n, [&](std::size_t i) {
    w.keys[i] = items[i].key;
    w.order[i] = items[i].index;
  });
}

}  // namespace

std::string_view sort_algorithm_name(SortAlgorithm algorithm) {
  return algorithm == SortAlgorithm::radix ? "radix" : "comparison";
}

void sort_pairs(SortAlgorithm algorithm, PairSortWorkspace& workspace) {
  const std::size_t n = workspace.keys.size();
  if (workspace.order.size() != n || workspace.key_scratch.size() != n || workspace.order_scratch.size() != n)
    throw std::invalid_argument("pair sort: the keys, order and scratch spans differ in length");
  for_each_particle(n, [&](std::size_t i) { workspace.order[i] = static_cast<Index>(i); });
  if (algorithm == SortAlgorithm::radix) {
    radix_sort(workspace);
  } else {
    comparison_sort(workspace);
  }
}

}  // namespace tide
