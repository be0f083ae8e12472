#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "tide/core/types.hpp"

namespace tide {

/// Thrown when a run leaves the range where its results mean anything: a non-finite value, a
/// density beyond the scene's band (solver.max_density_ratio), or a particle faster than
/// solver.max_mach_number times the speed of sound.
class InstabilityError : public std::runtime_error {
 public:
  /// `note`, when not empty, follows the diagnosis as a sentence of its own (e.g. what bound the
  /// time step).
  InstabilityError(Index particle_id, std::string field, double value, std::uint64_t step, double time,
                   const std::string& reason, const std::string& note = "");

  Index particle_id() const { return particle_id_; }
  const std::string& field() const { return field_; }
  double value() const { return value_; }
  std::uint64_t step() const { return step_; }
  double time() const { return time_; }

 private:
  Index particle_id_;
  std::string field_;
  double value_;
  std::uint64_t step_;
  double time_;
};

}  // namespace tide
