#include <array>

#include "scene_keys.hpp"
#include "scene_sections.hpp"

namespace tide::io {

std::span<const Key<scene::Solver>> solver_keys() {
  static constexpr std::array<Key<scene::Solver>, 28> keys{{
      {"scheme", "string: `\"wcsph\"`, `\"dfsph\"`, `\"iisph\"` or `\"crowd\"`", "–", "`\"wcsph\"`",
       "Weakly compressible SPH, or an incompressible scheme: divergence-free SPH (Bender & Koschier 2015, 2017) or "
       "implicit incompressible SPH (Ihmsen et al. 2014); see [Incompressible schemes](#incompressible-schemes). "
       "Several fluid materials run with every scheme; `dfsph` and `iisph` take rest densities at most 10 times apart "
       "and no surface tension ([multiphase.md](multiphase.md#incompressible-schemes-dfsph-iisph)). `crowd` moves the "
       "agents of the `crowd` section instead ([crowds.md](crowds.md)).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.scheme = values.choice(value, scheme_names);
       }},
      {"equation_of_state", "string: `\"tait\"` or `\"linear\"`", "–", "`\"tait\"`",
       "p = ρ₀c₀²/γ ((ρ/ρ₀)^γ − 1), or p = c₀² (ρ − ρ₀).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.equation_of_state = values.choice(value, equation_of_state_names);
       }},
      {"tait_exponent", "number > 0", "–", "`7`", "γ of the Tait equation.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.tait_exponent = values.number(value, positive);
       }},
      {"density", "string: `\"summation\"` or `\"continuity\"`", "–", "`\"summation\"`",
       "Density by kernel summation, or integrated by the continuity equation with δ-SPH diffusion; with "
       "`clamp_negative_pressure`, a free-surface particle's integrated density is held at ρ₀ or above (p = 0 at "
       "a free surface), so a splash does not carry the memory of its stretching.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.density = values.choice(value, density_method_names);
       }},
      {"delta_sph", "number ≥ 0", "–", "`0.1`",
       "δ of the δ-SPH diffusion term (Molteni & Colagrossi 2009; continuity density only).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.delta_sph = values.number(value, non_negative);
       }},
      {"riemann_solver", "string: `\"none\"` or `\"low_dissipation\"`", "–", "`\"none\"`",
       "`wcsph` with `continuity` density, one fluid, no rigid bodies or artificial stress: `low_dissipation` takes "
       "each pair's pressure in the momentum equation and velocity in the continuity equation from a linearised "
       "acoustic Riemann problem between the two particles (Zhang, Hu & Adams 2017), its dissipation limited to "
       "approaching pairs; the continuity equation's Riemann term replaces δ-SPH (`delta_sph` is not used), with "
       "the hydrostatic pressure difference taken out. Walls are right states with their extrapolated pressure, "
       "moving with the wall. Measured on Buchner's dam break: [wall-pressure.md](wall-pressure.md).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.riemann_solver = values.choice(value, riemann_solver_names);
       }},
      {"kernel_gradient_correction", "boolean", "–", "`false`",
       "With `riemann_solver` `\"low_dissipation\"` only: the momentum equation's pressure term takes the "
       "renormalised kernel gradient L_i ∇W_ij, L_i = (Σ_j V_j ∇W_ij ⊗ (x_j − x_i))⁻¹ (Bonet & Lok 1999), symmetrised "
       "between fluid particles as ½ (L_i + L_j) ∇W_ij; L = I where det L⁻¹ < 0.1 (a splash). Costs one more "
       "neighbour pass per step when on; nothing when off. Measured: [wall-pressure.md](wall-pressure.md).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.kernel_gradient_correction = values.boolean(value);
       }},
      {"viscosity", "string: `\"artificial\"` or `\"laminar\"`", "–", "`\"artificial\"`",
       "Monaghan artificial viscosity, or laminar viscosity (Morris, Fox & Zhu 1997) from `kinematic_viscosity`.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.viscosity = values.choice(value, viscosity_model_names);
       }},
      {"alpha", "number ≥ 0", "–", "`0.02`", "Artificial viscosity, linear term.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.alpha = values.number(value, non_negative);
       }},
      {"beta", "number ≥ 0", "–", "`0`", "Artificial viscosity, quadratic term.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.beta = values.number(value, non_negative);
       }},
      {"cfl", "number > 0", "–", "`0.25`",
       "Acoustic limit: Δt ≤ cfl · h / (c₀ + |v|max). Above 1 `tide run` and `tide check` warn (but run): explicit "
       "WCSPH steps are not known to be stable there; the tank at rest of [stability.md](stability.md#time-step) goes "
       "unstable from 2.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.cfl = values.number(value, positive);
       }},
      {"viscous_number", "number > 0", "–", "`0.125`", "Viscous limit: Δt ≤ viscous_number · h² / ν.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.viscous_number = values.number(value, positive);
       }},
      {"force_number", "number > 0", "–", "`0.25`", "Force limit: Δt ≤ force_number · sqrt(h / |a|max).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.force_number = values.number(value, positive);
       }},
      {"max_density_ratio", "number > 1", "–", "`1.5`",
       "Stability band: a run whose ρ/ρ₀ leaves [1/ratio, ratio] stops as unstable (the lower bound only with "
       "`continuity` density: summation density is naturally low at a free surface, and a continuity free-surface "
       "particle's density is held at ρ₀ or above, so the lower bound meets the bulk only).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.max_density_ratio = values.number(value, above_one);
       }},
      {"max_mach_number", "number > 0", "–", "`1`",
       "Stability band: a run with a particle faster than max_mach_number × c₀ stops as unstable (exit code 3). A "
       "weakly compressible flow stays near 0.1.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.max_mach_number = values.number(value, positive);
       }},
      {"clamp_negative_pressure", "boolean", "–", "`true`",
       "p = max(p, 0) for fluid and wall particles: a free surface, where the kernel is only partly filled, then "
       "exerts no tension that would clump particles. Switch off for flows that need tension (closed or periodic "
       "domains). With `dfsph` and `iisph`, `false` makes the pressure solve two-sided, aimed at the mean density (a "
       "closed domain fixes the volume; see [Incompressible schemes](#incompressible-schemes)).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.clamp_negative_pressure = values.boolean(value);
       }},
      {"gravity_ramp_time", "number ≥ 0", "s", "`0`",
       "Gravity rises smoothly from zero, g(t) = g (sin(π (t/t_ramp − ½)) + 1)/2, over this time after the start "
       "(Adami, Hu & Adams 2012), so a column at rest is loaded without a start-up pressure wave. `0`: full gravity "
       "from the start.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.gravity_ramp_time = values.number(value, non_negative);
       }},
      {"background_pressure", "number ≥ 0", "Pa", "`0`",
       "Added to the equation of state: p = p(ρ) + p_b. Keeps pressures positive in closed or periodic flows without a "
       "free surface (Morris, Fox & Zhu 1997; Adami, Hu & Adams 2013), away from the tensile instability. Leave at 0 "
       "with a free surface.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.background_pressure = values.number(value, non_negative);
       }},
      {"max_density_error", "number in (0, 1]", "–", "`0.0005`",
       "`dfsph`, `iisph`: a pressure solve ends when the mean density error of its particles is below this share of ρ₀ "
       "(0.05%).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.max_density_error = values.number(value, in_unit_interval);
       }},
      {"max_divergence_error", "number in (0, 1]", "–", "`0.001`",
       "`dfsph`: the divergence solve ends when the mean of |Δt Dρ/Dt| is below this share of ρ₀.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.max_divergence_error = values.number(value, in_unit_interval);
       }},
      {"max_solver_iterations", "integer in [1, 10⁶]", "–", "`100`",
       "`dfsph`, `iisph`: Jacobi sweeps (or conjugate-gradient iterations) per solve at most. A solve that reaches the "
       "cap above its threshold logs a "
       "warning with the step and the error.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.max_solver_iterations = values.count(value);
       }},
      {"pressure_solver", "`jacobi` or `conjugate_gradients`", "–", "`jacobi`",
       "`dfsph`, `iisph`: `jacobi`, projected Jacobi sweeps stopped by the mean density error; "
       "`conjugate_gradients`, preconditioned conjugate gradients on the pressure equation made symmetric by the "
       "walls' adjoint term, stopped also by an energy-norm error estimate that sees smooth errors: the 2D tank's "
       "pressure error 5× smaller, DFSPH Taylor–Green within 2%, the DFSPH 2D dam break 2.6× slower (see "
       "[Incompressible schemes](#incompressible-schemes)). One fluid only; several fluids keep the Jacobi sweeps.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.pressure_solver = values.choice(value, pressure_solver_names);
       }},
      {"max_failed_solves", "integer in [1, 10⁶]", "–", "`10`",
       "`dfsph`, `iisph`: that many consecutive steps with a missed solve stop the run as unstable (exit code 3), "
       "naming the most compressed particle.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.max_failed_solves = values.count(value);
       }},
      {"shifting", "string: `\"none\"` or `\"fickian\"`", "–", "`\"none\"`",
       "Particle shifting after each step: δr = −D Σ [1 + 0.2 (W/W(Δx))⁴] V ∇W (Lind et al. 2012) with D = 4 h |v|max "
       "Δt (Sun et al. 2017), at most h²/2 (the stability limit of Lind et al. 2012), which keeps the particles from "
       "pairing along the stagnation lines of a vortex. Near a free surface (∇·r < d − ½, Lind et al. 2012) only the "
       "part of the shift along the surface is kept; isolated particles (∇·r < d/2) are not shifted. Positions only: "
       "velocity and density are not corrected for the shift. Costs two extra neighbour passes per step when on; "
       "nothing when off.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.shifting = values.choice(value, shifting_names);
       }},
      {"artificial_stress", "number ≥ 0", "–", "`0` (off)",
       "ε of the artificial stress against the tensile instability (Monaghan 2000; Gray, Monaghan & Swift 2001): each "
       "pair's pressure term gains (R_i + R_j)(W(r)/W(Δx))⁴ with R_i = ε |p_i|/ρ_i² where p_i < 0 (none under "
       "compression), a short-range repulsion that keeps particles in tension from clumping in pairs. 0.2 is "
       "Monaghan's value for fluids, with the cubic spline at h = 1.3 Δx; with Wendland C2 at h = 1.7 Δx the term is "
       "weaker ([stability.md](stability.md#tension)). Only acts on negative pressures, so pair it with "
       "`clamp_negative_pressure: false`. Costs one kernel evaluation per pair when on; nothing when off (a separately "
       "compiled pass).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.artificial_stress = values.number(value, non_negative);
       }},
      {"neighbor_skin", "number ≥ 0", "particle spacings", "`0.3` for `wcsph`, `0` for `dfsph` and `iisph`",
       "How far the neighbour lists reach beyond the kernel support (a Verlet list with a skin). The fluid is "
       "re-sorted and the candidate lists rebuilt only when some particle has moved half the skin since the last "
       "build, left the domain box, or the particle count changed; every step then keeps the candidates inside the "
       "support, so the pairs the passes see are exactly those of a list rebuilt every step (in another order, so "
       "results agree to rounding, not bitwise). On the 3D dam break a WCSPH step moves a particle a few hundredths of "
       "a spacing and 0.3 rebuilds every 4 steps, 1.5× faster per step; an incompressible step moves it about 6 times "
       "as far and gains nothing from a skin this size ([performance.md](performance.md)). Cells widen to support + "
       "skin, which costs memory: the candidate lists and the positions at the build, 304 B per fluid particle at 0.3 "
       "(3D dam break, 10^6 particles: 669 B held in all, against 352 B at 0; `memory_report --skin`). `0`: sort and "
       "rebuild every step. Reduced where a periodic axis would hold fewer than 3 cells.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         solver.neighbor_skin = values.number(value, non_negative);
       }},
      {"surface_tension", "object", "–", "none",
       "Surface tension and wetting, WCSPH only (refused for `dfsph` and `iisph`): `model` (*required*: `\"csf\"`, "
       "`\"akinci\"` or `\"pairwise\"`), `coefficient` (number > 0, N/m; N in 2D; *required*: σ, or Akinci's γ for "
       "`akinci`), `contact_angle` (degrees in (0, 180), default `90`; `pairwise` only: the static angle measured "
       "through the first fluid material), `adhesion` (number ≥ 0, default `0`; `akinci` only: the wall adhesion β), "
       "`unlike_attraction` (`true` or `false`, default `true`; `pairwise` only, two fluids: whether unlike fluid "
       "particles attract; `false` gives the same σ and contact angle with less lattice cohesion, so contact lines "
       "move). `csf` needs exactly two fluid materials. What each model does, and the settings it needs to stay "
       "stable: [multiphase.md](multiphase.md).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         read_section(values, value, surface_tension_keys(), solver.surface_tension);
       }},
      {"body_contact", "object", "–", "the defaults of its keys",
       "How rigid bodies touch one another and the walls: `restitution`, `friction`, `frequency` "
       "([bodies.md](bodies.md), \"Contact\").",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Solver& solver) {
         read_section(values, value, body_contact_keys(), solver.body_contact);
       }},
  }};
  return keys;
}

