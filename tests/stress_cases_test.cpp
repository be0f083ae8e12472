// The stress suite's short forms (tide stress --short): every row must behave as its case says
// it should. The bounds are the cases' own, set from physics (see each case and
// docs/stability.md): a row that fails one is a regression in the solver, not a tolerance to widen.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tide/stress/case.hpp"

namespace tide::stress {
namespace {

std::vector<Row> run_short(const std::string& name) {
  const Case* c = find_case(name);
  EXPECT_NE(c, nullptr) << name;
  return c ? c->run(Length::short_run) : std::vector<Row>{};
}

void expect_rows_as_expected(const std::vector<Row>& rows) {
  EXPECT_FALSE(rows.empty());
  for (const Row& row : rows) {
    EXPECT_TRUE(row.as_expected()) << row.settings << ": " << row.metric << " = " << row.value << ", bound "
                                   << row.bound.text() << ": " << row.outcome() << " (" << row.note << ")";
  }
}

// The rotating square patch, 30 particles across, to t = 1.5 s (measured: 96% of the core's
// particles paired closer than 0.5 dx without artificial stress, none with ε = 0.2).
TEST(StressCases, TensionClumpsWithoutArtificialStressAndNotWithIt) {
  const std::vector<Row> rows = run_short("tension");
  ASSERT_EQ(rows.size(), 2u);
  const Row& without = rows[0];
  const Row& with = rows[1];
  ASSERT_TRUE(without.failure.empty()) << without.failure;
  ASSERT_TRUE(with.failure.empty()) << with.failure;
  EXPECT_FALSE(without.bound.holds(without.value))
      << "no tensile clumping without artificial stress: close pair fraction " << without.value;
  EXPECT_TRUE(with.bound.holds(with.value))
      << "artificial stress did not cure the clumping: close pair fraction " << with.value << " (" << with.note << ")";
}

// Measured: kinetic energy 3.5e-8 M g H, no escapes, density error 0.0063 after 5 s.
TEST(StressCases, LongRest) { expect_rows_as_expected(run_short("long_rest")); }

// Measured (short): speeds up to 1.5 U, pressures up to 1.12 ρ0 c0 U and density errors up to
// 0.086, against the water hammer's 4.9 U, 1.2 ρ0 c0 U and 0.091.
TEST(StressCases, ViolentImpactStaysBelowTheWaterHammer) { expect_rows_as_expected(run_short("violent_impact")); }

TEST(StressCases, ExtremesStayStable) { expect_rows_as_expected(run_short("extremes")); }

// Stable at cfl 0.25 to 1.5; from cfl 2 the run stops with a report that names solver.cfl and
// the time step as the likely cause.
TEST(StressCases, TooLargeATimeStepIsReported) { expect_rows_as_expected(run_short("time_step")); }

// Measured: |E − E0|/E0 up to 5.2e-4 over 0.5 s, budget 1e-3.
TEST(StressCases, InviscidEnergyIsConserved) { expect_rows_as_expected(run_short("conservation")); }

}  // namespace
}  // namespace tide::stress
