#include "tide/solvers/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tide {

std::string_view time_step_limit_name(TimeStepLimit limit) {
  switch (limit) {
    case TimeStepLimit::acoustic:
      return "acoustic";
    case TimeStepLimit::velocity:
      return "velocity";
    case TimeStepLimit::viscous:
      return "viscous";
    case TimeStepLimit::force:
      return "force";
  }
  return "unknown";
}

TimeStep choose_time_step(const TimeStepRule& rule, Real max_speed, Real max_acceleration) {
  const Real h = rule.smoothing_length;
  TimeStep step = rule.sound_speed > 0
                      ? TimeStep{rule.cfl * h / (rule.sound_speed + max_speed), TimeStepLimit::acoustic}
                      : TimeStep{rule.cfl * h / std::max(max_speed, rule.speed_floor), TimeStepLimit::velocity};
  if (rule.kinematic_viscosity > 0) {
    const Real viscous = rule.viscous_number * h * h / rule.kinematic_viscosity;
    if (viscous < step.dt) step = {viscous, TimeStepLimit::viscous};
  }
  if (max_acceleration > 0) {
    const Real force = rule.force_number * std::sqrt(h / max_acceleration);
    if (force < step.dt) step = {force, TimeStepLimit::force};
  }
  return step;
}

TimeStepLimit TimeStepTally::most_frequent() const {
  return static_cast<TimeStepLimit>(std::max_element(counts.begin(), counts.end()) - counts.begin());
}

}  // namespace tide
