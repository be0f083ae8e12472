#include "tide/core/particle_set.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "tide/core/scratch_arena.hpp"

namespace tide {
namespace {

TEST(ParticleSet, StartsWithIdAndPositionOnly) {
  ParticleSet<3> set;
  ASSERT_EQ(set.fields().size(), 2u);
  EXPECT_EQ(set.fields()[0].name, "id");
  EXPECT_EQ(set.fields()[1].name, "position");
  EXPECT_EQ(set.fields()[1].components, 3);
  EXPECT_EQ(set.field_bytes(), 0u);
  set.append(10);
  EXPECT_EQ(set.field_bytes(), 10 * (sizeof(Index) + 3 * sizeof(Real)));
}

TEST(ParticleSet, FieldBytesCountWhatTheArraysHoldNotTheirSize) {
  ParticleSet<3> set;
  set.add_scalar("density");
  set.append(1000);
  set.append(1);  // the arrays grow geometrically: they hold more than 1001 particles
  const std::size_t per_particle = sizeof(Index) + 4 * sizeof(Real);
  EXPECT_GT(set.field_bytes(), set.size() * per_particle);
  MemoryUsage usage;
  set.add_memory(usage, "fluid");
  ASSERT_EQ(usage.items().size(), 3u);  // id, position, density
  EXPECT_EQ(usage.items()[1].name, "fluid.position");
  EXPECT_EQ(usage.total(), set.field_bytes());
}

TEST(ParticleSet, AppendAssignsFreshIdsAndZeroFields) {
  ParticleSet<2> set;
  const auto density = set.add_scalar("density");
  set.append(3);
  set[density][1] = 5;
  EXPECT_EQ(set.append(2), 3u);
  ASSERT_EQ(set.size(), 5u);
  const auto ids = set[set.id()];
  for (Index i = 0; i < 5; ++i) EXPECT_EQ(ids[i], i);
  EXPECT_EQ(set[density][1], 5);
  EXPECT_EQ(set[density][4], 0);
}

TEST(ParticleSet, FieldsAreCreatedOnceAndTyped) {
  ParticleSet<3> set;
  const auto a = set.add_vector("velocity");
  const auto b = set.add_vector("velocity");
  EXPECT_EQ(a.slot, b.slot);
  EXPECT_THROW(set.add_scalar("velocity"), std::invalid_argument);
  EXPECT_THROW(set.scalar("pressure"), std::out_of_range);
  EXPECT_TRUE(set.has("velocity"));
  EXPECT_FALSE(set.has("pressure"));
}

// Every field, of every kind, must follow the same permutation, and dropped particles vanish.
TEST(ParticleSet, PermuteKeepsEveryFieldConsistent) {
  ParticleSet<3> set;
  const auto mass = set.add_scalar("mass");
  const auto velocity = set.add_vector("velocity");
  const auto phase = set.add_index("phase");
  constexpr std::size_t n = 10000;
  set.append(n);
  auto x = set[set.position()];
  auto v = set[velocity];
  for (std::size_t i = 0; i < n; ++i) {
    const Real s = static_cast<Real>(i);
    x.set(i, Vector<3>(s, 2 * s, 3 * s));
    v.set(i, Vector<3>(-s, -2 * s, -3 * s));
    set[mass][i] = s + Real(0.5);
    set[phase][i] = static_cast<Index>(i % 7);
  }
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), Index(0));
  for (std::size_t i = 0; i < n; ++i) std::swap(order[i], order[(i * 7919) % n]);
  order.resize(n - 100);
  ScratchArena arena;
  arena.reset(ParticleSet<3>::permute_scratch_bytes(order.size()));
  set.permute(order, arena.take<std::byte>(ParticleSet<3>::permute_scratch_bytes(order.size())));
  ASSERT_EQ(set.size(), n - 100);
  const auto ids = set[set.id()];
  const auto xs = set[set.position()];
  const auto vs = set[velocity];
  for (std::size_t k = 0; k < set.size(); ++k) {
    const Index original = ids[k];
    ASSERT_EQ(original, order[k]);
    const Real s = static_cast<Real>(original);
    EXPECT_EQ(xs[k], Vector<3>(s, 2 * s, 3 * s));
    EXPECT_EQ(vs[k], Vector<3>(-s, -2 * s, -3 * s));
    EXPECT_EQ(set[mass][k], s + Real(0.5));
    EXPECT_EQ(set[phase][k], original % 7);
  }
}

