#include "tide/solvers/capabilities.hpp"

#include <string>

#include "simulation_setup.hpp"
#include "tide/core/scene_error.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide {
namespace {

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "\"" + std::string(...).
std::string quoted_scheme(scene::Scheme scheme) {
  std::string text = "\"";
  text += scheme_name(scheme);
  text += '"';
  return text;
}

[[noreturn]] void refuse(const scene::Scene& scene, std::string path, std::string supported, std::string found) {
  throw scene::SceneError(scene.source, std::move(path), std::move(supported), std::move(found));
}

/// The multiphase formulation is number-density summation (docs/multiphase.md): a continuity
/// density or an artificial stress per material is not implemented; the incompressible schemes'
/// pressure solve holds density ratios up to scene::max_incompressible_density_ratio.
void check_phases(const scene::Scene& scene, std::size_t fluids) {
  const scene::Solver& solver = scene.solver;
  if (fluids < 2) return;
  const double ratio = scene::fluid_density_ratio(scene);
  if (solver.scheme != scene::Scheme::wcsph && ratio > scene::max_incompressible_density_ratio) {
    const std::string limit = setup::format_number(scene::max_incompressible_density_ratio);
    refuse(scene, "/solver/scheme",
           "\"wcsph\" for fluids whose rest densities differ by more than " + limit +
               " times (multiphase dfsph and iisph take " + limit + ")",
           quoted_scheme(solver.scheme) + " with a ratio of " + setup::format_number(ratio));
  }
  if (solver.density != scene::DensityMethod::summation)
    refuse(scene, "/solver/density", "\"summation\" for a scene with several fluid materials (number density)",
           "\"continuity\"");
  if (solver.artificial_stress > 0)
    refuse(scene, "/solver/artificial_stress", "0 for a scene with several fluid materials",
           setup::format_number(solver.artificial_stress));
}

/// Surface tension is implemented in the WCSPH momentum pass only; csf takes the colour gradient
/// between exactly two fluids, and no model pairs more than two.
void check_surface_tension(const scene::Scene& scene, std::size_t fluids) {
  const scene::SurfaceTensionModel model = scene.solver.surface_tension.model;
  if (model == scene::SurfaceTensionModel::none) return;
  if (scene.solver.scheme != scene::Scheme::wcsph)
    refuse(scene, "/solver/scheme", "\"wcsph\" with surface tension", quoted_scheme(scene.solver.scheme));
  if (model == scene::SurfaceTensionModel::csf && fluids != 2)
    refuse(scene, "/solver/surface_tension/model", "a model for this scene: \"csf\" needs exactly two fluid materials",
           "\"csf\" with " + std::to_string(fluids) + " fluid material" + (fluids == 1 ? "" : "s"));
  if (fluids > 2)
    refuse(scene, "/solver/surface_tension/model", "surface tension between at most two fluid materials",
           std::to_string(fluids) + " fluid materials");
}

/// Rigid bodies (obstacles with a "body") feel the WCSPH momentum pass's pressure and viscous
/// forces, of one fluid or several (passes/body_force.hpp): not yet the incompressible schemes'
/// pressure solve, the artificial stress, or surface tension, whose adhesion to walls would act
/// on the fluid without its reaction on the body.
void check_bodies(const scene::Scene& scene) {
  for (std::size_t k = 0; k < scene.walls.obstacles.size(); ++k) {
    if (!scene.walls.obstacles[k].body) continue;
    const std::string path = "/walls/obstacles/" + std::to_string(k) + "/body";
    if (scene.solver.scheme != scene::Scheme::wcsph)
      refuse(scene, "/solver/scheme", "\"wcsph\" with a rigid body (" + path + ")", quoted_scheme(scene.solver.scheme));
    if (scene.solver.surface_tension.model != scene::SurfaceTensionModel::none)
      refuse(scene, "/solver/surface_tension/model", "\"none\" in a scene with a rigid body (" + path + ")",
             "a surface-tension model");
    if (scene.solver.artificial_stress > 0)
      refuse(scene, "/solver/artificial_stress", "0 in a scene with a rigid body (" + path + ")",
             setup::format_number(scene.solver.artificial_stress));
  }
}

/// The Riemann-solver WCSPH (passes/riemann.hpp) is written for one fluid integrated by the
/// continuity equation, with its own pressure term: not for number density, the artificial
/// stress, or the bodies, whose force pass takes Monaghan's pressure term.
void check_riemann(const scene::Scene& scene, std::size_t fluids) {
  const scene::Solver& solver = scene.solver;
  if (solver.kernel_gradient_correction && solver.riemann_solver == scene::RiemannSolver::none)
    refuse(scene, "/solver/kernel_gradient_correction",
           "false without solver.riemann_solver \"low_dissipation\" (the correction is implemented in its momentum "
           "pass)",
           "true");
  if (solver.riemann_solver == scene::RiemannSolver::none) return;
  const std::string path = "/solver/riemann_solver";
  const std::string found = "\"low_dissipation\"";
  if (solver.scheme != scene::Scheme::wcsph)
    refuse(scene, path, "\"none\" for solver.scheme " + quoted_scheme(solver.scheme), found);
  if (solver.density != scene::DensityMethod::continuity)
    refuse(scene, path, "\"none\" with summation density (the Riemann scheme integrates the continuity equation)",
           found);
  if (fluids > 1) refuse(scene, path, "\"none\" for a scene with several fluid materials", found);
  if (solver.artificial_stress > 0) refuse(scene, path, "\"none\" with an artificial stress", found);
  for (std::size_t k = 0; k < scene.walls.obstacles.size(); ++k) {
    if (scene.walls.obstacles[k].body)
      refuse(scene, path, "\"none\" in a scene with a rigid body (/walls/obstacles/" + std::to_string(k) + "/body)",
             found);
  }
}

/// A crowd (docs/crowds.md) walks on the floor plane among fixed walls; the crowd scheme moves
/// agents and nothing else, and agents only the crowd scheme.
void check_crowd(const scene::Scene& scene) {
  const bool crowd_scheme = scene.solver.scheme == scene::Scheme::crowd;
  if (crowd_scheme && !scene.crowd)
    refuse(scene, "/crowd", "a crowd section (agents and exits) for solver.scheme \"crowd\"", "nothing");
  if (!crowd_scheme && scene.crowd)
    refuse(scene, "/solver/scheme", "\"crowd\" for a scene with a crowd section", quoted_scheme(scene.solver.scheme));
  if (!crowd_scheme) return;
  if (scene.dimension != 2)
    refuse(scene, "/dimension", "2 for solver.scheme \"crowd\" (agents walk on the floor plane)",
           std::to_string(scene.dimension));
  for (std::size_t k = 0; k < scene.walls.obstacles.size(); ++k) {
    const scene::Obstacle& obstacle = scene.walls.obstacles[k];
    const std::string path = "/walls/obstacles/" + std::to_string(k);
    if (obstacle.motion) refuse(scene, path + "/motion", "fixed walls in a crowd scene", "a motion");
    if (obstacle.body) refuse(scene, path + "/body", "fixed walls in a crowd scene", "a body");
  }
}

}  // namespace

void check_capabilities(const scene::Scene& scene) {
  check_crowd(scene);
  const std::size_t fluids = scene::fluid_material_count(scene);
  check_phases(scene, fluids);
  check_surface_tension(scene, fluids);
  check_bodies(scene);
  check_riemann(scene, fluids);
  // The phase index exists in multiphase scenes only.
  for (std::size_t k = 0; k < scene.output.fields.size(); ++k) {
    if (scene.output.fields[k] == "phase" && fluids < 2)
      refuse(scene, "/output/fields/" + std::to_string(k),
             "a field this scene has (\"phase\" needs several fluid materials)", "\"phase\"");
  }
  // The inflow's buffer is applied at the end of a WCSPH step only.
  if (scene.domain.inflow && scene.solver.scheme != scene::Scheme::wcsph)
    refuse(scene, "/solver/scheme", "\"wcsph\" with a domain inflow", quoted_scheme(scene.solver.scheme));
}

}  // namespace tide
