#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>

namespace tide::app {

/// Shows how far a run is: a one-line bar redrawn in place on a terminal, or a plain log line
/// every few seconds when the output is a file or a pipe.
class Progress {
 public:
  /// `from_time` and `from_step`: where this process takes the run over (a resume's checkpoint;
  /// the start otherwise), from which the ETA and the rate count.
  Progress(std::ostream& out, bool terminal, bool quiet, double start_time, double end_time, std::size_t particles,
           double from_time, std::uint64_t from_step);

  void update(double time, std::uint64_t steps, bool force = false);
  void finish(double time, std::uint64_t steps);
  double wall_seconds() const;

 private:
  std::ostream& out_;
  bool terminal_;
  bool quiet_;
  double start_time_;
  double end_time_;
  std::size_t particles_;
  double from_time_;
  std::uint64_t from_step_;
  std::chrono::steady_clock::time_point wall_start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace tide::app
