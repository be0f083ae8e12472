#include "tide/neighbor/neighbor_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "tide/core/kernels/cubic_spline.hpp"
#include "tide/core/log.hpp"
#include "tide/neighbor/morton.hpp"
#include "tide/neighbor/neighbor_list.hpp"
#include "tide/solvers/interactions.hpp"

namespace tide {
namespace {

constexpr Real support = Real(0.1);

enum class Cloud { uniform, clustered, lattice, sheet, cell_borders };

std::string cloud_name(Cloud cloud) {
  switch (cloud) {
    case Cloud::uniform:
      return "uniform";
    case Cloud::clustered:
      return "clustered";
    case Cloud::lattice:
      return "lattice";
    case Cloud::sheet:
      return "sheet";
    case Cloud::cell_borders:
      return "cell_borders";
  }
  return "?";
}

// Domain [0, 1] x [0, 0.8] (x [0, 0.6]): axes of different lengths, none a multiple of the
// support, so cells are wider than the support and differ per axis.
template <int D>
GridDomain<D> test_domain(bool periodic) {
  GridDomain<D> domain;
  domain.lower.setZero();
  for (int d = 0; d < D; ++d) {
    domain.upper[d] = Real(1) - Real(0.2) * Real(d);
    domain.periodic[d] = periodic;
  }
  return domain;
}

template <int D>
std::vector<Vector<D>> make_cloud(Cloud cloud, const GridDomain<D>& domain, const Vector<D>& cell_size) {
  std::mt19937_64 random(42 + static_cast<int>(cloud));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  const Vector<D> extent = domain.upper - domain.lower;
  std::vector<Vector<D>> points;
  auto inside = [&](const Vector<D>& p) {
    for (int d = 0; d < D; ++d)
      if (!(p[d] >= domain.lower[d] && p[d] < domain.upper[d])) return false;
    return true;
  };
  switch (cloud) {
    case Cloud::uniform:
      for (int k = 0; k < 2500; ++k) {
        Vector<D> p;
        for (int d = 0; d < D; ++d) p[d] = domain.lower[d] + Real(unit(random)) * extent[d];
        points.push_back(p);
      }
      break;
    case Cloud::clustered:
      // Gaussian clusters, two of them straddling the domain's corner (periodic images).
      for (int c = 0; c < 6; ++c) {
        Vector<D> centre;
        for (int d = 0; d < D; ++d) centre[d] = c < 2 ? Real(0.01) : Real(unit(random)) * extent[d];
        for (int k = 0; k < 400; ++k) {
          Vector<D> p;
          for (int d = 0; d < D; ++d) p[d] = centre[d] + Real(0.03 * normal(random));
          if (inside(p)) points.push_back(p);
        }
      }
      break;
    case Cloud::lattice: {
      // Spacing support/2: many pairs sit at exactly the support distance (excluded, r < support).
      const Real spacing = support / 2;
      std::array<int, D> count;
      for (int d = 0; d < D; ++d) count[d] = static_cast<int>(extent[d] / spacing);
      std::array<int, D> k{};
      while (true) {
        Vector<D> p;
        for (int d = 0; d < D; ++d) p[d] = domain.lower[d] + spacing * Real(k[d]);
        if (inside(p)) points.push_back(p);
        int d = 0;
        while (d < D && ++k[d] == count[d]) k[d++] = 0;
        if (d == D) break;
      }
      break;
    }
    case Cloud::sheet:
      // All particles on one plane through the domain, at a cell border.
      for (int k = 0; k < 2000; ++k) {
        Vector<D> p;
        for (int d = 0; d < D; ++d) p[d] = domain.lower[d] + Real(unit(random)) * extent[d];
        p[D - 1] = domain.lower[D - 1] + 2 * cell_size[D - 1];
        points.push_back(p);
      }
      break;
    case Cloud::cell_borders:
      // Every coordinate exactly on a cell border (or one support away from it).
      for (int k = 0; k < 2500; ++k) {
        Vector<D> p;
        for (int d = 0; d < D; ++d) {
          const int cells = static_cast<int>(std::round(extent[d] / cell_size[d]));
          const int index = static_cast<int>(unit(random) * cells);
          p[d] = domain.lower[d] + Real(index) * cell_size[d] + (k % 3 == 0 ? support : Real(0));
          if (p[d] >= domain.upper[d]) p[d] = domain.lower[d] + Real(index) * cell_size[d];
        }
        points.push_back(p);
      }
      break;
  }
  return points;
}

template <int D>
std::vector<Vector<D>> image_shifts(const GridDomain<D>& domain) {
  std::vector<Vector<D>> shifts{Vector<D>::Zero()};
  for (int d = 0; d < D; ++d) {
    if (!domain.periodic[d]) continue;
    const std::size_t existing = shifts.size();
    for (std::size_t s = 0; s < existing; ++s) {
      for (Real sign : {Real(1), Real(-1)}) {
        Vector<D> shifted = shifts[s];
        shifted[d] = sign * (domain.upper[d] - domain.lower[d]);
        shifts.push_back(shifted);
      }
    }
  }
  return shifts;
}

// O(N²) reference: ids of all j with |x_i − (x_j + image)| < support for some periodic image,
// computed with the same floating-point operations as the grid.
template <int D>
std::vector<Index> brute_force(const Vector<D>& point, const ParticleSet<D>& set, const GridDomain<D>& domain) {
  const auto x = set[set.position()];
  const auto ids = set[set.id()];
  const auto shifts = image_shifts(domain);
  std::vector<Index> found;
  for (std::size_t j = 0; j < set.size(); ++j) {
    for (const Vector<D>& shift : shifts) {
      const Vector<D> image = point - shift;
      Vector<D> xij;
      for (int d = 0; d < D; ++d) xij[d] = image[d] - x.component[d][j];
      if (squared_norm<D>(xij) < support * support) found.push_back(ids[j]);
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

struct GridCase {
  int dimension;
  Cloud cloud;
  bool periodic;
  SortAlgorithm sort;
  CellLookup lookup;
};

std::string case_name(const testing::TestParamInfo<GridCase>& info) {
  const GridCase& c = info.param;
  return std::to_string(c.dimension) + "D_" + cloud_name(c.cloud) + (c.periodic ? "_periodic" : "_open") + "_" +
         std::string(sort_algorithm_name(c.sort)) + "_" + std::string(cell_lookup_name(c.lookup));
}

class NeighborGridAgainstBruteForce : public testing::TestWithParam<GridCase> {
 protected:
  template <int D>
  void check() {
    const GridCase& c = GetParam();
    const GridDomain<D> domain = test_domain<D>(c.periodic);
    NeighborGrid<D> grid(domain, support, c.sort, c.lookup);
    ParticleSet<D> set;
    const auto points = make_cloud<D>(c.cloud, domain, grid.cell_size());
    ASSERT_GT(points.size(), 300u);
    set.append(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) set[set.position()].set(i, points[i]);
    const auto mass = set.add_scalar("mass");
    for (std::size_t i = 0; i < set.size(); ++i) set[mass][i] = Real(set[set.id()][i]);

    ASSERT_EQ(grid.update(set), 0u);
    ASSERT_EQ(set.size(), points.size());
    const auto x = set[set.position()];
    const auto ids = set[set.id()];
    // The sort moved every field together.
    for (std::size_t i = 0; i < set.size(); ++i) {
      ASSERT_EQ(set[mass][i], Real(ids[i]));
      ASSERT_EQ(x[i], points[ids[i]]);
    }

    std::size_t pairs = 0;
    for (std::size_t i = 0; i < set.size(); ++i) {
      std::vector<Index> found;
      grid.for_each_neighbor(i, x, [&](Index j, const Vector<D>& xij, Real r2) {
        found.push_back(ids[j]);
        EXPECT_EQ(r2, squared_norm<D>(xij));
      });
      std::sort(found.begin(), found.end());
      const auto expected = brute_force<D>(x[i], set, domain);
      ASSERT_EQ(found, expected) << "particle id " << ids[i];
      pairs += found.size();
    }
    EXPECT_GT(pairs, set.size());  // not only self-pairs: the test exercises real neighbours

    // The neighbour list gives the cell walk's neighbours, in its order, with the same x_ij and r².
    NeighborList<D> list;
    list.build(grid, x, grid.own_neighbors(), x);
    for (std::size_t i = 0; i < set.size(); ++i) {
      std::vector<std::pair<Index, Vector<D>>> walked;
      grid.for_each_neighbor(i, x, [&](Index j, const Vector<D>& xij, Real) { walked.emplace_back(j, xij); });
      std::size_t k = 0;
      list.for_each(i, x, x, [&](Index j, const Vector<D>& xij, Real r2) {
        ASSERT_LT(k, walked.size());
        EXPECT_EQ(j, walked[k].first);
        EXPECT_EQ(xij, walked[k].second);
        EXPECT_EQ(r2, squared_norm<D>(walked[k].second));
        ++k;
      });
      ASSERT_EQ(k, walked.size()) << "particle id " << ids[i];
    }

    // Cross-set queries, including points up to one support outside a closed domain.
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-0.1, 1.1);
    for (int q = 0; q < 300; ++q) {
      Vector<D> point;
      for (int d = 0; d < D; ++d) point[d] = domain.lower[d] + Real(unit(random)) * (domain.upper[d] - domain.lower[d]);
      std::vector<Index> found;
      grid.for_each_neighbor_of(point, x, [&](Index j, const Vector<D>&, Real) { found.push_back(ids[j]); });
      std::sort(found.begin(), found.end());
      Vector<D> wrapped = point;
      for (int d = 0; d < D; ++d) {
        if (!domain.periodic[d]) continue;
        const Real length = domain.upper[d] - domain.lower[d];
        wrapped[d] -= length * std::floor((wrapped[d] - domain.lower[d]) / length);
      }
      ASSERT_EQ(found, brute_force<D>(wrapped, set, domain)) << "query " << q;
    }
  }
};

TEST_P(NeighborGridAgainstBruteForce, FindsExactlyTheBruteForceNeighbours) {
  if (GetParam().dimension == 2) {
    check<2>();
  } else {
    check<3>();
  }
}

std::vector<GridCase> all_cases() {
  std::vector<GridCase> cases;
  for (int dimension : {2, 3})
    for (Cloud cloud : {Cloud::uniform, Cloud::clustered, Cloud::lattice, Cloud::sheet, Cloud::cell_borders})
      for (bool periodic : {false, true}) {
        cases.push_back({dimension, cloud, periodic, SortAlgorithm::radix, CellLookup::hash});
        cases.push_back({dimension, cloud, periodic, SortAlgorithm::comparison, CellLookup::dense});
        cases.push_back({dimension, cloud, periodic, SortAlgorithm::radix, CellLookup::automatic});
      }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Clouds, NeighborGridAgainstBruteForce, testing::ValuesIn(all_cases()), case_name);

TEST(NeighborGrid, RemovesParticlesOutsideTheDomainWithAWarning) {
  std::vector<std::string> warnings;
  const LogSink previous = set_log_sink([&](LogLevel level, std::string_view message) {
    if (level == LogLevel::warning) warnings.emplace_back(message);
  });
  GridDomain<2> domain;
  domain.upper = Vector<2>(1, 1);
  NeighborGrid<2> grid(domain, support);
  ParticleSet<2> set;
  set.append(5);
  auto x = set[set.position()];
  x.set(0, Vector<2>(0.5, 0.5));
  x.set(1, Vector<2>(1.5, 0.5));
  x.set(2, Vector<2>(0.5, std::numeric_limits<Real>::quiet_NaN()));
  x.set(3, Vector<2>(0.2, -0.01));
  x.set(4, Vector<2>(0.99, 0.99));
  EXPECT_EQ(grid.update(set), 3u);
  set_log_sink(previous);
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(grid.removed_total(), 3u);
  std::vector<Index> kept(set[set.id()].begin(), set[set.id()].end());
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(kept, (std::vector<Index>{0, 4}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("3 particle(s)"), std::string::npos) << warnings[0];
}

TEST(NeighborGrid, WrapsPositionsOnPeriodicAxes) {
  GridDomain<2> domain;
  domain.upper = Vector<2>(1, 1);
  domain.periodic = {true, false};
  NeighborGrid<2> grid(domain, support);
  ParticleSet<2> set;
  set.append(2);
  set[set.position()].set(0, Vector<2>(1.25, 0.5));
  set[set.position()].set(1, Vector<2>(-0.25, 0.5));
  EXPECT_EQ(grid.update(set), 0u);
  const auto x = set[set.position()];
  const auto ids = set[set.id()];
  for (std::size_t i = 0; i < 2; ++i) {
    const Real expected = ids[i] == 0 ? Real(0.25) : Real(0.75);
    EXPECT_NEAR(x[i][0], expected, 1e-6);
  }
}

// A particle set with one particle at each point.
ParticleSet<3> particles_at(const std::vector<Vector<3>>& points) {
  ParticleSet<3> set;
  set.append(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) set[set.position()].set(i, points[i]);
  return set;
}

// Every (query, source) neighbour pair a list over `table` yields, by particle id.
template <int D>
std::vector<std::pair<Index, Index>> listed_pairs(const NeighborGrid<D>& queries, const ParticleSet<D>& query_set,
                                                  const CrossNeighbors<D>& table, const ParticleSet<D>& source_set) {
  const auto qx = query_set[query_set.position()];
  const auto sx = source_set[source_set.position()];
  NeighborList<D> list;
  list.build(queries, qx, table, sx);
  std::vector<std::pair<Index, Index>> pairs;
  for (std::size_t i = 0; i < query_set.size(); ++i)
    list.for_each(i, qx, sx, [&](Index j, const Vector<D>&, Real) {
      pairs.emplace_back(query_set[query_set.id()][i], source_set[source_set.id()][j]);
    });
  return pairs;
}

// A grid sorted once (fixed walls) frees its sort workspace and own table; the cross tables and
// lists in both directions stay those of the full grid, and the next update restores everything.
TEST(NeighborGrid, ReleasedGridStillLinksToAnotherSet) {
  const GridDomain<3> domain = test_domain<3>(false);
  NeighborGrid<3> fluid_grid(domain, support);
  NeighborGrid<3> wall_grid(domain, support);
  ParticleSet<3> fluid = particles_at(make_cloud<3>(Cloud::uniform, domain, fluid_grid.cell_size()));
  ParticleSet<3> walls = particles_at(make_cloud<3>(Cloud::clustered, domain, wall_grid.cell_size()));
  ASSERT_EQ(fluid_grid.update(fluid), 0u);
  ASSERT_EQ(wall_grid.update(walls), 0u);

  const auto links = [&] {
    CrossNeighbors<3> to_walls;
    CrossNeighbors<3> to_fluid;
    to_walls.build(fluid_grid, wall_grid);
    to_fluid.build(wall_grid, fluid_grid);
    return std::pair{listed_pairs<3>(fluid_grid, fluid, to_walls, walls),
                     listed_pairs<3>(wall_grid, walls, to_fluid, fluid)};
  };
  const auto full = links();
  ASSERT_GT(full.first.size(), fluid.size());
  const std::size_t full_bytes = wall_grid.bytes();

  wall_grid.release_update_memory();
  EXPECT_EQ(links(), full);
  // The sort workspace alone is 24 B per particle (two 8-byte keys and two 4-byte indices).
  EXPECT_LE(wall_grid.bytes() + 24 * walls.size(), full_bytes);
  const auto wall_x = std::as_const(walls)[walls.position()];
  std::size_t found = 0;
  for (std::size_t i = 0; i < walls.size(); ++i)
    wall_grid.for_each_neighbor(i, wall_x, [&](Index, const Vector<3>&, Real) { ++found; });
  EXPECT_EQ(found, 0u);

  ASSERT_EQ(wall_grid.update(walls), 0u);
  EXPECT_EQ(links(), full);
  EXPECT_EQ(wall_grid.bytes(), full_bytes);
}

// Sources in one corner of a closed domain, queries everywhere: the query cells far from the
// sources skip their look-ups, and every query still gets exactly its brute-force neighbours.
TEST(CrossNeighbors, FindsTheBruteForceNeighboursOfSourcesInACorner) {
  const GridDomain<3> domain = test_domain<3>(false);
  NeighborGrid<3> query_grid(domain, support);
  NeighborGrid<3> source_grid(domain, support);
  std::vector<Vector<3>> source_points;
  for (const Vector<3>& p : make_cloud<3>(Cloud::uniform, domain, source_grid.cell_size()))
    if (p[0] < Real(0.3) && p[1] < Real(0.25)) source_points.push_back(p);
  ASSERT_GT(source_points.size(), 100u);
  ParticleSet<3> queries = particles_at(make_cloud<3>(Cloud::clustered, domain, query_grid.cell_size()));
  ParticleSet<3> sources = particles_at(source_points);
  ASSERT_EQ(query_grid.update(queries), 0u);
  ASSERT_EQ(source_grid.update(sources), 0u);
  CrossNeighbors<3> table;
  table.build(query_grid, source_grid);

  std::vector<std::vector<Index>> found(queries.size());
  for (const auto& [query, source] : listed_pairs<3>(query_grid, queries, table, sources))
    found[query].push_back(source);
  const auto x = std::as_const(queries)[queries.position()];
  const auto ids = std::as_const(queries)[queries.id()];
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    std::vector<Index>& mine = found[ids[i]];
    std::sort(mine.begin(), mine.end());
    ASSERT_EQ(mine, brute_force<3>(x[i], sources, domain)) << "query id " << ids[i];
    pairs += mine.size();
  }
  EXPECT_GT(pairs, 0u);
}

// Moves every particle by a random offset of length up to `reach` (a quarter of them by exactly
// `reach`), in a fixed sequence.
void move_by_up_to(ParticleSet<3>& set, Real reach, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto x = set[set.position()];
  for (std::size_t i = 0; i < set.size(); ++i) {
    Vector<3> direction(Real(normal(random)), Real(normal(random)), Real(normal(random)));
    const Real length = i % 4 == 0 ? reach : reach * Real(unit(random));
    x.set(i, x[i] + length / direction.norm() * direction);
  }
}

// Which particles (by id) each particle (by id) finds through `list`.
std::vector<std::vector<Index>> found_by_id(const NeighborList<3>& list, const ParticleSet<3>& queries,
                                            const ParticleSet<3>& sources) {
  const auto qx = queries[queries.position()];
  const auto sx = sources[sources.position()];
  const auto query_ids = queries[queries.id()];
  const auto source_ids = sources[sources.id()];
  std::vector<std::vector<Index>> found(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    list.for_each(i, qx, sx, [&](Index j, const Vector<3>&, Real) { found[query_ids[i]].push_back(source_ids[j]); });
    std::sort(found[query_ids[i]].begin(), found[query_ids[i]].end());
  }
  return found;
}

// A list built on grids with a skin holds candidates up to support + skin; after every particle
// has moved up to half the skin, its refinement is exactly the brute-force neighbours at the new
// positions, in the candidates' order, on closed and periodic domains.
class RefinedList : public testing::TestWithParam<bool> {
 protected:
  // Sorts the clustered cloud and lists its candidates.
  void SetUp() override {
    ASSERT_EQ(grid.update(set), 0u);
    const auto x = std::as_const(set)[set.position()];
    candidates.build(grid, x, grid.own_neighbors(), x);
  }

  const GridDomain<3> domain = test_domain<3>(GetParam());
  const Real skin = Real(0.3) * support;
  NeighborGrid<3> grid{domain, support, SortAlgorithm::radix, CellLookup::automatic, skin};
  ParticleSet<3> set = particles_at(make_cloud<3>(Cloud::clustered, domain, grid.cell_size()));
  NeighborList<3> candidates;
};

TEST_P(RefinedList, IsTheBruteForceNeighboursAfterMovesOfUpToHalfTheSkin) {
  const auto x = std::as_const(set)[set.position()];
  std::vector<std::vector<Index>> candidate_order(set.size());
  for (std::size_t i = 0; i < set.size(); ++i)
    candidates.for_each(i, x, x, [&](Index j, const Vector<3>&, Real) { candidate_order[i].push_back(j); });

  move_by_up_to(set, skin / 2, 7);
  NeighborList<3> list;
  list.refine(candidates, x, x);
  const std::vector<std::vector<Index>> found = found_by_id(list, set, set);
  const auto ids = std::as_const(set)[set.id()];
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    ASSERT_EQ(found[ids[i]], brute_force<3>(x[i], set, domain)) << "particle id " << ids[i];
    pairs += found[ids[i]].size();
    std::vector<Index> order;
    list.for_each(i, x, x, [&](Index j, const Vector<3>&, Real) { order.push_back(j); });
    auto next = candidate_order[i].begin();
    for (const Index j : order) {
      next = std::find(next, candidate_order[i].end(), j);
      ASSERT_NE(next, candidate_order[i].end()) << "particle id " << ids[i] << ": not in the candidates' order";
      ++next;
    }
  }
  EXPECT_GT(pairs, 10 * set.size());
}

// A pair of the list as a walk hands it out: source index and r².
using ListedPair = std::pair<Index, Real>;

// What for_each_run hands out for particle i's pairs: indices and r².
std::vector<ListedPair> listed_by_runs(const NeighborList<3>& list, std::size_t i, const ConstVectorView<3>& x) {
  std::vector<ListedPair> listed;
  list.for_each_run(i, x, x, [&](const NeighborRun<3>& run) {
    for (int k = 0; k < run.count; ++k) listed.emplace_back(run.index[k], run.r2[k]);
  });
  return listed;
}

// A refinement that hands each particle's pairs to a visitor lists what the plain refinement
// does, and hands out exactly (bitwise) the indices and r² a later walk of the list computes.
TEST_P(RefinedList, HandsEachParticlesPairsWithTheRSquaredOfAWalk) {
  const auto x = std::as_const(set)[set.position()];
  move_by_up_to(set, skin / 2, 3);

  NeighborList<3> plain;
  plain.refine(candidates, x, x);
  NeighborList<3> visited;
  std::vector<std::vector<ListedPair>> handed_out(set.size());
  std::vector<int> visits(set.size(), 0);
  visited.refine(candidates, x, x, [&](std::size_t i, const auto& runs) {
    ++visits[i];
    runs([&](const NeighborRun<3>& run) {
      for (int k = 0; k < run.count; ++k) handed_out[i].emplace_back(run.index[k], run.r2[k]);
    });
  });
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    ASSERT_EQ(visits[i], 1) << "particle " << i;
    const std::vector<ListedPair> walked = listed_by_runs(plain, i, x);
    ASSERT_EQ(handed_out[i], walked) << "particle " << i;
    ASSERT_EQ(listed_by_runs(visited, i, x), walked) << "particle " << i;
    pairs += walked.size();
  }
  EXPECT_GT(pairs, 10 * set.size());
}

INSTANTIATE_TEST_SUITE_P(Domains, RefinedList, testing::Bool(),
                         [](const testing::TestParamInfo<bool>& info) { return info.param ? "periodic" : "closed"; });

// Each listed pair's brute-force kernel gradient ∇W_ij = derivative_over_r(r) x_ij at the current
// positions, by source id, with x_ij the minimum image computed as brute_force does. The domain is
// longer than twice the support on every axis, so a pair has at most one image in the support.
template <int D>
std::vector<std::vector<std::pair<Index, Vector<D>>>> brute_force_gradients(const ParticleSet<D>& queries,
                                                                            const ParticleSet<D>& sources,
                                                                            const GridDomain<D>& domain,
                                                                            const CubicSplineKernel<D>& kernel) {
  const auto qx = queries[queries.position()];
  const auto sx = sources[sources.position()];
  const auto query_ids = queries[queries.id()];
  const auto source_ids = sources[sources.id()];
  const auto shifts = image_shifts(domain);
  std::vector<std::vector<std::pair<Index, Vector<D>>>> gradients(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    for (std::size_t j = 0; j < sources.size(); ++j) {
      for (const Vector<D>& shift : shifts) {
        const Vector<D> image = qx[i] - shift;
        Vector<D> xij;
        for (int d = 0; d < D; ++d) xij[d] = image[d] - sx.component[d][j];
        const Real r2 = squared_norm<D>(xij);
        if (r2 < support * support)
          gradients[query_ids[i]].emplace_back(source_ids[j], kernel.derivative_over_r(std::sqrt(r2)) * xij);
      }
    }
    std::sort(gradients[query_ids[i]].begin(), gradients[query_ids[i]].end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
  }
  return gradients;
}

// The gradients a list's runs hand out after cache_gradients, by query id and source id, with
// the runs walked for gradients only (no positions); `most` is set to the most neighbours of one
// query.
template <int D>
void expect_cached_gradients_are_brute_force(const NeighborList<D>& list, const ParticleSet<D>& queries,
                                             const ParticleSet<D>& sources, const GridDomain<D>& domain,
                                             const CubicSplineKernel<D>& kernel, std::size_t& most) {
  const auto expected = brute_force_gradients<D>(queries, sources, domain, kernel);
  const auto qx = queries[queries.position()];
  const auto sx = sources[sources.position()];
  const auto query_ids = queries[queries.id()];
  const auto source_ids = sources[sources.id()];
  most = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    std::vector<std::pair<Index, Vector<D>>> cached;
    list.template for_each_run<false>(i, qx, sx, [&](const NeighborRun<D>& run) {
      for (int d = 0; d < D; ++d) ASSERT_NE(run.gradient[d], nullptr);
      for (int k = 0; k < run.count; ++k) {
        Vector<D> gradient;
        for (int d = 0; d < D; ++d) gradient[d] = run.gradient[d][k];
        cached.emplace_back(source_ids[run.index[k]], gradient);
      }
    });
    std::sort(cached.begin(), cached.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const auto& mine = expected[query_ids[i]];
    ASSERT_EQ(cached.size(), mine.size()) << "query id " << query_ids[i];
    for (std::size_t k = 0; k < cached.size(); ++k) {
      ASSERT_EQ(cached[k].first, mine[k].first) << "query id " << query_ids[i];
      // The same operations on the same x_ij: the same numbers.
      EXPECT_EQ(cached[k].second, mine[k].second) << "query id " << query_ids[i] << ", source id " << mine[k].first;
    }
    most = std::max(most, cached.size());
  }
}

// cache_gradients keeps every pair's brute-force kernel gradient, in runs longer and shorter than
// one NeighborRun, for a list built without a skin, for one refined after moves and for a list
// between two sets; a refine drops the cache, after which a gradients-only walk still hands out
// offsets.
class CachedGradients : public testing::TestWithParam<bool> {};

TEST_P(CachedGradients, AreTheBruteForceKernelGradients) {
  const GridDomain<3> domain = test_domain<3>(GetParam());
  const CubicSplineKernel<3> kernel(support / CubicSplineKernel<3>::support_factor);
  const auto derivative_over_r = [&](Real r) { return kernel.derivative_over_r(r); };
  std::size_t most = 0;

  NeighborGrid<3> grid(domain, support);
  ParticleSet<3> set = particles_at(make_cloud<3>(Cloud::clustered, domain, grid.cell_size()));
  ASSERT_EQ(grid.update(set), 0u);
  const auto x = std::as_const(set)[set.position()];
  NeighborList<3> built;
  built.build(grid, x, grid.own_neighbors(), x);
  built.cache_gradients(x, x, derivative_over_r);
  expect_cached_gradients_are_brute_force<3>(built, set, set, domain, kernel, most);
  EXPECT_GT(most, std::size_t(NeighborRun<3>::capacity));

  NeighborGrid<3> source_grid(domain, support);
  ParticleSet<3> sources = particles_at(make_cloud<3>(Cloud::uniform, domain, source_grid.cell_size()));
  ASSERT_EQ(source_grid.update(sources), 0u);
  CrossNeighbors<3> table;
  table.build(grid, source_grid);
  const auto source_x = std::as_const(sources)[sources.position()];
  NeighborList<3> cross;
  cross.build(grid, x, table, source_x);
  cross.cache_gradients(x, source_x, derivative_over_r);
  expect_cached_gradients_are_brute_force<3>(cross, set, sources, domain, kernel, most);
  EXPECT_GT(most, 0u);

  const Real skin = Real(0.3) * support;
  NeighborGrid<3> skin_grid(domain, support, SortAlgorithm::radix, CellLookup::automatic, skin);
  ASSERT_EQ(skin_grid.update(set), 0u);
  const auto skin_x = std::as_const(set)[set.position()];
  NeighborList<3> candidates;
  candidates.build(skin_grid, skin_x, skin_grid.own_neighbors(), skin_x);
  NeighborList<3> refined;
  refined.refine(candidates, skin_x, skin_x);
  refined.cache_gradients(skin_x, skin_x, derivative_over_r);
  move_by_up_to(set, skin / 2, 11);
  refined.refine(candidates, skin_x, skin_x);
  refined.for_each_run<false>(0, skin_x, skin_x, [&](const NeighborRun<3>& run) {
    EXPECT_EQ(run.gradient[0], nullptr) << "a refine drops the cache";
    for (int k = 0; k < run.count; ++k) {
      Real r2 = 0;
      for (int d = 0; d < 3; ++d) r2 += run.x_ij[d][k] * run.x_ij[d][k];
      EXPECT_EQ(run.r2[k], r2);
    }
  });
  refined.cache_gradients(skin_x, skin_x, derivative_over_r);
  expect_cached_gradients_are_brute_force<3>(refined, set, set, domain, kernel, most);
}

INSTANTIATE_TEST_SUITE_P(Domains, CachedGradients, testing::Bool(),
                         [](const testing::TestParamInfo<bool>& info) { return info.param ? "periodic" : "closed"; });

// A contact of wall particles at the given places (position, mass, density, pressure).
Contact<3>& add_walls(Interactions<3>& interactions, const std::vector<Vector<3>>& places, ContactMotion motion,
                      const char* name = "walls") {
  ParticleSet<3> walls = particles_at(places);
  const WallFields<3> fields{walls.position(),
                             std::nullopt,
                             walls.add_scalar("mass"),
                             walls.add_scalar("density"),
                             walls.add_scalar("pressure"),
                             std::nullopt,
                             std::nullopt};
  return interactions.add_contact(name, ContactRole::wall, motion, std::move(walls), fields);
}

// Interactions with a skin keeps its sort and candidates while every particle has moved less
// than half the skin, rebuilds when one has moved farther or left the domain, and the fluid's
// lists are the brute-force neighbours at every update.
TEST(Interactions, RebuildsOnlyWhenAParticleOutrunsHalfTheSkin) {
  const GridDomain<3> domain = test_domain<3>(false);
  const Real skin = Real(0.3) * support;
  Interactions<3> neighbors(domain, support, skin);
  const Contact<3>& contact = add_walls(
      neighbors, make_cloud<3>(Cloud::sheet, domain, neighbors.fluid_grid().cell_size()), ContactMotion::fixed);
  const ParticleSet<3>& walls = contact.particles();
  std::vector<Vector<3>> inner;
  for (const Vector<3>& p : make_cloud<3>(Cloud::uniform, domain, neighbors.fluid_grid().cell_size())) {
    bool away_from_sides = true;
    for (int d = 0; d < 3; ++d) away_from_sides = away_from_sides && p[d] > skin && p[d] < domain.upper[d] - skin;
    if (away_from_sides) inner.push_back(p);
  }
  ParticleSet<3> fluid = particles_at(inner);
  const auto expect_brute_force = [&](const char* when) {
    const auto x = std::as_const(fluid)[fluid.position()];
    const auto ids = std::as_const(fluid)[fluid.id()];
    const auto wall_ids = std::as_const(walls)[walls.id()];
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      std::vector<Index> found;
      neighbors.for_each_fluid_neighbor(i, x, [&](Index j, const Vector<3>&, Real) { found.push_back(ids[j]); });
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, brute_force<3>(x[i], fluid, domain)) << when << ", fluid id " << ids[i];
      found.clear();
      contact.for_each_neighbor(i, x, [&](Index b, const Vector<3>&, Real) { found.push_back(wall_ids[b]); });
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, brute_force<3>(x[i], walls, domain)) << when << ", fluid id " << ids[i] << " to walls";
    }
  };

