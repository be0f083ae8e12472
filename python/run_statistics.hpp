#pragma once

// What the steps a Python script takes did: their count, wall time, binding time-step limits and
// pressure solves, for tidesph.Simulation.statistics.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "tide/solvers/step_report.hpp"
#include "tide/solvers/time_step.hpp"

namespace tide::python {

struct RunStatistics {
  std::uint64_t steps = 0;
  double particle_steps = 0;
  double wall_seconds = 0;  // spent in the steps
  TimeStepTally limits;
  SolveTally density_solves;
  SolveTally divergence_solves;
  std::optional<StepReport> last;

  void add(const StepReport& report, std::size_t particles, double seconds) {
    ++steps;
    particle_steps += static_cast<double>(particles);
    wall_seconds += seconds;
    limits.add(report.time_step.limit);
    if (report.density_solve) density_solves.add(*report.density_solve);
    if (report.divergence_solve) divergence_solves.add(*report.divergence_solve);
    last = report;
  }
};

}  // namespace tide::python
