#include "tide/solvers/simulation.hpp"

#include "tide/solvers/incompressible_sph.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {

template <int D>
std::unique_ptr<Simulation<D>> make_simulation(const scene::Scene& scene) {
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
  }
  return "unknown";
}

template std::unique_ptr<Simulation<2>> make_simulation<2>(const scene::Scene&);
template std::unique_ptr<Simulation<3>> make_simulation<3>(const scene::Scene&);

}  // namespace tide