  EXPECT_EQ(neighbors.update(fluid), 0u);
  EXPECT_EQ(neighbors.builds(), 1u);
  expect_brute_force("first build");
  move_by_up_to(fluid, skin / 4, 1);
  move_by_up_to(fluid, skin / 4, 2);  // at most half the skin in all
  EXPECT_EQ(neighbors.update(fluid), 0u);
  EXPECT_EQ(neighbors.builds(), 1u) << "every particle within half the skin of where it was sorted";
  expect_brute_force("after moves of up to half the skin");

  auto x = fluid[fluid.position()];
  x.set(0, x[0] + Vector<3>(x[0][0] < Real(0.5) ? skin : -skin, 0, 0));
  EXPECT_EQ(neighbors.update(fluid), 0u);
  EXPECT_EQ(neighbors.builds(), 2u) << "one particle beyond half the skin";
  expect_brute_force("after one particle moved a skin");

  x.set(0, Vector<3>(-1, 0.5, 0.5));
  EXPECT_EQ(neighbors.update(fluid), 1u);
  EXPECT_EQ(neighbors.builds(), 3u) << "one particle outside the domain";
  expect_brute_force("after one particle left");
}

// A moving contact is re-sorted with the fluid: its particles' moves count against the skin as
// the fluid's do, and its lists in both directions are the brute-force ones at every update.
TEST(Interactions, RebuildsWhenAMovingContactOutrunsHalfTheSkin) {
  const GridDomain<3> domain = test_domain<3>(false);
  const Real skin = Real(0.3) * support;
  Interactions<3> neighbors(domain, support, skin);
  std::vector<Vector<3>> inner;
  for (const Vector<3>& p : make_cloud<3>(Cloud::clustered, domain, neighbors.fluid_grid().cell_size())) {
    bool away_from_sides = true;
    for (int d = 0; d < 3; ++d) away_from_sides = away_from_sides && p[d] > skin && p[d] < domain.upper[d] - skin;
    if (away_from_sides) inner.push_back(p);
  }
  Contact<3>& body = add_walls(neighbors, inner, ContactMotion::moving, "body");
  ParticleSet<3> fluid = particles_at(make_cloud<3>(Cloud::uniform, domain, neighbors.fluid_grid().cell_size()));
  const auto expect_brute_force = [&](const char* when) {
    const ParticleSet<3>& moving = body.particles();
    const auto x = std::as_const(fluid)[fluid.position()];
    const auto body_x = moving[moving.position()];
    const auto ids = std::as_const(fluid)[fluid.id()];
    const auto body_ids = moving[moving.id()];
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      std::vector<Index> found;
      body.for_each_neighbor(i, x, [&](Index b, const Vector<3>&, Real) { found.push_back(body_ids[b]); });
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, brute_force<3>(x[i], moving, domain)) << when << ", fluid id " << ids[i];
    }
    for (std::size_t b = 0; b < moving.size(); ++b) {
      std::vector<Index> found;
      body.for_each_fluid_neighbor_of(b, x, [&](Index j, const Vector<3>&, Real) { found.push_back(ids[j]); });
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, brute_force<3>(body_x[b], fluid, domain)) << when << ", body id " << body_ids[b];
    }
  };
  EXPECT_EQ(neighbors.update(fluid), 0u);
  expect_brute_force("first build");
  move_by_up_to(body.particles(), skin / 4, 3);
  move_by_up_to(body.particles(), skin / 4, 4);
  neighbors.update(fluid);
  EXPECT_EQ(neighbors.builds(), 1u) << "every body particle within half the skin of where it was sorted";
  expect_brute_force("after body moves of up to half the skin");
  auto body_x = body.particles()[body.particles().position()];
  body_x.set(0, body_x[0] + Vector<3>(body_x[0][0] < Real(0.5) ? skin : -skin, 0, 0));
  neighbors.update(fluid);
  EXPECT_EQ(neighbors.builds(), 2u) << "one body particle beyond half the skin";
  expect_brute_force("after one body particle moved a skin");
}

