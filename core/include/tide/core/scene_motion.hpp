#pragma once

// Prescribed (kinematic) motion of a solid in the scene model: what moves an obstacle's wall
// particles, independent of the fluid. Every motion is a rigid one, a displacement d(τ) of the
// solid and a rotation by θ(τ) about a fixed axis through the displaced centre c + d(τ), where
// τ = t − time.start: the scene's geometry is the solid at the start. docs/bodies.md gives the
// keys; solvers/include/tide/solvers/rigid_motion.hpp evaluates them, and MovingWalls moves a
// steered solid where it is steered.

#include <array>
#include <string>
#include <variant>
#include <vector>

namespace tide::scene {

using Vec = std::array<double, 3>;

/// Rotation about `axis` through `centre` at ω0, reached over `ramp_time` along
/// ω(τ) = ω0 (1 − cos(π τ / ramp_time)) / 2, so the solid starts at rest without a jolt.
struct Rotation {
  Vec centre{};
  Vec axis{0, 0, 1};            // unit vector; 2D scenes rotate about z
  double angular_velocity = 0;  // ω0, rad/s, positive counter-clockwise about `axis`
  double ramp_time = 0;         // s; 0 starts at ω0
};

/// Translation back and forth (a piston wavemaker): d(τ) = A (sin(2π f τ + φ) − sin φ).
struct Oscillation {
  Vec amplitude{};       // A, m
  double frequency = 0;  // f, Hz
  double phase = 0;      // φ, rad; −π/2 starts at rest
};

/// Rotation back and forth about a hinge (a flap wavemaker): θ(τ) = θA (sin(2π f τ + φ) − sin φ).
struct FlapOscillation {
  Vec hinge{};           // a point of the hinge axis
  Vec axis{0, 0, 1};     // unit vector; 2D scenes rotate about z
  double amplitude = 0;  // θA, rad
  double frequency = 0;  // f, Hz
  double phase = 0;      // φ, rad
};

/// One row of a motion table: at τ = `time`, the solid is displaced by `displacement` and turned
/// by `angle` (rad) about the table's axis.
struct MotionSample {
  double time = 0;
  Vec displacement{};
  double angle = 0;
};

/// A motion read from a CSV file: the pose is interpolated linearly between rows (the velocity is
/// the row-to-row slope, the acceleration zero) and held after the last row. The first row is
/// τ = 0 with no displacement and no angle.
struct MotionTable {
  std::string file;
  Vec centre{};
  Vec axis{0, 0, 1};
  std::vector<MotionSample> samples;
};

/// A translation the running program steers (tide serve's pointer drags the solid): the solid
/// heads for the displacement it is given (Simulation::steer), no faster than `max_speed`, and
/// stays where the scene puts it until it is given one.
struct Steered {
  double max_speed = 1;  // m/s
};

using Motion = std::variant<Rotation, Oscillation, FlapOscillation, MotionTable, Steered>;

}  // namespace tide::scene
