// Crowd scenes the reader, the capability check or the crowd scheme refuses (issue 36: no exit,
// an unreachable goal, agents inside walls, negative counts), each at its key path; the
// crush-risk flag; the navigation field and the agents' desired speeds.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "tide/core/log.hpp"
#include "tide/core/scene_error.hpp"
#include "tide/solvers/agent_placement.hpp"
#include "tide/solvers/crowd_sph.hpp"
#include "tide/solvers/navigation_field.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/validation/crowd_scenes.hpp"

namespace tide {
namespace {

// The key path of the SceneError that reading `json` and building its simulation throws.
std::string refusal_path(const std::string& json, int dimension = 2) {
  try {
    const scene::Scene scene = io::parse_scene(json, "crowd.json");
    if (dimension == 2) {
      make_simulation<2>(scene);
    } else {
      make_simulation<3>(scene);
    }
  } catch (const scene::SceneError& error) {
    return error.key_path();
  }
  return "(accepted)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(CrowdScene, TheTestRoomIsAccepted) { EXPECT_EQ(refusal_path(validation::crowd_room_json({})), "(accepted)"); }

TEST(CrowdScene, NoExitIsRefused) {
  const std::string json = validation::crowd_room_json({});
  const std::size_t from = json.find(R"("exits": [)") + 10;
  const std::size_t to = json.find(R"(, "desired_speed")") - 1;
  EXPECT_EQ(refusal_path(std::string(json).replace(from, to - from, "")), "/crowd/exits");
}

TEST(CrowdScene, NegativeAndZeroCountsAreRefused) {
  for (const char* count : {"-3", "0", "2.5"}) {
    validation::CrowdRoom room;
    room.agents = std::string(R"([{"region": {"min": [1, 1], "max": [5, 5]}, "count": )") + count + "}]";
    EXPECT_EQ(refusal_path(validation::crowd_room_json(room)), "/crowd/agents/0/count") << count;
  }
}

TEST(CrowdScene, MoreAgentsThanFitTheRegionAreRefused) {
  validation::CrowdRoom room;
  room.agents = R"([{"region": {"min": [1, 1], "max": [3, 3]}, "count": 17}])";  // 4 m²: 16 at 0.5 m
  EXPECT_EQ(
      refusal_path(replaced(validation::crowd_room_json(room), R"("crowd": {)", R"("crowd": {"body_radius": 0.25, )")),
      "/crowd/agents/0/count");
}

TEST(CrowdScene, AgentsInsideAWallAreRefused) {
  validation::CrowdRoom room;
  // The second group's first agent stands well within crowd.body_radius of the wall face x = 0, not
  // on the edge of the blocked cells, where the precision's rounding would decide.
  room.agents = R"([{"region": {"min": [1, 1], "max": [5, 5]}, "count": 4},
                    {"region": {"min": [-0.4, 1], "max": [0.6, 3]}, "count": 2}])";
  EXPECT_EQ(refusal_path(validation::crowd_room_json(room)), "/crowd/agents/1");
}

TEST(CrowdScene, AnUnreachableExitIsRefused) {
  validation::CrowdRoom room;
  room.door = 0.3;  // narrower than a body (2 × 0.2 m): the room is closed to its agents
  EXPECT_EQ(refusal_path(validation::crowd_room_json(room)), "/crowd/agents/0");
}

TEST(CrowdScene, AnExitInsideAWallIsRefused) {
  const std::string json =
      replaced(validation::crowd_room_json({}), R"("region": {"min": [12.3, 1.4], "max": [13.8, 4.6]})",
               R"("region": {"min": [-0.3, 2], "max": [0, 3]})");
  EXPECT_EQ(refusal_path(json), "/crowd/exits/0");
}

TEST(CrowdScene, FluidKeysAndOtherSchemesAreRefused) {
  const std::string json = validation::crowd_room_json({});
  EXPECT_EQ(
      refusal_path(replaced(json, R"("crowd": {)", R"("materials": [{"name": "water", "max_speed": 1}], "crowd": {)")),
      "/materials");
  EXPECT_EQ(refusal_path(replaced(json, R"("scheme": "crowd")", R"("scheme": "wcsph")")), "/solver/scheme");
}

// A corridor's walkers follow a heading and need no exit; a group without one does.
TEST(CrowdScene, ExitsMayBeLeftOutOnlyWhenEveryGroupHasAHeading) {
  const std::string json = validation::crowd_room_json({});
  const std::size_t from = json.find(R"(, "exits": [)");
  const std::size_t to = json.find(R"(, "desired_speed")");
  const std::string no_exits = std::string(json).replace(from, to - from, "");
  EXPECT_EQ(refusal_path(no_exits), "/crowd/exits");
  const std::string headed = replaced(no_exits, R"("count": 20})", R"("count": 20, "heading": [1, 0]})");
  EXPECT_EQ(refusal_path(headed), "(accepted)");
  EXPECT_EQ(refusal_path(replaced(headed, R"("heading": [1, 0])", R"("heading": [0, 0])")), "/crowd/agents/0/heading");
}

TEST(CrowdScene, ThreeDimensionsAreRefused) {
  const std::string json = R"({"dimension": 3, "particle_spacing": 0.1,
    "crowd": {"agents": [{"region": {"min": [1, 1, 0], "max": [2, 2, 1]}, "count": 1}],
              "exits": [{"name": "door", "region": {"min": [3, 0, 0], "max": [4, 4, 1]}}]},
    "domain": {"min": [0, 0, 0], "max": [4, 4, 1]}, "solver": {"scheme": "crowd"}, "time": {"end": 1}})";
  EXPECT_EQ(refusal_path(json, 3), "/dimension");
}

