#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "tide/core/types.hpp"
#include "tide/solvers/step_report.hpp"

namespace tide {

/// What the stages of one step share: its time step and the report the step returns.
struct StepContext {
  Real dt = 0;
  StepReport report;
};

/// One stage of a scheme's step: the name the reports give it and what it runs. A stage may hold
/// a loop (a pressure solve with its sweeps); passes that run in one walk, and so cannot be timed
/// apart, are one stage whose name joins theirs with '+' ("neighbor_search+density_summation").
struct Stage {
  std::string name;
  std::function<void(StepContext&)> run;
};

/// A stage's name and the wall-clock seconds of all its runs.
struct StageTime {
  std::string_view name;
  double seconds = 0;
};

/// The ordered stages of a scheme's step, built once from what the scene uses, so a stage the
/// scene does not need is not in the list and costs nothing. run() is the step: it runs every
/// stage in order and adds each one's wall time; the reports (Simulation::pipeline(), the run
/// summary, the benchmarks) read the same list.
class Pipeline {
 public:
  Pipeline() = default;
  /// Throws std::invalid_argument when two stages share a name: the reports tell them apart by it.
  explicit Pipeline(std::vector<Stage> stages);

  /// Runs the stages in order. A stage that throws ends the run, its time not added.
  void run(StepContext& context);

  std::vector<std::string_view> names() const;
  bool contains(std::string_view name) const;
  /// The seconds of the stage `name`, summed over its runs; 0 for a stage not in the list.
  double seconds(std::string_view name) const;
  /// Every stage with its seconds, in the order they run.
  std::vector<StageTime> times() const;

 private:
  std::vector<Stage> stages_;
  std::vector<double> seconds_;
};

}  // namespace tide
