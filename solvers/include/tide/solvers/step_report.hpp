#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "tide/solvers/time_step.hpp"

namespace tide {

/// How one implicit pressure solve ended.
struct SolveReport {
  int iterations = 0;  // pressure updates made
  int sweeps = 0;      // evaluations of the pressure's velocity and density error: the solve's cost
  double error = 0;    // the mean density error it left, as a share of ρ0 (see IncompressibleSph::solve)
  bool converged = false;
};

/// Iterations and final errors of a stretch of solves of one kind.
struct SolveTally {
  std::size_t solves = 0;
  std::size_t missed = 0;  // solves that ended at the iteration cap above their threshold
  std::uint64_t iterations = 0;
  int max_iterations = 0;
  double error_sum = 0;
  double max_error = 0;

  void add(const SolveReport& report) {
    ++solves;
    missed += report.converged ? 0 : 1;
    iterations += static_cast<std::uint64_t>(report.iterations);
    max_iterations = std::max(max_iterations, report.iterations);
    error_sum += report.error;
    max_error = std::max(max_error, report.error);
  }
  double mean_iterations() const { return solves ? static_cast<double>(iterations) / static_cast<double>(solves) : 0; }
  double mean_error() const { return solves ? error_sum / static_cast<double>(solves) : 0; }
};

/// What one step did.
struct StepReport {
  TimeStep time_step;
  std::size_t removed = 0;                      // particles that left the domain in this step
  std::optional<SolveReport> density_solve;     // incompressible schemes
  std::optional<SolveReport> divergence_solve;  // DFSPH
};

}  // namespace tide