// 36 agents of body radius 0.2 m packed 0.4 m apart (6.25 persons/m² on the lattice): the peak
// density passes 5 persons/m² at the start, where the crowd stands, and is flagged once (the
// crowd then spreads out).
TEST(CrowdPeak, ADensityAboveFiveIsFlaggedOnceWithWhereAndWhen) {
  validation::CrowdRoom room;
  room.agents = R"([{"region": {"min": [2, 2], "max": [4.4, 4.4]}, "count": 36}])";
  std::string json = validation::crowd_room_json(room);
  json = replaced(json, R"("crowd": {)", R"("crowd": {"body_radius": 0.2, )");
  std::vector<std::string> warnings;
  const LogSink previous = set_log_sink([&](LogLevel level, std::string_view message) {
    if (level == LogLevel::warning) warnings.emplace_back(message);
  });
  CrowdSph crowd(io::parse_scene(json, "packed"));
  for (int k = 0; k < 20; ++k) crowd.step();
  set_log_sink(previous);
  const CrowdPeak& peak = crowd.peak();
  // Measured: 6.336, the kernel sum over the 6.25 persons/m² lattice.
  EXPECT_GT(peak.density, crush_density) << peak.density;
  EXPECT_EQ(peak.time, 0);
  EXPECT_GE(peak.position[0], 2);
  EXPECT_LE(peak.position[0], 4.4);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_NE(warnings[0].find("a crush risk"), std::string::npos) << warnings[0];
}

// Fast marching in an open 4 m × 4 m square toward its left column: the distance grows by one
// cell per cell along x, and the direction is −x.
TEST(NavigationField, OpenSquareLeadsStraightToItsExit) {
  NavigationField::Grid grid;
  grid.cell = 0.1;
  grid.cells = {40, 40};
  std::vector<bool> blocked(1600, false), goal(1600, false);
  for (std::size_t y = 0; y < 40; ++y) goal[y * 40] = true;
  const NavigationField field(grid, blocked, goal);
  for (const double x : {0.55, 1.55, 3.05}) {
    // The exit is the column of cells centred at x = 0.05: a plane front, exact to rounding.
    EXPECT_NEAR(field.distance(Vector<2>(Real(x), Real(2.0))), x - 0.05, 1e-9);
    const Vector<2> e = field.direction(Vector<2>(Real(x), Real(2.03)));
    EXPECT_NEAR(e[0], -1, 1e-6);
    EXPECT_NEAR(e[1], 0, 1e-6);
  }
}

