// Regression thresholds for the validation cases: each case at its low test resolution, with
// the default variant (WCSPH, summation density, Wendland C2). A threshold is the error
// measured at that resolution (double, any thread count: the runs are deterministic) with a
// margin of about 25% for the float build and compiler differences; a broken pass (wrong
// viscosity, wall condition or pressure force) moves these errors by multiples, not by 25%.
// The measured values are in the comments; the study's ladders are in docs/validation.md.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>

#include "tide/validation/case.hpp"

namespace tide::validation {
namespace {

RunRecord run_at_test_resolution(const std::string& name, const Variant& variant = Variant{}) {
  const Case* c = find_case(name);
  EXPECT_NE(c, nullptr) << name;
  return c ? c->run(c->test_resolution, variant) : RunRecord{};
}

double metric(const RunRecord& record, const std::string& name) {
  for (const Metric& m : record.metrics)
    if (m.name == name) return m.value;
  ADD_FAILURE() << record.case_name << " has no metric " << name;
  return 0;
}

// 10 rows: pressure L2 error 0.093, density error 0.0050.
TEST(ValidationCases, HydrostaticTank2D) {
  const RunRecord r = run_at_test_resolution("hydrostatic_2d");
  EXPECT_LT(metric(r, "pressure_l2_error"), 0.12);
  EXPECT_LT(metric(r, "max_density_error"), 0.01);  // the bound
}

// 8 rows with summation density: pressure L2 error 0.049, density error 0.0047.
TEST(ValidationCases, HydrostaticTank3D) {
  const RunRecord r = run_at_test_resolution("hydrostatic_3d");
  EXPECT_LT(metric(r, "pressure_l2_error"), 0.065);
  EXPECT_LT(metric(r, "max_density_error"), 0.01);
}

// 10 particles across: L2 error 0.048 averaged over the five times.
TEST(ValidationCases, PoiseuilleStartUp) {
  EXPECT_LT(metric(run_at_test_resolution("poiseuille"), "velocity_l2_error"), 0.06);
}

// The same with continuity density: the driving force lies along the periodic axis, where it
// builds no hydrostatic pressure (the initial density once took it for gravity and started the
// channel at 1.5 ρ0). 10 particles across: L2 error 0.048.
TEST(ValidationCases, PoiseuilleStartUpWithContinuityDensity) {
  const Case* c = find_case("poiseuille");
  ASSERT_NE(c, nullptr);
  EXPECT_LT(
      metric(c->run(c->test_resolution, Variant{"wcsph_continuity", KernelType::wendland_c2}), "velocity_l2_error"),
      0.06);
}

// 10 particles across: L2 error 0.0105 averaged over the five times.
TEST(ValidationCases, CouetteStartUp) {
  EXPECT_LT(metric(run_at_test_resolution("couette"), "velocity_l2_error"), 0.014);
}

// DFSPH and IISPH on both channels at 20 particles across, where they used to blow up: the
// warm-started pressure, barely changed by the two sweeps that met the threshold, integrated the
// density error over the steps until a transverse velocity grew tenfold every ~20 steps. Measured
// (double): Poiseuille L2 error 0.0203 for both (WCSPH 0.0203), Couette 0.00686 (WCSPH 0.00689).
TEST(ValidationCases, ChannelStartUpIncompressible) {
  for (const std::string scheme : {"dfsph", "iisph"}) {
    for (const auto& [name, bound] : {std::pair{"poiseuille", 0.025}, std::pair{"couette", 0.0086}}) {
      const Case* c = find_case(name);
      ASSERT_NE(c, nullptr);
      EXPECT_LT(metric(c->run(20, Variant{scheme}), "velocity_l2_error"), bound) << name << ", " << scheme;
    }
  }
}

// 25 particles across, with Fickian shifting: velocity L2 error 0.082 at t = 1 s, decay rate
// error 0.064 (without shifting both exceed 0.9: the lattice pairs along the stagnation lines).
// In double both are stable to 10^-8 under rounding-level changes (skin 0 or 0.3, the CFL number
// × (1 + n 10^-9)). In float they are not: eight runs that differ by one ulp of the CFL number or
// by the skin (2026-12-02) spread the decay rate error over 0.023–0.100 and the velocity error
// over 0.077–0.094, so the float bounds are those extremes + 25%.
TEST(ValidationCases, TaylorGreenVortex) {
  const RunRecord r = run_at_test_resolution("taylor_green");
  constexpr bool single = std::is_same_v<Real, float>;
  EXPECT_LT(metric(r, "velocity_l2_error"), single ? 0.118 : 0.1);
  EXPECT_LT(metric(r, "decay_rate_error"), single ? 0.125 : 0.08);
}

// a/Δx = 20: the front runs ahead of Martin & Moyce's experiment, whose gate took time to open;
// one fitted start offset δT must lie in [0.1, 0.4] and leave a mean error of at most 4% over
// 0.4 ≤ T ≤ 2.5 (the criterion of the WCSPH issue; SPlisHSPlasH and DualSPHysics measure
// δT ≈ 0.25 and about 2%). Measured: δT = 0.237, 2.06% (raw 11.6%); against Koshizuka & Oka
// 3.5% after δT = 0.143.
TEST(ValidationCases, DamBreakFrontFollowsTheExperiments) {
  const RunRecord r = run_at_test_resolution("dam_break_2d");
  EXPECT_GE(metric(r, "start_offset"), 0.1);
  EXPECT_LE(metric(r, "start_offset"), 0.4);
  EXPECT_LE(metric(r, "front_error_after_offset"), 0.04);
  EXPECT_LE(metric(r, "front_error_after_offset_ko"), 0.045);
}

// The incompressible schemes on the same dam break and by the same criterion (velocity limit,
// ~125 steps instead of ~1900). Measured at a/Δx = 20 (double): DFSPH δT = 0.254, 2.04% (raw
// 12.4%); IISPH δT = 0.253, 2.09% (raw 12.2%); about 5 and 13 sweeps per step.
TEST(ValidationCases, DamBreakFrontFollowsTheExperimentsIncompressible) {
  for (const std::string scheme : {"dfsph", "iisph"}) {
    const RunRecord r = run_at_test_resolution("dam_break_2d", Variant{scheme});
    EXPECT_GE(metric(r, "start_offset"), 0.1) << scheme;
    EXPECT_LE(metric(r, "start_offset"), 0.4) << scheme;
    EXPECT_LE(metric(r, "front_error_after_offset"), 0.04) << scheme;
  }
}

// The same column in 3D, a/2 deep between free-slip side walls, a/Δx = 10 (1000 particles), by the
// same criterion for every scheme. Measured (double): WCSPH δT = 0.176, 1.86% (960 steps); DFSPH
// δT = 0.215, 1.80%; IISPH δT = 0.219, 1.84% (61 steps each).
TEST(ValidationCases, DamBreakFront3DFollowsTheExperiments) {
  for (const std::string scheme : {"wcsph", "dfsph", "iisph"}) {
    const RunRecord r = run_at_test_resolution("dam_break_3d_front", Variant{scheme});
    EXPECT_GE(metric(r, "start_offset"), 0.1) << scheme;
    EXPECT_LE(metric(r, "start_offset"), 0.4) << scheme;
    EXPECT_LE(metric(r, "front_error_after_offset"), 0.04) << scheme;
  }
}

// H/Δx = 40 (3200 particles, about 8250 steps, 30 s on 2 cores): against Buchner's downstream-wall
// pressure, filtered over 0.1 in τ = t sqrt(g/H). The flow before the impact is chaotic: two runs
// that differ only in rounding (another neighbour-list skin, or the CFL number × (1 + 10^-9); the
// particles agree to 10^-19 m after two steps) drift apart tenfold every 250 steps and by a third of
// a spacing when the water reaches the wall. Twelve such runs (2026-12-01, double) span: first peak
// −5%…+32%, its time 0.007…0.673 late, impact (half the peak reached) 0.035…0.178 late, L2 error
// 0.358…0.533. The bounds are those extremes + 25%; a bound inside them would test the rounding.
// A wall that lets the water through or a missing impact moves the peak by −100% and the times by
// more than a unit of τ.
TEST(ValidationCases, DamBreakWallPressureFollowsBuchner) {
  const RunRecord r = run_at_test_resolution("dam_break_buchner");
  EXPECT_LE(std::abs(metric(r, "first_peak_error")), 0.4);
  EXPECT_LE(std::abs(metric(r, "first_peak_time_error")), 0.84);
  EXPECT_LE(std::abs(metric(r, "impact_time_error")), 0.22);
  EXPECT_LE(metric(r, "pressure_l2_error"), 0.67);
}

// Continuity density with δ-SPH (δ = 0.1) on the same dam break at H/Δx = 20 (800 particles,
// 7 s of CPU): it used to stop at τ ≈ 2.3 on the surge's tip (ρ = 666 < ρ0/1.5); with the
// free-surface density it runs through, and its raw wall pressure is smooth on the run-up plateau
// where summation density's jumps between 0 and twice its mean within a quarter of τ. Measured:
// plateau_spread 3.7 (summation at this resolution: 200, the floor of the metric; at H/Δx = 40,
// 1.9 against 31), bounded by 10, an order of magnitude below summation's, so a pressure that
// turns noisy fails; first peak +7%, its time 0.28 early, impact 0.18 early, L2 0.62, bounded by
// the measured + 25% (rounded) as the summation test above (a smaller first-peak error keeps
// that test's 0.4, which tells a missing impact).
TEST(ValidationCases, DamBreakWallPressureWithContinuityDensityIsSmooth) {
  const Case* c = find_case("dam_break_buchner");
  ASSERT_NE(c, nullptr);
  const RunRecord r = c->run(20, Variant{"wcsph_continuity"});
  EXPECT_LE(metric(r, "plateau_spread"), 10.0);
  EXPECT_LE(std::abs(metric(r, "first_peak_error")), 0.4);
  EXPECT_LE(std::abs(metric(r, "first_peak_time_error")), 0.35);
  EXPECT_LE(std::abs(metric(r, "impact_time_error")), 0.22);
  EXPECT_LE(metric(r, "pressure_l2_error"), 0.78);
}

// The Lobovsky scene at H/Δx = 12 (1724 particles, 6 across the width, 2445 steps, 52 s on 2
// shared cores), its end-wall probe at 0.2H against Buchner as above. The impact arrives within
// 0.036 of Buchner's (measured −0.036; bound +25%, rounded). At this resolution the kernel
// support (0.085 m) is wider than the probe's height (0.06 m) and the filtered first peak
// overshoots (measured +196%, bound +25%); a missing impact would read −100%, hence the lower
// bound. L2 error: measured 1.32, bound +25%. (At H/Δx = 24 the impact is 0.30 late, the peak
// +44% and the L2 error 0.63: the 3D case is far from converged at the resolutions ctest can
// afford; dam_break_buchner shows the converged behaviour.)
TEST(ValidationCases, DamBreak3DWallPressureAtLowResolution) {
  const RunRecord r = run_at_test_resolution("dam_break_3d");
  EXPECT_LE(std::abs(metric(r, "impact_time_error")), 0.05);
  EXPECT_GE(metric(r, "first_peak_error"), 0);
  EXPECT_LE(metric(r, "first_peak_error"), 2.45);
  EXPECT_LE(metric(r, "pressure_l2_error"), 1.65);
}

// 40 particles across, with Fickian shifting, t = 10, centre lines averaged over the last time
// unit: u RMS error 0.0137 U, v 0.0069 U, vortex minimum 2.0% weak. The particle noise that
// survives the averaging (the averaged profile moves by 0.0042 U between the last two units) is a
// third of the u error, so the margin here is twice that noise, not 25%: a float build follows
// other particle paths. The vortex minimum, one sample, gets 0.037 (its scatter without shifting).
TEST(ValidationCases, LidDrivenCavityRe100) {
  const RunRecord r = run_at_test_resolution("cavity_re100");
  EXPECT_LT(metric(r, "u_centreline_rms_error"), 0.022);
  EXPECT_LT(metric(r, "v_centreline_rms_error"), 0.015);
  EXPECT_LT(metric(r, "u_min_error"), 0.057);
}

// 25 particles across, with shifting, t = 30: u RMS error 0.093 U, v 0.111 U, vortex minimum 32%
// weak — far from resolved (50 particles: 0.064, 0.065, 12%; that run takes minutes), so this
// guards the set-up, not the accuracy. Margins as above: twice the last unit's change (0.0061 U),
// 0.04 on the vortex minimum.
TEST(ValidationCases, LidDrivenCavityRe1000) {
  const RunRecord r = run_at_test_resolution("cavity_re1000");
  EXPECT_LT(metric(r, "u_centreline_rms_error"), 0.105);
  EXPECT_LT(metric(r, "v_centreline_rms_error"), 0.123);
  EXPECT_LT(metric(r, "u_min_error"), 0.36);
}

// Archimedes (issue 35, 6a): a box of half the water's density settles upright at its draft
// below the still water's hydrostatic level. 2D, 10 rows over its height (draft 5 Δx): within the
// issue's 2%, measured 1.5% (double and float; 2.3% at 20 rows, where the bound does not hold).
// 3D at the test's 5 rows (Δx = 2 cm, draft 2.5 Δx, a particle layer 40% of it): 0.84% in double
// but 4.5% in float, so this run checks the set-up (bound 6%); the 2% holds at 10 rows in both
// precisions (0.71%, 0.72%; `tide validate floating_box_3d`, 2–3 minutes). Below the top particles
// plus Δx/2 instead the draft reads 12% (2D) and 26% (3D) short: SPH's free surface sags by about
// half a spacing (docs/validation-bodies.md).
TEST(ValidationCases, FloatingBoxSettlesAtArchimedesDraft) {
  for (const auto& [name, bound] : {std::pair{"floating_box_2d", 0.02}, std::pair{"floating_box_3d", 0.06}}) {
    const RunRecord r = run_at_test_resolution(name);
    EXPECT_LT(metric(r, "draft_error"), bound) << name;
    EXPECT_LT(metric(r, "max_tilt_rad"), 0.05) << name << ": upright";
    EXPECT_LT(metric(r, "late_speed_m_per_s"), 0.05) << name << ": at rest (measured 0.025 and 0.010 m/s)";
  }
}

// A body of the density of the water round it, let go once the water has settled (issue 35, 6b:
// drift < 0.1 Δx over 2 s). At Δx = 1 cm the box sinks 0.21 Δx and the ball rises 1.09 Δx: SPH's
// buoyancy is not exact to the 0.1% that bound needs (a locked ball feels 1.4% more than ρ g V at
// h = 1.7 Δx, a locked box 0.9% less), and the fluid's lattice holds the body elastically where
// that force balances. At Δx = 5 mm the box drifts 0.094 Δx, within the bound, and the ball
// 0.62 Δx (docs/validation-bodies.md). These are regression thresholds, 25% over the measured.
TEST(ValidationCases, NeutrallyBuoyantBodiesStayNearWhereTheyAreLetGo) {
  EXPECT_LT(metric(run_at_test_resolution("neutral_box"), "drift_over_spacing"), 0.26);
  EXPECT_LT(metric(run_at_test_resolution("neutral_ball"), "drift_over_spacing"), 1.37);
}

// A cylinder settling at low Reynolds number (issue 35, 6e: its analytic drag within 10%):
// midway between walls 8 radii away, its mean speed over 1.5-3.5 s against Faxén's Stokes drag.
// 8 particles across: 2.8% fast (Re = 0.04), within the bound (docs/validation-settling.md).
TEST(ValidationCases, SettlingCylinderMeetsFaxensDrag) {
  const RunRecord r = run_at_test_resolution("settling_cylinder");
  EXPECT_LT(metric(r, "speed_error"), 0.10);
  EXPECT_LT(metric(r, "reynolds_number"), 0.1) << "Stokes flow";
  EXPECT_LT(metric(r, "sideways_over_spacing"), 0.1) << "it falls straight";
}

// A published experiment of a body in water (issue 35, 6d): a block of 800.52 kg/m³ let go under
// water rises, overshoots and bobs at its floating height (Qiu, Liu & Han 2017, §3.3; measured
// there: first peak 0.0512 m at 0.376 s, then a period of 0.356 s about 0.0433 m). At the test's
// 6 rows over the block (Δx = 4 mm) the block starts 16 mm higher than in the experiment (it must
// start a kernel support clear of the floor, docs/validation-rising-block.md) and hardly
// overshoots: RMS height error 0.187 of the experiment's 0.039 m rise, mean height from 0.55 s
// 0.0012 of it low (0.064 at 8 rows, 0.039 at 12, where the first peak comes 0.09 s late and the
// period is 9% long). Regression bounds: the RMS 25% over the measured; the mean within a tenth
// of the rise (4 mm), so that a block that floats at the wrong height or stays down fails.
TEST(ValidationCases, RisingBlockFollowsTheExperiment) {
  const RunRecord r = run_at_test_resolution("rising_block");
  EXPECT_LT(metric(r, "height_rms_error"), 0.23);
  EXPECT_LT(std::abs(metric(r, "mean_height_error")), 0.1);
}

// The crowd cases of issue 36 (docs/crowds.md, "What is measured"), with the crowd scheme.
RunRecord run_crowd_case(const std::string& name) {
  return run_at_test_resolution(name, {std::string(crowd_scheme), KernelType::wendland_c2});
}

// Case (c): one agent crosses an empty room to the door, from off the door's axis.
TEST(CrowdWalk, SingleAgentWalksToTheDoorAtItsDesiredSpeed) {
  const RunRecord r = run_crowd_case("crowd_single_agent");
  // Measured: 0.65%, the start-up deficit e^-5 = 0.67% that relaxation leaves at 5τ (the issue's
  // bound, 2%).
  EXPECT_LT(metric(r, "open_room_speed_error"), 0.02);
  // Measured: 0.26% over the whole walk, the door's slowdown included (the 2%).
  EXPECT_LT(metric(r, "exit_time_error"), 0.02);
  // Measured: the path is 0.06% longer than the straight line from start to exit: the navigation
  // field leads straight to the door (bound: half the 2%).
  EXPECT_LT(metric(r, "path_excess"), 0.01);
}

// Case (a): the fundamental diagram's shape in a corridor 10 m long, each density up to 4
// persons/m² slower than the one before and than Weidmann's free speed v0 = 1.34 m/s; at 4.5 and
// 5 the crowd is jammed (measured −0.0000 and 0.055 m/s, from a lattice start) and must be
// slower than at 4 and not walk backwards. Its distance to Weidmann (the case's metric, 38.6% RMS
// at this length, 29.2% at the study's 20 m) is printed. Measured, 0.5 to 4: 1.025, 0.788, 0.595,
// 0.460, 0.435, 0.300, 0.209, 0.136 m/s (the uneasiness pressure on the density of the others).
TEST(CrowdCorridor, MeanSpeedFallsWithDensity) {
  const RunRecord r = run_crowd_case("crowd_fundamental_diagram");
  double previous = 1.34, at_four = 0;
  for (const char* density : {"0_5", "1", "1_5", "2", "2_5", "3", "3_5", "4", "4_5", "5"}) {
    const double speed = metric(r, std::string("mean_speed_") + density + "_m_per_s");
    std::printf("density %s persons/m^2: mean speed %.4f m/s, %+.1f%% from Weidmann 1993\n", density, speed,
                100 * metric(r, std::string("speed_error_") + density));
    if (at_four > 0) {
      EXPECT_LT(speed, at_four) << density;
      EXPECT_GT(speed, -0.01) << density;
      continue;
    }
    EXPECT_LT(speed, previous) << density;
    previous = speed;
    if (std::string(density) == "4") at_four = speed;
  }
  std::printf("root mean square error against Weidmann 1993: %.1f%%\n", 100 * metric(r, "speed_rms_error"));
}

// Case (b): flow through a door 1.6, 2.0 and 2.4 m wide. Measured: specific flows 1.285, 1.312,
// 1.270 persons/(m s), 1.8% at most from their mean (34–41% below Liddle et al. 2011's measured
// flows, the case's specific_flow_error_*, printed, not bounded: docs/crowds.md, "Bottleneck"). Bound: 10%, the spread
// of a constant specific flow (a flow linear in the width through 0) over three widths.
TEST(CrowdBottleneck, FlowGrowsLinearlyWithTheWidthOfAWideDoor) {
  const RunRecord r = run_crowd_case("crowd_bottleneck");
  EXPECT_LT(metric(r, "flow_1_6_per_s"), metric(r, "flow_2_per_s"));
  EXPECT_LT(metric(r, "flow_2_per_s"), metric(r, "flow_2_4_per_s"));
  EXPECT_LT(metric(r, "specific_flow_spread"), 0.1);
  std::printf("specific flows %.3f, %.3f, %.3f persons/(m s)\n", metric(r, "specific_flow_1_6_per_m_s"),
              metric(r, "specific_flow_2_per_m_s"), metric(r, "specific_flow_2_4_per_m_s"));
  std::printf("against Liddle et al. 2011: %+.1f%%, %+.1f%%, %+.1f%%\n", 100 * metric(r, "specific_flow_error_1_6"),
              100 * metric(r, "specific_flow_error_2"), 100 * metric(r, "specific_flow_error_2_4"));
}

}  // namespace
}  // namespace tide::validation