// Each model's own keys: a key of another model is refused rather than ignored.
std::span<const Key<scene::SurfaceTension>> surface_tension_keys() {
  static constexpr std::array<Key<scene::SurfaceTension>, 5> keys{{
      {"model", "string: `\"csf\"`, `\"akinci\"` or `\"pairwise\"`", "–", "",
       "csf: continuum surface force between two fluids (Brackbill et al. 1992; Morris 2000); akinci: cohesion "
       "and surface-area minimisation with wall adhesion (Akinci et al. 2013); pairwise: inter-particle forces "
       "whose fluid–wall strength sets the contact angle (Tartakovsky & Meakin 2005).",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::SurfaceTension& tension) {
         tension.model = values.choice(value, surface_tension_model_names);
       }},
      {"coefficient", "number > 0", "N/m (2D: N)", "", "σ, or Akinci's γ for `akinci`.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::SurfaceTension& tension) {
         tension.coefficient = values.number(value, positive);
       }},
      {"contact_angle", "degrees in (0, 180)", "°", "`90`",
       "`pairwise` only: the static contact angle, measured through the first fluid material.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::SurfaceTension& tension) {
         if (tension.model != scene::SurfaceTensionModel::pairwise)
           values.fail(value,
                       "no contact_angle: only the pairwise model sets the wetting by an angle (akinci: adhesion)");
         tension.contact_angle =
             values.number(value, "an angle in degrees in (0, 180)", [](double x) { return x > 0 && x < 180; });
       }},
      {"adhesion", "number ≥ 0", "–", "`0`", "`akinci` only: the wall adhesion β.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::SurfaceTension& tension) {
         if (tension.model != scene::SurfaceTensionModel::akinci)
           values.fail(value,
                       "no adhesion: only the akinci model has a wall adhesion coefficient (pairwise: contact_angle)");
         tension.adhesion = values.number(value, non_negative);
       }},
      {"unlike_attraction", "boolean", "–", "`true`",
       "`pairwise` only, two fluids: whether unlike fluid particles attract; `false` gives the same σ and contact "
       "angle with less lattice cohesion, so contact lines move.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::SurfaceTension& tension) {
         if (tension.model != scene::SurfaceTensionModel::pairwise)
           values.fail(value, "no unlike_attraction: only the pairwise model has pair strengths between fluids");
         tension.unlike_attraction = values.boolean(value);
       }},
  }};
  return keys;
}

void read_solver(const ValueReader& values, const Node& node, scene::Scene& scene) {
  read_section(values, node, solver_keys(), scene.solver);
}

}  // namespace tide::io
