#include "tide/solvers/instability.hpp"

#include <sstream>

namespace tide {
namespace {

std::string describe(Index particle_id, const std::string& field, double value, std::uint64_t step, double time,
                     const std::string& reason, const std::string& note) {
  std::ostringstream message;
  message << "unstable run: particle " << particle_id << " has " << field << " = " << value << " (" << reason
          << ") at step " << step << ", t = " << time << " s";
  if (!note.empty()) message << "; " << note;
  return message.str();
}

}  // namespace

InstabilityError::InstabilityError(Index particle_id, std::string field, double value, std::uint64_t step, double time,
                                   const std::string& reason, const std::string& note)
    : std::runtime_error(describe(particle_id, field, value, step, time, reason, note)),
      particle_id_(particle_id),
      field_(std::move(field)),
      value_(value),
      step_(step),
      time_(time) {}

}  // namespace tide