// A point goal: the first-order fast marching distance along a diagonal is longer than the
// Euclidean one by a few per cent (Sethian 1996), and the direction points at the goal.
TEST(NavigationField, PointGoalIsFoundAlongTheDiagonal) {
  NavigationField::Grid grid;
  grid.cell = 0.1;
  grid.cells = {41, 41};
  std::vector<bool> blocked(41 * 41, false), goal(41 * 41, false);
  goal[20 * 41 + 20] = true;  // the centre cell, at (2.05, 2.05)
  const NavigationField field(grid, blocked, goal);
  const double diagonal = std::hypot(1.5, 1.5);
  const double distance = field.distance(Vector<2>(Real(3.55), Real(3.55)));
  // Measured: 2.2152 against 2.1213 (+4.4%), the first-order scheme's diagonal error; bound 5%.
  EXPECT_NEAR(distance / diagonal, 1, 0.05);
  const Vector<2> e = field.direction(Vector<2>(Real(3.55), Real(3.55)));
  EXPECT_NEAR(e[0], -std::sqrt(Real(0.5)), 1e-3);
  EXPECT_NEAR(e[1], -std::sqrt(Real(0.5)), 1e-3);
}

// Seeded draws: the same seed gives the same speeds; their mean and deviation are those asked
// for, within the sampling error of 20 000 draws (σ/√n = 0.0018 m/s for the mean).
TEST(AgentPlacement, DesiredSpeedsFollowTheirDistribution) {
  const scene::DesiredSpeed speed;  // 1.34 ± 0.26 m/s
  const std::vector<Real> a = desired_speeds(speed, 20'000), b = desired_speeds(speed, 20'000);
  EXPECT_EQ(a, b);
  const double mean = std::accumulate(a.begin(), a.end(), 0.0) / static_cast<double>(a.size());
  double square = 0;
  for (const Real v : a) square += (v - mean) * (v - mean);
  const double deviation = std::sqrt(square / static_cast<double>(a.size()));
  // Measured: 1.3372 (1.6 σ/√n below), bound 4 σ/√n.
  EXPECT_NEAR(mean, 1.34, 4 * 0.0018);
  // Truncation at three deviations narrows a normal distribution's deviation by 1.3% (0.2565);
  // measured 0.2553, within the sampling error σ/√(2n) = 0.0013; bound 4 of those.
  EXPECT_NEAR(deviation, 0.2565, 0.005);
  for (const Real v : a) EXPECT_LE(std::abs(v - 1.34), 3 * 0.26 + 1e-6);
}

// The closest two agents of `starts`, across the periodic x of a corridor `length` long, after
// checking that each stands inside `region`.
double closest_pair_inside(const AgentStarts& starts, const scene::Box& region, double length) {
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < starts.positions.size(); ++i) {
    const Vector<2> p = starts.positions[i];
    EXPECT_GE(p[0], region.min[0]) << i;
    EXPECT_LE(p[0], region.max[0]) << i;
    EXPECT_GE(p[1], region.min[1]) << i;
    EXPECT_LE(p[1], region.max[1]) << i;
    for (std::size_t j = 0; j < i; ++j) {
      Vector<2> d = p - starts.positions[j];
      d[0] -= static_cast<Real>(length * std::round(static_cast<double>(d[0]) / length));
      closest = std::min(closest, static_cast<double>(d.norm()));
    }
  }
  return closest;
}

