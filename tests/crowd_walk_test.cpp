// Validation of the crowd scheme (docs/crowds.md, "What is measured"), case (c) of issue 36: a
// single agent in an empty room walks to the door at its desired speed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "crowd_scenes.hpp"
#include "tide/solvers/crowd_sph.hpp"

namespace tide {
namespace {

TEST(CrowdWalk, SingleAgentWalksToTheDoorAtItsDesiredSpeed) {
  test::CrowdRoom room;
  // Off the door's axis, so that the agent must turn toward the door, not walk along a grid line.
  room.agents = R"([{"region": {"min": [1.5, 0.8], "max": [2.5, 1.8]}, "count": 1}])";
  room.end = 20;
  CrowdSph crowd(test::crowd_room(room));
  const ParticleSet<2>& agent = crowd.fluid();
  const FluidFields<2>& f = crowd.fluid_fields();
  const Real v0 = agent[crowd.desired_speed()][0];
  const Vector<2> start = agent[f.position][0];
  const double tau = crowd.scene().crowd->relaxation_time;
  double open_room_error = 0, door_error = 0, walked = 0, exit_time = -1;
  Vector<2> at = start;
  while (crowd.time() < room.end) {
    crowd.step();
    if (crowd.exited()[0] == 1) {
      exit_time = crowd.time();
      break;
    }
    const Vector<2> x = agent[f.position][0];
    walked += static_cast<double>((x - at).norm());
    at = x;
    // After five relaxation times (e^-5 < 1% of the start-up deficit left).
    if (crowd.time() < 5 * tau) continue;
    const double error = std::abs(static_cast<double>(agent[f.velocity][0].norm() / v0) - 1);
    // In the open room, a metre or more from every wall, the walls' repulsion A/m exp(−(1 m − r)/B)
    // changes the speed by at most τ A/m e^(−9.4) = 1e-3 m/s; passing the door's edge it slows
    // the agent (measured: by 9.3% for about 0.4 s), which the walk's time below includes.
    const double wall_gap = std::min({static_cast<double>(x[0]), room.length - static_cast<double>(x[0]),
                                      static_cast<double>(x[1]), room.width - static_cast<double>(x[1])});
    (wall_gap >= 1 ? open_room_error : door_error) = std::max(wall_gap >= 1 ? open_room_error : door_error, error);
  }
  ASSERT_GT(exit_time, 0) << "the agent did not reach the door in " << room.end << " s";
  EXPECT_EQ(crowd.fluid().size(), 0U);
  // Relaxing from rest, v = v0 (1 − e^(−t/τ)), costs v0 τ of distance: a walk of length s at v0
  // takes s/v0 + τ.
  const double expected_time = walked / v0 + tau;
  const double straight = static_cast<double>((at - start).norm());
  std::printf(
      "v0 %.4f m/s; speed error: open room %.5f, near the door %.4f; walked %.4f m (straight line %.4f m); "
      "exit after %.4f s, s/v0 + tau = %.4f s\n",
      static_cast<double>(v0), open_room_error, door_error, walked, straight, exit_time, expected_time);
  // Measured: 0.65%, the start-up deficit e^-5 = 0.67% that relaxation leaves at 5τ (the issue's
  // bound, 2%).
  EXPECT_LT(open_room_error, 0.02);
  // Measured: 0.37% over the whole walk, the door's slowdown included (the issue's 2%).
  EXPECT_NEAR(exit_time / expected_time, 1, 0.02);
  // Measured: the path is 0.15% longer than the straight line from start to exit: the navigation
  // field leads straight to the door (bound: half the 2%).
  EXPECT_LT(walked / straight - 1, 0.01);
}

}  // namespace
}  // namespace tide
