#include "tide/serve/frame_snapshot.hpp"

#include <algorithm>
#include <cmath>

namespace tide::serve {
namespace {

void append_positions(const ParticleSet<2>& set, VectorField field, std::vector<float>& out) {
  const auto x = set[field];
  for (std::size_t i = 0; i < set.size(); ++i) {
    out.push_back(static_cast<float>(x.component[0][i]));
    out.push_back(static_cast<float>(x.component[1][i]));
  }
}

}  // namespace

Frame snapshot(const Simulation<2>& simulation, ColourField colour) {
  Frame frame;
  frame.time = simulation.time();
  frame.steps = simulation.step_count();
  frame.colour = colour;
  const scene::Scene& scene = simulation.scene();
  frame.view = {static_cast<float>(scene.domain.box.min[0]), static_cast<float>(scene.domain.box.min[1]),
                static_cast<float>(scene.domain.box.max[0]), static_cast<float>(scene.domain.box.max[1])};
  frame.particle_spacing = static_cast<float>(scene.particle_spacing);
  const ParticleSet<2>& fluid = simulation.fluid();
  const FluidFields<2>& fields = simulation.fluid_fields();
  frame.fluid.reserve(2 * fluid.size());
  append_positions(fluid, fields.position, frame.fluid);
  frame.colour_values.resize(fluid.size());
  const Real rest = simulation.rest_density();
  if (colour == ColourField::speed) {
    const auto v = fluid[fields.velocity];
    for (std::size_t i = 0; i < fluid.size(); ++i) frame.colour_values[i] = static_cast<float>(v[i].norm());
    const auto& material = scene.materials.front();
    frame.colour_high = static_cast<float>(material.max_speed.value_or(2.0));
  } else {
    const auto values = fluid[colour == ColourField::density ? fields.density : fields.pressure];
    for (std::size_t i = 0; i < fluid.size(); ++i) frame.colour_values[i] = static_cast<float>(values[i]);
    if (colour == ColourField::density) {
      frame.colour_low = static_cast<float>(0.97 * rest);
      frame.colour_high = static_cast<float>(1.03 * rest);
    } else {
      const auto highest = std::max_element(frame.colour_values.begin(), frame.colour_values.end());
      frame.colour_high = highest == frame.colour_values.end() ? 1.0f : std::max(*highest, 1.0f);
    }
  }
  const Interactions<2>& interactions = simulation.interactions();
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<2>& contact = interactions.contact(k);
    append_positions(contact.particles(), contact.fields().position, contact.moves() ? frame.obstacle : frame.walls);
  }
  return frame;
}

FluidSummary summarise(const Frame& frame, const Simulation<2>& simulation) {
  FluidSummary summary;
  const std::size_t n = frame.fluid.size() / 2;
  const auto v = simulation.fluid()[simulation.fluid_fields().velocity];
  for (std::size_t i = 0; i < n; ++i) {
    summary.mean_x += frame.fluid[2 * i];
    summary.mean_y += frame.fluid[2 * i + 1];
    const double speed = static_cast<double>(v[i].norm());
    summary.mean_speed += speed;
    summary.max_speed = std::max(summary.max_speed, speed);
  }
  if (n > 0) {
    summary.mean_x /= static_cast<double>(n);
    summary.mean_y /= static_cast<double>(n);
    summary.mean_speed /= static_cast<double>(n);
  }
  const std::size_t b = frame.obstacle.size() / 2;
  for (std::size_t i = 0; i < b; ++i) {
    summary.obstacle_x += frame.obstacle[2 * i] / static_cast<double>(b);
    summary.obstacle_y += frame.obstacle[2 * i + 1] / static_cast<double>(b);
  }
  return summary;
}

}  // namespace tide::serve