// An update that leaves the listing to the next pair walk hands out, in that walk, the pairs and
// r² an update that lists at once hands out (bitwise), fluid before each contact in order for
// every particle, and leaves the same lists for the walks after it.
TEST(Interactions, ListingInThePairWalkHandsOutWhatListingAtOnceDoes) {
  const GridDomain<3> domain = test_domain<3>(false);
  const Real skin = Real(0.3) * support;
  using Listing = Interactions<3>::Listing;
  Interactions<3> at_once(domain, support, skin);
  Interactions<3> in_walk(domain, support, skin);
  const auto sheet = make_cloud<3>(Cloud::sheet, domain, at_once.fluid_grid().cell_size());
  const auto obstacle = make_cloud<3>(Cloud::clustered, domain, at_once.fluid_grid().cell_size());
  for (Interactions<3>* interactions : {&at_once, &in_walk}) {
    add_walls(*interactions, sheet, ContactMotion::fixed);
    add_walls(*interactions, obstacle, ContactMotion::fixed, "obstacle");
  }
  ParticleSet<3> fluid = particles_at(make_cloud<3>(Cloud::clustered, domain, at_once.fluid_grid().cell_size()));
  ParticleSet<3> fluid_copy = fluid;
  // Per particle: its fluid pairs, then each contact's pairs, each list ended by a marker.
  const auto walk = [&](Interactions<3>& neighbors, const ParticleSet<3>& set) {
    std::vector<std::vector<ListedPair>> walked(set.size());
    const auto collect = [&](std::size_t i, const auto& runs) {
      runs([&](const NeighborRun<3>& run) {
        for (int k = 0; k < run.count; ++k) walked[i].emplace_back(run.index[k], run.r2[k]);
      });
      walked[i].emplace_back(Index(-1), Real(-1));
    };
    neighbors.walk_fluid_pairs(set[set.position()], collect,
                               [&](std::size_t i, std::size_t, const auto& runs) { collect(i, runs); });
    return walked;
  };
  for (int update = 0; update < 3; ++update) {
    ASSERT_EQ(at_once.update(fluid, Listing::now), in_walk.update(fluid_copy, Listing::in_next_pair_walk));
    EXPECT_FALSE(at_once.listing_pending());
    EXPECT_TRUE(in_walk.listing_pending());
    const auto expected = walk(at_once, fluid);
    EXPECT_EQ(walk(in_walk, fluid_copy), expected) << "update " << update;
    EXPECT_FALSE(in_walk.listing_pending());
    EXPECT_EQ(walk(in_walk, fluid_copy), expected) << "update " << update << ", a second walk";
    move_by_up_to(fluid, skin / 4, 11 + update);
    move_by_up_to(fluid_copy, skin / 4, 11 + update);
  }
  EXPECT_EQ(in_walk.builds(), at_once.builds());
}