// The set keeps no reorder workspace: permute borrows the caller's, one field wide, and refuses less.
TEST(ParticleSet, PermuteBorrowsOneFieldOfScratchAndKeepsNone) {
  ParticleSet<2> set;
  const auto mass = set.add_scalar("mass");
  const auto phase = set.add_index("phase");
  constexpr std::size_t n = 1000;
  set.append(n);
  for (std::size_t i = 0; i < n; ++i) {
    set[mass][i] = static_cast<Real>(i);
    set[phase][i] = static_cast<Index>(i % 3);
  }
  const std::size_t held = set.field_bytes();
  std::vector<Index> reversed(n);
  for (std::size_t i = 0; i < n; ++i) reversed[i] = static_cast<Index>(n - 1 - i);
  std::vector<Real> too_small(n / 2);
  EXPECT_THROW(set.permute(reversed, std::as_writable_bytes(std::span<Real>(too_small))), std::invalid_argument);
  std::vector<Real> scratch(n);
  set.permute(reversed, std::as_writable_bytes(std::span<Real>(scratch)));
  EXPECT_EQ(set.field_bytes(), held);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(set[mass][i], static_cast<Real>(n - 1 - i));
    EXPECT_EQ(set[phase][i], static_cast<Index>((n - 1 - i) % 3));
  }
}

// A phase of the arena hands out aligned, disjoint spans; a reset ends the phase and grows the
// storage only when asked for more than it holds.
TEST(ScratchArena, HandsOutAlignedDisjointSpansPerPhase) {
  ScratchArena arena;
  EXPECT_EQ(arena.bytes(), 0u);
  arena.reset(ScratchArena::aligned(100 * sizeof(std::uint64_t)) + ScratchArena::aligned(10 * sizeof(Index)));
  const std::size_t held = arena.bytes();
  const auto keys = arena.take<std::uint64_t>(100);
  const auto order = arena.take<Index>(10);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(keys.data()) % ScratchArena::alignment, 0u);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(order.data()) % ScratchArena::alignment, 0u);
  EXPECT_GE(static_cast<const void*>(order.data()), static_cast<const void*>(keys.data() + keys.size()));
  EXPECT_THROW(arena.take<std::uint64_t>(held), std::length_error);
  arena.reset(8);
  EXPECT_EQ(arena.bytes(), held);
  EXPECT_EQ(static_cast<void*>(arena.take<Real>(1).data()), static_cast<void*>(keys.data()));
  arena.release();
  EXPECT_EQ(arena.bytes(), 0u);
}

// A handle names a field of the set that made it (and of that set's copies); a default handle,
// another set's handle or an absent optional field is refused instead of reading some other
// field (a default handle used to read slot 0, position x).
TEST(ParticleSetHandles, AreRefusedOnAnotherSetOrWhenDefaultOrAbsent) {
  ParticleSet<2> fluid;
  fluid.append(3);
  const ScalarField density = fluid.add_scalar("density");
  fluid[density][1] = 7;
  const ParticleSet<2> copy = fluid;
  EXPECT_EQ(copy[density][1], 7) << "a copy reads through the original's handles";

  ParticleSet<2> walls;
  walls.append(3);
  walls.add_scalar("density");
  EXPECT_THROW(walls[density], std::logic_error);
  EXPECT_THROW(walls[fluid.position()], std::logic_error);
  EXPECT_THROW(fluid[ScalarField{}], std::logic_error);
  EXPECT_THROW(fluid[VectorField{}], std::logic_error);
  EXPECT_THROW(fluid[IndexField{}], std::logic_error);

  const std::optional<ScalarField> absent;
  EXPECT_THROW(fluid[absent], std::logic_error);
  const std::optional<ScalarField> present = density;
  EXPECT_EQ(fluid[present][1], 7);
}

}  // namespace
}  // namespace tide
