#include "tide/solvers/simulation.hpp"

#include "tide/solvers/capabilities.hpp"
#include "tide/solvers/crowd_sph.hpp"
#include "tide/solvers/incompressible_sph.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {

template <int D>
std::unique_ptr<Simulation<D>> make_simulation(const scene::Scene& scene) {
  // A crowd scene has no fluid for the fluid schemes to read: its refusals (3D, another scheme) come first.
  if (scene.solver.scheme == scene::Scheme::crowd || scene.crowd) check_capabilities(scene);
  if constexpr (D == 2) {
    if (scene.solver.scheme == scene::Scheme::crowd) return std::make_unique<CrowdSph>(scene);
  }
  if (scene.solver.scheme == scene::Scheme::wcsph) return std::make_unique<Wcsph<D>>(scene);
  return std::make_unique<IncompressibleSph<D>>(scene);
}

std::string_view scheme_name(scene::Scheme scheme) {
  switch (scheme) {
    case scene::Scheme::wcsph:
      return "wcsph";
    case scene::Scheme::dfsph:
      return "dfsph";
    case scene::Scheme::iisph:
      return "iisph";
    case scene::Scheme::crowd:
      return "crowd";
  }
  return "unknown";
}

template std::unique_ptr<Simulation<2>> make_simulation<2>(const scene::Scene&);
template std::unique_ptr<Simulation<3>> make_simulation<3>(const scene::Scene&);

}  // namespace tide
