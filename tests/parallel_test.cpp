#include "tide/core/parallel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "tide/core/types.hpp"

namespace tide {
namespace {

// A sum of values spanning many orders of magnitude: any change in the order of additions
// changes the rounded result, so equality across thread counts proves a fixed order.
Real ill_conditioned_sum() {
  constexpr std::size_t n = 1'000'003;
  return reduce(
      n, Real(0), [](std::size_t i) { return std::pow(Real(-1.0001), Real(i % 1000)) * std::sin(Real(i)); },
      [](Real a, Real b) { return a + b; });
}

TEST(Parallel, ReduceIsBitwiseIdenticalForOneAndTwoThreads) {
  Real one_thread = 0;
  Real two_threads = 0;
  {
    const ThreadLimit limit(1);
    EXPECT_EQ(thread_count(), 1);
    one_thread = ill_conditioned_sum();
  }
  {
    const ThreadLimit limit(2);
    two_threads = ill_conditioned_sum();
  }
  EXPECT_EQ(std::memcmp(&one_thread, &two_threads, sizeof(Real)), 0) << one_thread << " vs " << two_threads;
}

TEST(Parallel, ReduceMatchesSequentialSumOfIntegers) {
  const auto total = reduce(
      std::size_t(123457), std::uint64_t(0), [](std::size_t i) { return std::uint64_t(i); },
      [](std::uint64_t a, std::uint64_t b) { return a + b; });
  EXPECT_EQ(total, std::uint64_t(123456) * 123457 / 2);
  EXPECT_EQ(reduce(
                0, 7, [](std::size_t) { return 1; }, [](int a, int b) { return a + b; }),
            7);
}

TEST(Parallel, ForEachParticleVisitsEveryIndexOnce) {
  std::vector<int> visits(100'000, 0);
  for_each_particle(visits.size(), [&](std::size_t i) { ++visits[i]; });
  for (int v : visits) ASSERT_EQ(v, 1);
}

TEST(Parallel, ParallelSortOrdersByKeyThenIndex) {
  std::vector<KeyIndex> items;
  for (std::uint32_t i = 0; i < 50'000; ++i) items.push_back({(i * 2654435761u) % 97, i});
  parallel_sort(items);
  for (std::size_t k = 1; k < items.size(); ++k) {
    ASSERT_TRUE(items[k - 1].key < items[k].key ||
                (items[k - 1].key == items[k].key && items[k - 1].index < items[k].index));
  }
}

TEST(Parallel, ThreadLimitRejectsZero) { EXPECT_THROW(ThreadLimit(0), std::invalid_argument); }

}  // namespace
}  // namespace tide
