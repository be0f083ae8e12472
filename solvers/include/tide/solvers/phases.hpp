#pragma once

#include <cstddef>
#include <vector>

#include "tide/core/scene.hpp"
#include "tide/solvers/equation_of_state.hpp"

namespace tide {

/// The constants of one fluid phase of a multiphase scene. A particle's phase is the index of its
/// material in Scene::materials.
struct Phase {
  Real rest_density;
  Real mass;               // ρ0 / Σ_k W(|k| Δx): every phase fills the same lattice
  Real dynamic_viscosity;  // η = ρ0 ν, for the laminar viscosity
  EquationOfState eos;
};

/// The phases of a scene, one per material (materials no fluid block uses included, so that the
/// material index is the phase index), and which of them colours the interface.
struct Phases {
  std::vector<Phase> table;
  std::size_t first_fluid = 0;  // the first material in `materials` that the fluid uses (scene::fluid_materials_used)
  Real lightest_density = 0;    // of the materials the fluid uses
  Real densest_density = 0;
  Real fastest_sound = 0;
  Real largest_kinematic_viscosity = 0;
};

}  // namespace tide
