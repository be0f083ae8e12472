#include "case_support.hpp"

#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "tide/solvers/probes.hpp"

namespace tide::validation {

double smoothing_ratio_for(KernelType kernel) {
  return kernel == KernelType::wendland_c2 || kernel == KernelType::wendland_c4 ? 1.7 : 1.3;
}

void apply_variant(scene::Scene& scene, const Variant& variant) {
  if (variant.scheme == "wcsph") {
    scene.solver.density = scene::DensityMethod::summation;
  } else if (variant.scheme == "wcsph_continuity") {
    scene.solver.density = scene::DensityMethod::continuity;
    scene.solver.delta_sph = 0.1;
  } else if (variant.scheme == "wcsph_riemann" || variant.scheme == "wcsph_riemann_kgc") {
    scene.solver.density = scene::DensityMethod::continuity;
    scene.solver.riemann_solver = scene::RiemannSolver::low_dissipation;
    scene.solver.kernel_gradient_correction = variant.scheme.ends_with("_kgc");
  } else if (variant.scheme == "dfsph" || variant.scheme == "dfsph_cg") {
    scene.solver.scheme = scene::Scheme::dfsph;
  } else if (variant.scheme == "iisph" || variant.scheme == "iisph_cg") {
    scene.solver.scheme = scene::Scheme::iisph;
  } else {
    throw std::invalid_argument("unknown scheme \"" + variant.scheme + "\"");
  }
  if (variant.scheme.ends_with("_cg")) scene.solver.pressure_solver = scene::PressureSolver::conjugate_gradients;
  scene.kernel = variant.kernel;
  scene.smoothing_ratio = smoothing_ratio_for(variant.kernel);
  scene.walls.layers = scene::required_wall_layers(scene.kernel, scene.smoothing_ratio);
}

scene::Scene water_tank(int dimension, double width, double depth, double rim, double spacing,
                        const scene::Material& water, const Variant& variant) {
  scene::Scene s;
  s.dimension = dimension;
  s.particle_spacing = spacing;
  s.materials.push_back(water);
  const int up = dimension - 1;
  scene::Vec top{width, width, width}, wall_top{width, width, width};
  top[up] = depth;
  wall_top[up] = rim;
  if (dimension == 2) top[2] = wall_top[2] = 0;
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, top}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, wall_top}, true};
  apply_variant(s, variant);
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * spacing, dimension);
  s.gravity = {0, 0, 0};
  s.gravity[up] = -9.81;
  s.solver.alpha = 0.1;
  return s;
}

Curve read_reference(const std::string& file, int x_column, int y_column) {
  const std::string path = std::string(TIDE_VALIDATION_DATA_DIR) + "/" + file;
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the reference table");
  Curve curve;
  std::string line;
  bool header_seen = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    std::vector<double> values;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) values.push_back(field.empty() ? NAN : std::stod(field));
    if (line.back() == ',') values.push_back(NAN);  // an empty last column (getline does not return it)
    const auto needed = static_cast<std::size_t>(std::max(x_column, y_column));
    if (values.size() <= needed) throw std::runtime_error(path + ": a row has fewer columns than expected");
    if (std::isnan(values[static_cast<std::size_t>(y_column)])) continue;
    curve.x.push_back(values[static_cast<std::size_t>(x_column)]);
    curve.y.push_back(values[static_cast<std::size_t>(y_column)]);
  }
  if (curve.x.empty()) throw std::runtime_error(path + ": no data rows");
  return curve;
}

template <int D>
Vector<D> shepard_velocity(const Simulation<D>& simulation, const Vector<D>& point) {
  const auto v = simulation.fluid()[simulation.fluid_fields().velocity];
  return shepard_interpolation<D>(
      simulation, point, [&](Index j, const Vector<D>&) { return Vector<D>(v[j]); },
      Vector<D>(Vector<D>::Constant(std::numeric_limits<Real>::quiet_NaN())));
}

template Vector<2> shepard_velocity<2>(const Simulation<2>&, const Vector<2>&);
template Vector<3> shepard_velocity<3>(const Simulation<3>&, const Vector<3>&);

}  // namespace tide::validation
