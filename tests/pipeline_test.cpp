// The step is its pipeline: the stages run in order and are timed one by one, the shares of the
// run summary add to 100% and name every stage, and a stage the scene does not use is not in
// the list and costs nothing.

#include "tide/solvers/pipeline.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <numeric>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "small_scenes.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/solvers/stage_shares.hpp"

namespace tide {
namespace {

// Waits (busy) until `seconds` of wall time have passed.
void spin_for(double seconds) {
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds) {
  }
}

int sum(const std::vector<int>& values) { return std::accumulate(values.begin(), values.end(), 0); }

TEST(Pipeline, RunsItsStagesInOrderAndTimesEach) {
  std::vector<std::string> ran;
  const auto slow = [&](StepContext& context) {
    ran.push_back("slow");
    context.report.removed = 3;
    spin_for(2e-3);
  };
  Pipeline pipeline({{"first", [&](StepContext&) { ran.push_back("first"); }}, {"slow", slow}});
  StepContext context;
  pipeline.run(context);
  pipeline.run(context);
  EXPECT_EQ(ran, (std::vector<std::string>{"first", "slow", "first", "slow"}));
  EXPECT_EQ(context.report.removed, 3u);
  EXPECT_EQ(pipeline.names(), (std::vector<std::string_view>{"first", "slow"}));
  EXPECT_GE(pipeline.seconds("slow"), 4e-3);
  EXPECT_LT(pipeline.seconds("first"), pipeline.seconds("slow"));
  EXPECT_FALSE(pipeline.contains("absent"));
  EXPECT_EQ(pipeline.seconds("absent"), 0);
  const std::vector<StageTime> times = pipeline.times();
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[1].name, "slow");
  EXPECT_EQ(times[1].seconds, pipeline.seconds("slow"));
}

TEST(Pipeline, RefusesTwoStagesOfOneName) {
  EXPECT_THROW(Pipeline({{"check", [](StepContext&) {}}, {"check", [](StepContext&) {}}}), std::invalid_argument);
}

// Three equal stages: 333.3‰ each, the tenth left over to the first.
TEST(StageShares, AddToExactlyAHundredPercent) {
  EXPECT_EQ(stage_shares_permille({{"a", 1}, {"b", 1}, {"c", 1}}), (std::vector<int>{334, 333, 333}));
  const std::vector<int> skewed = stage_shares_permille({{"a", 0.12345}, {"b", 7.0}, {"c", 1e-9}, {"d", 0.5}});
  EXPECT_EQ(sum(skewed), 1000);
  EXPECT_EQ(format_stage_shares({{"a", 1}, {"b", 3}}), "a 25.0%, b 75.0%");
  EXPECT_EQ(stage_shares_permille({{"a", 0}, {"b", 0}}), (std::vector<int>{0, 0}));
}

// After a few steps of the small dam break, the pipeline's stages are the summary's: every
// stage is named in the shares, and the shares add to 100%.
TEST(StepPipeline, SummaryNamesEveryStageThatRanAndAddsToAHundredPercent) {
  for (const scene::Scheme scheme : {scene::Scheme::wcsph, scene::Scheme::dfsph, scene::Scheme::iisph}) {
    scene::Scene s = small_dam_break_2d();
    s.solver.scheme = scheme;
    const auto simulation = make_simulation<2>(s);
    for (int step = 0; step < 5; ++step) simulation->step();
    const std::vector<StageTime> times = simulation->pipeline().times();
    const std::string summary = format_stage_shares(times);
    for (const StageTime& stage : times)
      EXPECT_NE(summary.find(std::string(stage.name) + " "), std::string::npos) << summary;
    EXPECT_EQ(sum(stage_shares_permille(times)), 1000) << summary;
  }
}

// Shifting off: no shifting stage, and none of the step's time is charged to it; on: the stage
// is in the list, which is otherwise the same, and takes time.
TEST(StepPipeline, ASkippedStageIsAbsentAndCostsNothing) {
  for (const scene::Scheme scheme : {scene::Scheme::wcsph, scene::Scheme::dfsph}) {
    scene::Scene s = small_dam_break_2d();
    s.solver.scheme = scheme;
    const auto plain = make_simulation<2>(s);
    s.solver.shifting = scene::Shifting::fickian;
    const auto shifted = make_simulation<2>(s);
    for (int step = 0; step < 3; ++step) {
      plain->step();
      shifted->step();
    }
    EXPECT_FALSE(plain->pipeline().contains("particle_shifting"));
    EXPECT_EQ(plain->pipeline().seconds("particle_shifting"), 0);
    EXPECT_EQ(format_stage_shares(plain->pipeline().times()).find("shifting"), std::string::npos);
    EXPECT_TRUE(shifted->pipeline().contains("particle_shifting"));
    EXPECT_GT(shifted->pipeline().seconds("particle_shifting"), 0);
    std::vector<std::string_view> names = shifted->pipeline().names();
    std::erase(names, "particle_shifting");
    EXPECT_EQ(names, plain->pipeline().names());
  }
}

}  // namespace
}  // namespace tide
