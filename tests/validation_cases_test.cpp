// Regression thresholds for the validation cases: each case at its low test resolution, with
// the default variant (WCSPH, summation density, Wendland C2). A threshold is the error
// measured at that resolution (double, any thread count: the runs are deterministic) with a
// margin of about 25% for the float build and compiler differences; a broken pass (wrong
// viscosity, wall condition or pressure force) moves these errors by multiples, not by 25%.
// The measured values are in the comments; the study's ladders are in docs/validation.md.

#include <gtest/gtest.h>

#include <string>

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

// 10 particles across: L2 error 0.0105 averaged over the five times.
TEST(ValidationCases, CouetteStartUp) {
  EXPECT_LT(metric(run_at_test_resolution("couette"), "velocity_l2_error"), 0.014);
}

// 25 particles across, with Fickian shifting: velocity L2 error 0.082 at t = 1 s, decay rate
// error 0.064 (without shifting both exceed 0.9: the lattice pairs along the stagnation lines).
TEST(ValidationCases, TaylorGreenVortex) {
  const RunRecord r = run_at_test_resolution("taylor_green");
  EXPECT_LT(metric(r, "velocity_l2_error"), 0.1);
  EXPECT_LT(metric(r, "decay_rate_error"), 0.08);
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

}  // namespace
}  // namespace tide::validation
