#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "tide/core/types.hpp"

namespace tide {

/// The largest acoustic CFL number at which WCSPH's kick-drift-kick steps are taken to be
/// stable. Above 1 a scene is warned about; the 2D tank at rest of docs/stability.md (time step)
/// stays at rest up to 1.5 and goes unstable from 2.
inline constexpr Real max_stable_cfl = 1;

/// Which stability limit set a time step: acoustic (weakly compressible schemes), velocity
/// (incompressible schemes), viscous, force or capillary (surface tension).
enum class TimeStepLimit { acoustic, velocity, viscous, force, capillary };
inline constexpr std::size_t time_step_limit_count = 5;

std::string_view time_step_limit_name(TimeStepLimit limit);

struct TimeStepRule {
  Real smoothing_length = 0;
  Real sound_speed = 0;          // 0: an incompressible scheme, limited by the flow speed instead
  Real speed_floor = 0;          // incompressible: the speed the velocity limit assumes while the flow is slower
  Real kinematic_viscosity = 0;  // 0: no viscous limit
  Real cfl = Real(0.25);
  Real viscous_number = Real(0.125);
  Real force_number = Real(0.25);
  Real capillary_limit = 0;  // s; 0: no surface tension (see capillary_time_step)
};

/// The acoustic limit cfl h / (c0 + |v|max) of a rule with a sound speed (WCSPH).
Real acoustic_time_step(const TimeStepRule& rule, Real max_speed);

/// The capillary-wave limit of an explicit surface-tension step, 0.25 sqrt(ρ h³ / (2π σ))
/// (Brackbill, Kothe & Zemach 1992, eq. 61; Adami, Hu & Adams 2010 take the factor 0.25), with
/// ρ the lightest phase's rest density.
Real capillary_time_step(Real lightest_density, Real smoothing_length, Real coefficient);

struct TimeStep {
  Real dt = 0;
  TimeStepLimit limit = TimeStepLimit::acoustic;
};

/// The adaptive step: the smallest of the acoustic limit cfl·h/(c0 + |v|max) (explicit WCSPH), or
/// for an incompressible scheme (sound_speed = 0) the velocity limit cfl·h/max(|v|max, speed_floor)
/// (Bender & Koschier 2017, Sec. 5: a particle moves at most a fraction of its support per step),
/// the viscous limit viscous_number·h²/ν and the force limit force_number·sqrt(h/|a|max)
/// (Monaghan 1992; Morris, Fox & Zhu 1997), and the capillary limit when one is set.
TimeStep choose_time_step(const TimeStepRule& rule, Real max_speed, Real max_acceleration);

/// Counts of binding limits over a stretch of steps.
struct TimeStepTally {
  std::array<std::size_t, time_step_limit_count> counts{};
  void add(TimeStepLimit limit) { ++counts[static_cast<std::size_t>(limit)]; }
  std::size_t total() const { return counts[0] + counts[1] + counts[2] + counts[3] + counts[4]; }
  TimeStepLimit most_frequent() const;
};

}  // namespace tide
