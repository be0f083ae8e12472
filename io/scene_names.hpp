#pragma once

// The spellings of the scene model's enumerators in scene files: what the reader accepts, and
// the names of the fuzz dictionary.

#include <array>
#include <string_view>

#include "tide/core/scene.hpp"

namespace tide::io {

/// An enumerator with its spelling in scene files.
template <class E>
struct Named {
  std::string_view name;
  E value;
};

inline constexpr std::array<Named<scene::Scheme>, 4> scheme_names{{{"wcsph", scene::Scheme::wcsph},
                                                                   {"dfsph", scene::Scheme::dfsph},
                                                                   {"iisph", scene::Scheme::iisph},
                                                                   {"crowd", scene::Scheme::crowd}}};
inline constexpr std::array<Named<scene::EquationOfState>, 2> equation_of_state_names{
    {{"tait", scene::EquationOfState::tait}, {"linear", scene::EquationOfState::linear}}};
inline constexpr std::array<Named<scene::DensityMethod>, 2> density_method_names{
    {{"summation", scene::DensityMethod::summation}, {"continuity", scene::DensityMethod::continuity}}};
inline constexpr std::array<Named<scene::ViscosityModel>, 2> viscosity_model_names{
    {{"artificial", scene::ViscosityModel::artificial}, {"laminar", scene::ViscosityModel::laminar}}};
inline constexpr std::array<Named<scene::Shifting>, 2> shifting_names{
    {{"none", scene::Shifting::none}, {"fickian", scene::Shifting::fickian}}};
inline constexpr std::array<Named<scene::SurfaceTensionModel>, 3> surface_tension_model_names{
    {{"csf", scene::SurfaceTensionModel::csf},
     {"akinci", scene::SurfaceTensionModel::akinci},
     {"pairwise", scene::SurfaceTensionModel::pairwise}}};
inline constexpr std::array<Named<scene::PressureSolver>, 2> pressure_solver_names{
    {{"jacobi", scene::PressureSolver::jacobi}, {"conjugate_gradients", scene::PressureSolver::conjugate_gradients}}};
inline constexpr std::array<Named<scene::RiemannSolver>, 2> riemann_solver_names{
    {{"none", scene::RiemannSolver::none}, {"low_dissipation", scene::RiemannSolver::low_dissipation}}};
inline constexpr std::array<Named<scene::WallSlip>, 2> wall_slip_names{
    {{"no_slip", scene::WallSlip::no_slip}, {"free_slip", scene::WallSlip::free_slip}}};
/// A mesh file's length unit, in metres.
inline constexpr std::array<Named<double>, 3> mesh_unit_names{{{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}}};
inline constexpr std::array<Named<scene::AgentPlacement>, 2> agent_placement_names{
    {{"lattice", scene::AgentPlacement::lattice}, {"random", scene::AgentPlacement::random}}};
inline constexpr std::array<Named<scene::ProbeType>, 2> probe_type_names{
    {{"pressure", scene::ProbeType::pressure}, {"water_height", scene::ProbeType::water_height}}};

}  // namespace tide::io