TEST(NeighborGrid, RejectsBadGeometry) {
  GridDomain<3> domain;
  EXPECT_THROW(NeighborGrid<3>(domain, 0), std::invalid_argument);
  EXPECT_THROW(NeighborGrid<3>(domain, Real(0.1), SortAlgorithm::radix, CellLookup::automatic, -1),
               std::invalid_argument);
  domain.periodic = {true, false, false};
  EXPECT_THROW(NeighborGrid<3>(domain, Real(0.4)), std::invalid_argument);  // fewer than 3 periodic cells
  domain.upper[1] = -1;
  EXPECT_THROW(NeighborGrid<3>(domain, Real(0.1)), std::invalid_argument);
}

TEST(Morton, InterleavesBitsAndDecodes) {
  std::mt19937 random(3);
  for (int k = 0; k < 1000; ++k) {
    const std::uint32_t x = random(), y = random();
    std::uint64_t expected = 0;
    for (int b = 0; b < 32; ++b)
      expected |= (std::uint64_t((x >> b) & 1) << (2 * b)) | (std::uint64_t((y >> b) & 1) << (2 * b + 1));
    EXPECT_EQ(morton_code<2>({x, y}), expected);
    EXPECT_EQ(morton_decode<2>(expected), (std::array<std::uint32_t, 2>{x, y}));
    const std::uint32_t a = random() & 0x1fffff, b3 = random() & 0x1fffff, c = random() & 0x1fffff;
    std::uint64_t expected3 = 0;
    for (int b = 0; b < 21; ++b)
      expected3 |= (std::uint64_t((a >> b) & 1) << (3 * b)) | (std::uint64_t((b3 >> b) & 1) << (3 * b + 1)) |
                   (std::uint64_t((c >> b) & 1) << (3 * b + 2));
    EXPECT_EQ(morton_code<3>({a, b3, c}), expected3);
    EXPECT_EQ(morton_decode<3>(expected3), (std::array<std::uint32_t, 3>{a, b3, c}));
  }
}

