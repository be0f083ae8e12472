#include "field_arrays.hpp"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/numpy.h>

#include "locked.hpp"

namespace py = pybind11;

namespace tide::python {
namespace {

/// Where a field's arrays are, taken under the handle's lock.
struct FieldLayout {
  AnySimulation simulation;  // the owner the views keep alive
  FieldKind kind = FieldKind::scalar;
  std::vector<const void*> components;
  std::size_t count = 0;
};

/// The fields of a fluid as the checks below need them.
struct FluidShape {
  std::vector<FieldInfo> fields;
  std::size_t count = 0;
};

const FieldInfo& find_field(const std::vector<FieldInfo>& fields, const std::string& name) {
  for (const FieldInfo& field : fields)
    if (field.name == name) return field;
  std::string known;
  for (const FieldInfo& field : fields) known += (known.empty() ? "" : ", ") + field.name;
  throw py::key_error("the fluid has no field '" + name + "' (it has: " + known + ")");
}

template <int D>
FieldLayout layout_of(const std::shared_ptr<Simulation<D>>& simulation, const std::string& name) {
  const ParticleSet<D>& fluid = simulation->fluid();
  const FieldInfo& field = find_field(fluid.fields(), name);
  FieldLayout layout{simulation, field.kind, {}, fluid.size()};
  if (field.kind == FieldKind::scalar) layout.components.push_back(fluid[fluid.scalar(name)].data());
  if (field.kind == FieldKind::index) layout.components.push_back(fluid[fluid.index(name)].data());
  if (field.kind == FieldKind::vector)
    for (const Real* component : fluid[fluid.vector(name)].component) layout.components.push_back(component);
  return layout;
}

/// A read-only array of the `count` values at `data`, which keeps `owner` alive.
template <class Value>
py::array view_of(const AnySimulation& owner, const void* data, std::size_t count) {
  const py::capsule keepalive(new AnySimulation(owner), [](void* held) { delete static_cast<AnySimulation*>(held); });
  py::array view(py::dtype::of<Value>(), {count}, {sizeof(Value)}, static_cast<const Value*>(data), keepalive);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

/// The values given for one field, checked against `shape` and copied: one vector per component.
struct FieldValues {
  std::string name;
  std::vector<std::vector<Real>> components;
};

FieldValues checked_values(const FluidShape& shape, const std::string& name, const py::handle& given) {
  const FieldInfo& field = find_field(shape.fields, name);
  if (field.kind == FieldKind::index)
    throw py::value_error("'" + name + "' is an index field the scheme keeps; only real fields can be set");
  const auto values = py::array_t<Real, py::array::c_style | py::array::forcecast>::ensure(given);
  if (!values) throw py::value_error("'" + name + "': expected an array of numbers");
  const auto n = static_cast<py::ssize_t>(shape.count);
  const py::ssize_t d = field.components;
  FieldValues result{name, std::vector<std::vector<Real>>(static_cast<std::size_t>(d))};
  const auto take = [&](py::ssize_t particle_stride, py::ssize_t component_stride) {
    for (py::ssize_t c = 0; c < d; ++c)
      for (py::ssize_t i = 0; i < n; ++i)
        result.components[std::size_t(c)].push_back(values.data()[i * particle_stride + c * component_stride]);
  };
  if (d == 1 && values.ndim() == 1 && values.shape(0) == n) {
    take(1, 0);
  } else if (d > 1 && values.ndim() == 2 && values.shape(0) == d && values.shape(1) == n) {
    take(1, n);
  } else if (d > 1 && values.ndim() == 2 && values.shape(0) == n && values.shape(1) == d) {
    take(d, 1);
  } else {
    std::string got;
    for (py::ssize_t k = 0; k < values.ndim(); ++k) got += (k ? ", " : "") + std::to_string(values.shape(k));
    const std::string expected = d == 1 ? "(" + std::to_string(n) + ")"
                                        : "(" + std::to_string(d) + ", " + std::to_string(n) + ") or (" +
                                              std::to_string(n) + ", " + std::to_string(d) + ")";
    throw py::value_error("'" + name + "': expected " + expected + " values for " + std::to_string(n) +
                          " particles, got shape (" + got + ")");
  }
  return result;
}

template <int D>
void copy_into(ParticleSet<D>& fluid, const std::vector<FieldValues>& assignments, std::size_t count) {
  if (fluid.size() != count)
    throw std::logic_error("the fluid changed from " + std::to_string(count) + " to " + std::to_string(fluid.size()) +
                           " particles while its starting fields were being set");
  for (const FieldValues& assignment : assignments) {
    if (assignment.components.size() == 1) {
      std::ranges::copy(assignment.components[0], fluid[fluid.scalar(assignment.name)].begin());
    } else {
      const VectorView<D> target = fluid[fluid.vector(assignment.name)];
      for (int c = 0; c < D; ++c) std::ranges::copy(assignment.components[std::size_t(c)], target.component[c]);
    }
  }
}

}  // namespace

py::object field_view(SimulationHandle& handle, const std::string& name) {
  const FieldLayout layout = locked(handle, [&](SimulationHandle& h) {
    return std::visit([&](const auto& simulation) { return layout_of(simulation, name); }, h.simulation());
  });
  if (layout.kind == FieldKind::index) return view_of<Index>(layout.simulation, layout.components[0], layout.count);
  if (layout.kind == FieldKind::scalar) return view_of<Real>(layout.simulation, layout.components[0], layout.count);
  py::tuple components(layout.components.size());
  for (std::size_t c = 0; c < layout.components.size(); ++c)
    components[c] = view_of<Real>(layout.simulation, layout.components[c], layout.count);
  return components;
}

py::list field_names(SimulationHandle& handle) {
  const FluidShape shape = locked(handle, [](SimulationHandle& h) {
    return std::visit([](const auto& s) { return FluidShape{s->fluid().fields(), s->fluid().size()}; }, h.simulation());
  });
  py::list names;
  for (const FieldInfo& field : shape.fields) names.append(field.name);
  return names;
}

void set_start_fields(SimulationHandle& handle, const py::dict& fields) {
  const FluidShape shape = locked(handle, [](SimulationHandle& h) {
    return std::visit([](const auto& s) { return FluidShape{s->fluid().fields(), s->fluid().size()}; }, h.simulation());
  });
  std::vector<FieldValues> assignments;
  for (const auto& [name, values] : fields) assignments.push_back(checked_values(shape, py::str(name), values));
  locked(handle, [&](SimulationHandle& h) {
    std::visit(
        [&](const auto& simulation) {
          simulation->edit_start([&](auto& fluid) { copy_into(fluid, assignments, shape.count); });
        },
        h.simulation());
  });
}

}  // namespace tide::python
