// Contact between rigid bodies and with walls (tide/solvers/body_contacts.hpp): the pair force
// against its formula, equal and opposite forces between two bodies, Coulomb's cap on friction.
// body_stack_test.cpp runs bodies resting on each other.

#include "tide/solvers/body_contacts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "tide/core/particle_set.hpp"
#include "tide/core/scene_body.hpp"

namespace tide {
namespace {

constexpr Real spacing = Real(0.01);
constexpr Real wall_share = std::numeric_limits<Real>::infinity();
// A few roundings of the particles' precision, relative to `value`.
double rounding(double value) { return 64 * std::numeric_limits<Real>::epsilon() * std::abs(value); }

// A set of particles at `positions` moving at `velocities` (none: at rest).
struct Particles {
  ParticleSet<2> set;
  VectorField velocity = set.add_vector("velocity");

  Particles(const std::vector<Vector<2>>& positions, const std::vector<Vector<2>>& velocities = {}) {
    set.append(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      set[set.position()].set(i, positions[i]);
      set[velocity].set(i, velocities.empty() ? Vector<2>::Zero() : velocities[i]);
    }
  }
  SolidParticles<2> solid(Real mass_share) const {
    return {set[set.position()], set[velocity], set.size(), mass_share};
  }
};

ContactLaw test_law() {
  scene::BodyContact contact;
  contact.frequency = 100;
  return contact_law(contact, spacing, Real(1e-4));
}

// The contact force on every particle of solids[body].
std::vector<Vector<2>> forces_on(const ContactLaw& law, const std::vector<SolidParticles<2>>& solids,
                                 std::size_t body) {
  const std::vector<std::size_t> bodies{body};
  SolidCells<2> cells;
  cells.build(solids, bodies, law.distance);
  ParticleSet<2> out;
  out.append(solids[body].size);
  const VectorField force = out.add_vector("force");
  contact_forces<2>(law, cells, solids, body, out[force]);
  std::vector<Vector<2>> result;
  for (std::size_t i = 0; i < out.size(); ++i) result.push_back(out[force][i]);
  return result;
}

TEST(BodyContact, LawTakesTheDampingRatioOfTheRestitution) {
  const ContactLaw law = test_law();
  // e = 0.2: ζ = −ln 0.2 / √(π² + ln² 0.2) = 0.4559.
  EXPECT_NEAR(law.damping_ratio, 0.45595, 1e-5);
  EXPECT_EQ(law.frequency, Real(100));
  scene::BodyContact elastic;
  elastic.restitution = 1;
  EXPECT_EQ(contact_law(elastic, spacing, Real(1e-4)).damping_ratio, 0);
  // Unset, ω is 0.2 over the acoustic time step.
  EXPECT_NEAR(contact_law(scene::BodyContact{}, spacing, Real(1e-4)).frequency, 2000, rounding(2000));
}

TEST(BodyContact, PairAtRestPressesWithTheSpring) {
  const ContactLaw law = test_law();
  const Real share = 2;
  const Particles body({Vector<2>(0, 0)});
  const Particles wall({Vector<2>(Real(0.8) * spacing, 0)});
  const auto force = forces_on(law, {body.solid(share), wall.solid(wall_share)}, 0);
  // k (Δx − r) along n = (x_a − x_p)/r = −x, with k = m ω² of the body particle's share.
  const double expected = -share * 100.0 * 100.0 * (0.2 * spacing);
  EXPECT_NEAR(force[0][0], expected, rounding(expected));
  EXPECT_EQ(force[0][1], 0);
}

TEST(BodyContact, ParticlesApartOrOfTheSameSetDoNotTouch) {
  const ContactLaw law = test_law();
  const Particles body({Vector<2>(0, 0), Vector<2>(Real(0.5) * spacing, 0)});
  const Particles wall({Vector<2>(Real(1.0001) * spacing, Real(0.5) * spacing)});
  const auto force = forces_on(law, {body.solid(1), wall.solid(wall_share)}, 0);
  EXPECT_EQ(force[0], Vector<2>::Zero());  // 1.12 Δx from the wall particle
  // The second is 0.71 Δx from the wall particle: only that pair acts, not the pair within the body.
  EXPECT_LT(force[1][0], 0);
  EXPECT_LT(force[1][1], 0);
}

TEST(BodyContact, FrictionIsAtMostCoulombsShareOfTheNormalForce) {
  const ContactLaw law = test_law();
  // Sliding fast along the wall: the dashpot's c |v_t| is far above μ F_n.
  const Particles body({Vector<2>(0, Real(0.9) * spacing)}, {Vector<2>(10, 0)});
  const Particles wall({Vector<2>(0, 0)});
  const auto force = forces_on(law, {body.solid(1), wall.solid(wall_share)}, 0);
  const double normal = 100.0 * 100.0 * 0.1 * spacing;  // at rest along n: the spring alone
  EXPECT_NEAR(force[0][1], normal, rounding(normal));
  EXPECT_NEAR(force[0][0], -law.friction * normal, rounding(normal));
  // Sliding slowly: the dashpot's force, c |v_t| = 2 ζ m ω |v_t|.
  const Particles creeping({Vector<2>(0, Real(0.9) * spacing)}, {Vector<2>(Real(1e-4), 0)});
  const auto slow = forces_on(law, {creeping.solid(1), wall.solid(wall_share)}, 0);
  const double dashpot = 2 * law.damping_ratio * 100.0 * 1e-4;
  EXPECT_NEAR(slow[0][0], -dashpot, rounding(dashpot));
}

// Two bodies of different mass shares overlapping at many pairs, moving: the forces on one sum
// to minus those on the other (each pair's force is the other's with its sign turned, the sums
// differ only in their order), and a wall's particles take the body's share.
TEST(BodyContact, BodiesPushEachOtherEquallyAndOppositely) {
  const ContactLaw law = test_law();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.3, 0.3), speed(-0.5, 0.5);
  std::vector<Vector<2>> a, b, va, vb;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 4; ++j) {
      a.emplace_back(Real(spacing * (i + offset(random))), Real(spacing * (j + offset(random))));
      va.emplace_back(Real(speed(random)), Real(speed(random)));
      b.emplace_back(Real(spacing * (i + offset(random))), Real(spacing * (j + 3.5 + offset(random))));
      vb.emplace_back(Real(speed(random)), Real(speed(random)));
    }
  }
  const Particles first(a, va), second(b, vb);
  const std::vector<SolidParticles<2>> solids{first.solid(Real(0.3)), second.solid(Real(0.7))};
  Vector<2> on_first = Vector<2>::Zero(), on_second = Vector<2>::Zero();
  Real scale = 0;
  for (const Vector<2>& f : forces_on(law, solids, 0)) {
    on_first += f;
    scale += f.norm();
  }
  for (const Vector<2>& f : forces_on(law, solids, 1)) on_second += f;
  ASSERT_GT(scale, 0);
  const double tolerance = rounding(scale);
  EXPECT_NEAR(on_first[0], -on_second[0], tolerance);
  EXPECT_NEAR(on_first[1], -on_second[1], tolerance);
}

}  // namespace
}  // namespace tide