// The placement tests below measure their geometry with bodies 0.5 m across (r = 0.25 m, the
// default before r = 0.2 m): the same code places bodies of any size.
scene::Scene with_body_radius(scene::Scene scene, double radius) {
  scene.crowd->body_radius = radius;
  return scene;
}

// 272 agents in the 20 m × 3.4 m band of a corridor, 3.4 persons/m² of it: more than a square
// lattice holds a body diameter apart (0.486 m), so a hexagonal one, 0.506 m apart, every
// agent inside the region and no two closer than a body diameter, across the periodic x too.
TEST(AgentPlacement, TooDenseForASquareLatticeStandsOnAHexagonalOne) {
  const scene::Scene corridor = with_body_radius(validation::crowd_corridor(272, 20, 4, 1), 0.25);
  const AgentStarts starts = place_agents(corridor);
  ASSERT_EQ(starts.positions.size(), 272U);
  // Measured: 0.50633 m, the spacing; bound: a body diameter.
  EXPECT_GE(closest_pair_inside(starts, corridor.crowd->agents[0].region, 20), 0.5 - 1e-6);
}

// Random placement (random sequential addition) of 160 agents, 2.35 persons/m² of the band:
// inside the region, no two closer than a body diameter across the periodic x, the same places
// from the same seed and other places from another, and spread evenly along the corridor.
TEST(AgentPlacement, RandomPlacementKeepsBodiesApartAndFollowsItsSeed) {
  scene::Scene corridor = with_body_radius(validation::crowd_corridor(160, 20, 4, 1, "random"), 0.25);
  const AgentStarts starts = place_agents(corridor);
  ASSERT_EQ(starts.positions.size(), 160U);
  EXPECT_GE(closest_pair_inside(starts, corridor.crowd->agents[0].region, 20), 0.5);
  EXPECT_EQ(place_agents(corridor).positions, starts.positions);
  corridor.crowd->desired_speed.seed = 2;
  EXPECT_NE(place_agents(corridor).positions, starts.positions);
  // Along the periodic x every place is alike: the mean of 160 uniform draws on [0, 20] m lies
  // within 3 standard errors (20/sqrt(12 · 160) = 0.456 m) of 10 m.
  double mean_x = 0;
  for (const Vector<2>& p : starts.positions) mean_x += static_cast<double>(p[0]) / 160;
  EXPECT_NEAR(mean_x, 10, 3 * 0.456);
}

// Two groups in the same band, one on the lattice and one at random, then another at random:
// every agent a body diameter or more from every other, whichever group it belongs to.
TEST(AgentPlacement, GroupsPlacedAtRandomKeepClearOfTheGroupsBeforeThem) {
  scene::Scene corridor = with_body_radius(validation::crowd_corridor(40, 20, 4, 1, "lattice"), 0.25);
  scene::AgentGroup second = corridor.crowd->agents[0];
  second.placement = scene::AgentPlacement::random;
  second.heading = scene::Vec{-1, 0, 0};
  corridor.crowd->agents.push_back(second);
  corridor.crowd->agents.push_back(second);
  const AgentStarts starts = place_agents(corridor);
  ASSERT_EQ(starts.positions.size(), 120U);
  EXPECT_GE(closest_pair_inside(starts, corridor.crowd->agents[0].region, 20), 0.5);
}

// 200 agents in that band, 2.9 persons/m² of it, past where random sequential addition jams:
// refused at the group's count, naming the lattice that holds them.
TEST(AgentPlacement, RandomPlacementTooDenseIsRefusedAtTheCount) {
  const scene::Scene corridor = with_body_radius(validation::crowd_corridor(200, 20, 4, 1, "random"), 0.25);
  try {
    place_agents(corridor);
    FAIL() << "200 agents placed at random";
  } catch (const scene::SceneError& error) {
    EXPECT_EQ(error.key_path(), "/crowd/agents/0/count");
    EXPECT_NE(std::string(error.what()).find("lattice"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace tide
