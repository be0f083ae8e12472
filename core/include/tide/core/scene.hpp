#pragma once

// The scene model: plain data describing one simulation, independent of any file format.
// io/ fills it from a JSON file (docs/scenes.md documents every key); solvers/ builds particle
// sets and a pipeline from it. All quantities are SI. Vectors always hold three numbers; a 2D
// scene uses the first two.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/scene_body.hpp"
#include "tide/core/scene_motion.hpp"
#include "tide/core/triangle_mesh.hpp"

namespace tide::scene {

using Vec = std::array<double, 3>;

struct Box {
  Vec min{};
  Vec max{};
};

struct Ball {
  Vec centre{};
  double radius = 0;
};

/// A half-space wall: the solid lies on the side opposite the normal.
struct Plane {
  Vec point{};
  Vec normal{};
};

/// A closed triangle mesh read from a file (docs/bodies.md, "Meshes"). Its vertices are placed in
/// the scene as scale × units, then rotated by `degrees` about `axis` (through the origin of the
/// file's coordinates), then translated. `surface` holds the repaired and placed triangles in
/// metres; the scene reader fills it, once, when it reads the scene.
struct Mesh {
  std::string file;    // as written in the scene, relative to the scene's directory
  double scale = 1;    // –
  double units = 1;    // metres per file unit: 1 (m), 0.01 (cm), 0.001 (mm)
  Vec axis{0, 0, 1};   // rotation axis
  double degrees = 0;  // rotation angle, counter-clockwise about `axis`
  Vec translation{};   // m
  std::shared_ptr<const TriangleMesh> surface;
  Box bounds;  // of `surface`
};

/// A fluid's material. The artificial speed of sound is either given (`sound_speed`) or set to
/// 10 × `max_speed`, the largest speed the user expects (Mach 0.1, density variation ≈ 1%).
struct Material {
  std::string name;
  double rest_density = 1000;         // kg/m³
  double kinematic_viscosity = 0;     // m²/s, used by the laminar (Morris) viscosity
  std::optional<double> sound_speed;  // m/s
  std::optional<double> max_speed;    // m/s
};

/// The Taylor–Green vortex in the periodic square [0, L)²: u = −U cos(2πx/L) sin(2πy/L),
/// v = U sin(2πx/L) cos(2πy/L) (Taylor & Green 1937).
struct TaylorGreenVelocity {
  double amplitude = 1;  // U, m/s
  double length = 1;     // L, m
};

/// Rigid rotation about `centre` in the plane: u = −ω (y − y_c), v = ω (x − x_c), ω > 0
/// counter-clockwise (the rotating square patch of Colagrossi 2005 starts this way).
struct RigidRotation {
  Vec centre{};
  double angular_velocity = 1;  // ω, rad/s
};

/// A block of fluid particles filled on the lattice of the particle spacing, with its initial
/// velocity: uniform, or a named field.
struct FluidBlock {
  std::size_t material = 0;  // index into Scene::materials
  std::variant<Box, Ball> shape;
  std::variant<Vec, TaylorGreenVelocity, RigidRotation> velocity{Vec{}};
};

enum class WallSlip { no_slip, free_slip };

/// A closed box container whose inner faces are walls; `open_top` leaves out the face at the
/// top of the last axis (y in 2D, z in 3D).
struct Container {
  Box inner;
  bool open_top = true;
};

/// A solid obstacle. Without `motion` its particles stay in place and `velocity` is the velocity
/// of its surface for the no-slip condition (a wall sliding in its own plane: a Couette plate,
/// the lid of a cavity). With `motion` the obstacle moves as a rigid body (scene_motion.hpp) and
/// its surface has the velocity of that motion.
struct Obstacle {
  std::variant<Box, Ball, Plane, Mesh> shape;
  Vec velocity{};
  std::optional<WallSlip> slip;  // unset: the walls' slip (Walls::slip)
  std::optional<Motion> motion;
  std::optional<Body> body;  // moved by the fluid (not with a motion)
};

/// Wall layers a kernel needs so that a fluid particle touching a wall has wall particles across
/// its whole support: ceil(support radius / spacing).
inline int required_wall_layers(KernelType kernel, double smoothing_ratio) {
  const double support_in_spacings = static_cast<double>(kernel_support_factor(kernel)) * smoothing_ratio;
  return static_cast<int>(std::ceil(support_in_spacings - 1e-9));  // 2 × 1.5 is 3 layers, not 4
}

struct Walls {
  int layers = 3;  // boundary particle layers; at least kernel support / spacing
  WallSlip slip = WallSlip::no_slip;
  std::optional<Container> container;
  std::vector<Obstacle> obstacles;
};

/// Pseudo-periodic inflow/outflow along x (a periodic axis): fluid leaving at max x re-enters at
/// min x, where the particles within `length` of the domain's min x move at `velocity` along x.
/// With `phase`, every particle that re-enters becomes that material (water injected into oil).
struct Inflow {
  double velocity = 0;               // m/s
  double length = 0;                 // m, the inflow buffer's extent along x
  std::optional<std::size_t> phase;  // index into Scene::materials of the injected fluid
};

/// The region particles may occupy; a particle leaving it on a closed axis is removed.
struct Domain {
  Box box;
  std::array<bool, 3> periodic{};
  std::optional<Inflow> inflow{};
};

/// The domain a container needs when the scene gives none: its inner box grown by the wall
/// thickness on every side and, above an open top, as much room again as the container is high,
/// so that a splash stays inside the domain.
inline Domain domain_around(const Container& container, double wall_thickness, int dimension) {
  Domain domain;
  for (int d = 0; d < dimension; ++d) {
    domain.box.min[d] = container.inner.min[d] - wall_thickness;
    domain.box.max[d] = container.inner.max[d] + wall_thickness;
  }
  const int up = dimension - 1;
  if (container.open_top) domain.box.max[up] += container.inner.max[up] - container.inner.min[up];
  return domain;
}

/// wcsph: weakly compressible, pressure from an equation of state. dfsph, iisph: incompressible,
/// pressure from an implicit solve (Bender & Koschier 2017; Ihmsen et al. 2014). crowd: people as
/// particles (Scene::crowd, docs/crowds.md).
enum class Scheme { wcsph, dfsph, iisph, crowd };
enum class EquationOfState { tait, linear };
enum class DensityMethod { summation, continuity };
enum class ViscosityModel { artificial, laminar };
enum class Shifting { none, fickian };

/// Surface tension (docs/multiphase.md). csf: continuum surface force from the colour gradient
/// of two fluids (Brackbill et al. 1992; Morris 2000). akinci: cohesion and surface-area
/// minimisation with adhesion to walls (Akinci et al. 2013). pairwise: inter-particle forces
/// whose fluid–wall strength sets the contact angle (Tartakovsky & Meakin 2005).
enum class SurfaceTensionModel { none, csf, akinci, pairwise };

struct SurfaceTension {
  SurfaceTensionModel model = SurfaceTensionModel::none;
  double coefficient = 0;     // σ in N/m (2D: N); akinci: Akinci's γ
  double contact_angle = 90;  // pairwise: static angle in degrees, measured through the first material
  double adhesion = 0;        // akinci: β of the wall adhesion
  // pairwise, two fluids: whether unlike fluid particles attract (s_ab = s/2) or do not (s_ab = 0,
  // like pairs s/2): the same σ and angle, less lattice cohesion to pin a contact line
  bool unlike_attraction = true;
};

/// The pair pressure and velocity of WCSPH (docs/scenes.md, solver.riemann_solver).
enum class RiemannSolver {
  none,             // Monaghan's symmetric pressure term, continuity with δ-SPH
  low_dissipation,  // Zhang, Hu & Adams 2017: a linearised Riemann problem per pair, limited dissipation
};

/// How DFSPH and IISPH solve for the pressure (docs/scenes.md, solver.pressure_solver).
enum class PressureSolver {
  jacobi,               // projected Jacobi sweeps (the density solve Chebyshev-accelerated)
  conjugate_gradients,  // preconditioned conjugate gradients on the symmetric equation, energy-norm stop
};

struct Solver {
  Scheme scheme = Scheme::wcsph;
  EquationOfState equation_of_state = EquationOfState::tait;
  double tait_exponent = 7;
  DensityMethod density = DensityMethod::summation;
  double delta_sph = 0.1;                              // δ-SPH diffusion coefficient (continuity density only)
  RiemannSolver riemann_solver = RiemannSolver::none;  // wcsph with continuity density only
  bool kernel_gradient_correction = false;             // riemann_solver low_dissipation only: L_i ∇W_ij
  ViscosityModel viscosity = ViscosityModel::artificial;
  double alpha = 0.02;                  // Monaghan artificial viscosity, linear term
  double beta = 0;                      // Monaghan artificial viscosity, quadratic term
  double cfl = 0.25;                    // acoustic limit: dt ≤ cfl · h / (c0 + |v|max)
  double viscous_number = 0.125;        // viscous limit: dt ≤ viscous_number · h² / ν
  double force_number = 0.25;           // force limit: dt ≤ force_number · sqrt(h / |a|max)
  double max_density_ratio = 1.5;       // stability band: ρ/ρ0 must stay inside [1/ratio, ratio]
  double max_mach_number = 1;           // stability band: |v| must stay at or below this multiple of c0
  bool clamp_negative_pressure = true;  // p = max(p, 0): free-surface flows without tension
  double gravity_ramp_time = 0;         // s: gravity rises smoothly from 0 over this time (0: at once)
  double background_pressure = 0;       // Pa, added to the equation of state (closed or periodic flows)
  Shifting shifting = Shifting::none;   // particle shifting after each step (Lind et al. 2012)
  double artificial_stress = 0;         // ε of Monaghan's (2000) artificial stress; 0: off
  // Particle spacings the neighbour lists reach beyond the support, so that they (and the sort)
  // are kept until some particle has moved half as far; unset: default_neighbor_skin
  std::optional<double> neighbor_skin;
  // Incompressible schemes (dfsph, iisph) only:
  double max_density_error = 0.0005;    // pressure solve ends when the mean density error is below this share of ρ0
  double max_divergence_error = 0.001;  // DFSPH divergence solve: mean error of Δt Dρ/Dt, as a share of ρ0
  int max_solver_iterations = 100;      // cap per pressure solve
  PressureSolver pressure_solver = PressureSolver::jacobi;  // DFSPH and IISPH
  int max_failed_solves = 10;  // consecutive steps whose solve missed its threshold before the run stops
  SurfaceTension surface_tension;
  BodyContact body_contact;  // between rigid bodies and with walls (scene_body.hpp)
};

/// The skin without solver.neighbor_skin: 0.3 spacings for wcsph, where a step moves a particle a
/// few hundredths of a spacing and the lists then serve about 4 steps (bench/results/notes.md,
/// "Neighbour lists with a skin"); 0 for dfsph and iisph, whose steps are about 6 times longer,
/// so that a skin that small would be outrun every step.
inline double default_neighbor_skin(Scheme scheme) { return scheme == Scheme::wcsph ? 0.3 : 0; }

struct Time {
  double start = 0;
  double end = 1;
  double output_interval = 0.01;
};

/// The per-particle fields a scene may ask the output to write: the one list the scene reader
/// checks names against and docs/scenes.md documents.
inline constexpr std::array<std::string_view, 8> output_field_names{"position",     "velocity", "density", "pressure",
                                                                    "acceleration", "mass",     "id",      "phase"};

/// The recovery of one fluid from a region (docs/scenes.md, "output.recovery"): the share of the
/// mass of `material` in `region` at the start that is no longer there, 1 − M(t)/M(0), the oil
/// recovery of a cavity (Zhou et al. 2010).
struct Recovery {
  std::size_t material = 0;  // index into Scene::materials
  Box region;
};

struct Output {
  std::vector<std::string> fields{"position", "velocity", "density", "pressure"};
  double probe_interval = 0.01;  // s between probe rows; the reader sets time.output_interval when the file has none
  std::optional<Recovery> recovery;  // written to recovery.csv every probe_interval
  bool vtk = false;                  // each frame also as a VTK file, and a .pvd collection
};

/// What a probe measures (docs/scenes.md, "probes"): the pressure at its position, or the height
/// of the free surface above its position along the up (−gravity) direction.
enum class ProbeType { pressure, water_height };

/// A pressure sensor's sensing face (docs/scenes.md, "probes"): a disc (3D) or a segment (2D) of
/// `diameter` centred on the probe's position, perpendicular to `normal`.
struct ProbeSensor {
  double diameter = 0;  // m
  Vec normal{};         // the face's normal, any length but 0
};

struct Probe {
  std::string name;  // the probe's column in probes.csv
  ProbeType type = ProbeType::pressure;
  Vec position{};
  std::optional<ProbeSensor> sensor;  // pressure only; none: the reading at the point
};

/// `count` agents spread evenly over a region (docs/crowds.md, "Agents"), walking to the nearest
/// exit or, with a heading, along it (a corridor without exits).
/// How a group's agents stand at the start (solvers/agent_placement.hpp).
enum class AgentPlacement {
  lattice,  // a square (or, too dense for it, hexagonal) lattice centred in the region
  random,   // uniformly at random, a body diameter or more apart (random sequential addition)
};

struct AgentGroup {
  Box region;
  std::size_t count = 0;
  std::optional<Vec> heading;  // unit vector
  AgentPlacement placement = AgentPlacement::lattice;
};

/// A region that removes and counts every agent that enters it: the space beyond a door.
struct CrowdExit {
  std::string name;  // its column in crowd.csv
  Box region;
};

/// Each agent's desired (free walking) speed, drawn once from a normal distribution truncated at
/// three deviations: 1.34 ± 0.26 m/s (Helbing & Molnár 1995, Sec. III, after Henderson 1971).
struct DesiredSpeed {
  double mean = 1.34;       // m/s
  double deviation = 0.26;  // m/s
  std::uint64_t seed = 1;   // of the generator: the same seed, the same speeds
};

/// A crowd (solver.scheme "crowd", docs/crowds.md): each agent a particle of an SPH crowd (van
/// Toll et al. 2021), with the social-force constants of Helbing, Farkas & Vicsek 2000.
struct Crowd {
  std::vector<AgentGroup> agents;
  std::vector<CrowdExit> exits;
  DesiredSpeed desired_speed;
  double comfortable_density = 2;    // persons/m², ρ_c: no uneasiness up to it
  double stiffness = 1;              // K, m⁴/s²: uneasiness p = K max(ρ − ρ_c, 0)
  double relaxation_time = 0.5;      // s, τ
  double time_gap = 1;               // s, T of the speed from the space ahead (Tordeux et al. 2016)
  double agent_length = 0.4;         // m, ℓ: the headway at which an agent stops, a body's diameter
  double steering_strength = 8;      // a: how far the agents close by turn one's walking direction
  double steering_range = 0.1;       // m, D: the range of that turning (Tordeux et al. 2016, eq. 5)
  double agent_mass = 80;            // kg, m
  double body_radius = 0.2;          // m, r (JuPedSim's collision-free speed model; docs/crowds.md)
  double repulsion_strength = 2000;  // N, A
  double repulsion_range = 0.08;     // m, B
  double body_stiffness = 1.2e5;     // kg/s², k
  double navigation_cell = 0.1;      // m: the cell of the distance field to the exits
};

struct Scene {
  std::string source;  // file the scene came from, for messages
  int dimension = 2;
  double particle_spacing = 0;
  KernelType kernel = KernelType::wendland_c2;
  double smoothing_ratio = 1.3;  // h / particle spacing
  Domain domain;
  std::vector<Material> materials;
  std::vector<FluidBlock> fluid;
  Walls walls;
  Vec gravity{0, -9.81, 0};
  Solver solver;
  Time time;
  Output output;
  std::vector<Probe> probes;
  std::optional<Crowd> crowd;  // solver.scheme "crowd": the agents instead of materials and fluid
};

/// Per material, whether the fluid uses it: a fluid block starts with it, or the inflow injects it.
inline std::vector<bool> fluid_materials_used(const Scene& scene) {
  std::vector<bool> used(scene.materials.size(), false);
  for (const FluidBlock& block : scene.fluid)
    if (block.material < used.size()) used[block.material] = true;
  if (scene.domain.inflow && scene.domain.inflow->phase && *scene.domain.inflow->phase < used.size())
    used[*scene.domain.inflow->phase] = true;
  return used;
}

/// The number of distinct materials the fluid uses (fluid_materials_used): more than one makes
/// the scene multiphase (a phase index per particle, the number-density formulation).
inline std::size_t fluid_material_count(const Scene& scene) {
  const std::vector<bool> used = fluid_materials_used(scene);
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
}

/// The largest ratio of the rest densities of the fluid's materials (1 for one material).
inline double fluid_density_ratio(const Scene& scene) {
  const std::vector<bool> used = fluid_materials_used(scene);
  double lightest = 0, densest = 0;
  for (std::size_t k = 0; k < used.size(); ++k) {
    if (!used[k]) continue;
    const double rho0 = scene.materials[k].rest_density;
    lightest = lightest == 0 ? rho0 : std::min(lightest, rho0);
    densest = std::max(densest, rho0);
  }
  return lightest > 0 ? densest / lightest : 1;
}

/// The largest fluid_density_ratio the incompressible schemes (dfsph, iisph) take: up to 10 their
/// pressure solve holds two layers at rest in a closed box (spurious speeds below 0.06 sqrt(g L)
/// over 7 s); at 30 it diverged within 4 s (docs/multiphase.md, "Incompressible schemes").
/// WCSPH takes 1000.
inline constexpr double max_incompressible_density_ratio = 10;

}  // namespace tide::scene
