#include "tide/solvers/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

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
    case TimeStepLimit::capillary:
      return "capillary";
  }
  return "unknown";
}

Real acoustic_time_step(const TimeStepRule& rule, Real max_speed) {
  return rule.cfl * rule.smoothing_length / (rule.sound_speed + max_speed);
}

TimeStep choose_time_step(const TimeStepRule& rule, Real max_speed, Real max_acceleration) {
  const Real h = rule.smoothing_length;
  TimeStep step = rule.sound_speed > 0
                      ? TimeStep{acoustic_time_step(rule, max_speed), TimeStepLimit::acoustic}
                      : TimeStep{rule.cfl * h / std::max(max_speed, rule.speed_floor), TimeStepLimit::velocity};
  if (rule.kinematic_viscosity > 0) {
    const Real viscous = rule.viscous_number * h * h / rule.kinematic_viscosity;
    if (viscous < step.dt) step = {viscous, TimeStepLimit::viscous};
  }
  if (max_acceleration > 0) {
    const Real force = rule.force_number * std::sqrt(h / max_acceleration);
    if (force < step.dt) step = {force, TimeStepLimit::force};
  }
  if (rule.capillary_limit > 0 && rule.capillary_limit < step.dt)
    step = {rule.capillary_limit, TimeStepLimit::capillary};
  return step;
}

Real capillary_time_step(Real lightest_density, Real smoothing_length, Real coefficient) {
  const Real h = smoothing_length;
  return Real(0.25) * std::sqrt(lightest_density * h * h * h / (2 * std::numbers::pi_v<Real> * coefficient));
}

TimeStepLimit TimeStepTally::most_frequent() const {
  return static_cast<TimeStepLimit>(std::max_element(counts.begin(), counts.end()) - counts.begin());
}

}  // namespace tide
