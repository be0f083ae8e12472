#include "tide/neighbor/keep_inside.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace tide {
namespace {

// Every count a refinement chunk can have, with squared distances on both sides of the limit and
// on it (not kept: the support is open), against the definition written as a filter. The
// outputs are 64 values with a guard past them: keep_inside may write past the kept values up to
// 64, never beyond.
template <bool WithR2>
void expect_the_filter() {
  constexpr Real limit = Real(0.01);
  constexpr std::uint32_t guard = 0xdeadbeef;
  std::mt19937 random(7);
  std::uniform_int_distribution<std::uint32_t> any_entry;
  std::uniform_int_distribution<int> side(0, 2);
  for (int count = 0; count <= 64; ++count) {
    for (int trial = 0; trial < 20; ++trial) {
      std::array<std::uint32_t, 64> entry{};
      std::array<Real, 64> r2{};
      std::vector<std::uint32_t> expected_entries;
      std::vector<Real> expected_r2;
      for (int k = 0; k < count; ++k) {
        entry[k] = any_entry(random);
        const int where = side(random);
        r2[k] = where == 0 ? limit * Real(0.5) : where == 1 ? limit : limit * Real(1.5);
        if (r2[k] < limit) {
          expected_entries.push_back(entry[k]);
          expected_r2.push_back(r2[k]);
        }
      }
      std::array<std::uint32_t, 65> out;
      std::array<Real, 65> r2_out;
      out.fill(guard);
      r2_out.fill(-1);
      const std::size_t kept =
          keep_inside<WithR2>(entry.data(), r2.data(), count, limit, out.data(), WithR2 ? r2_out.data() : nullptr);
      ASSERT_EQ(kept, expected_entries.size()) << "count " << count;
      for (std::size_t k = 0; k < kept; ++k) {
        EXPECT_EQ(out[k], expected_entries[k]) << "count " << count << ", kept entry " << k;
        if constexpr (WithR2) {
          EXPECT_EQ(r2_out[k], expected_r2[k]) << "count " << count << ", kept entry " << k;
        }
      }
      EXPECT_EQ(out[64], guard);
      EXPECT_EQ(r2_out[64], -1);
      if constexpr (!WithR2) {
        EXPECT_EQ(r2_out[0], -1);
      }
    }
  }
}

TEST(KeepInside, KeepsTheEntriesInsideTheLimitInTheirOrder) { expect_the_filter<false>(); }

TEST(KeepInside, KeepsTheirSquaredDistancesAlongside) { expect_the_filter<true>(); }

}  // namespace
}  // namespace tide