TEST(PairSort, RadixAndComparisonGiveTheSameUniqueOrder) {
  std::mt19937_64 random(11);
  std::vector<std::uint64_t> codes(200'000);
  for (auto& code : codes) code = random() % 5000 + (random() % 2 ? (std::uint64_t(1) << 40) : 0);
  const std::size_t n = codes.size();
  std::vector<std::uint64_t> radix_keys = codes, comparison_keys = codes, radix_key_scratch(n),
                             comparison_key_scratch(n);
  std::vector<Index> radix_order(n), comparison_order(n), radix_order_scratch(n), comparison_order_scratch(n);
  PairSortWorkspace radix{radix_keys, radix_order, radix_key_scratch, radix_order_scratch, {}};
  PairSortWorkspace comparison{comparison_keys, comparison_order, comparison_key_scratch, comparison_order_scratch, {}};
  sort_pairs(SortAlgorithm::radix, radix);
  sort_pairs(SortAlgorithm::comparison, comparison);
  EXPECT_TRUE(std::ranges::equal(radix.order, comparison.order));
  EXPECT_TRUE(std::ranges::equal(radix.keys, comparison.keys));
  for (std::size_t k = 1; k < codes.size(); ++k) {
    ASSERT_LE(radix.keys[k - 1], radix.keys[k]);
    if (radix.keys[k - 1] == radix.keys[k]) {
      ASSERT_LT(radix.order[k - 1], radix.order[k]);
    }
    ASSERT_EQ(radix.keys[k], codes[radix.order[k]]);
  }
}

}  // namespace
}  // namespace tide
