#include <algorithm>
#include <array>
#include <cctype>
#include <nlohmann/json.hpp>
#include <string>

#include "scene_keys.hpp"
#include "scene_sections.hpp"
#include "scene_shapes.hpp"
#include "scene_text.hpp"

namespace tide::io {
namespace {

std::string field_name(const ValueReader& values, const Node& node, const std::vector<std::string>& earlier) {
  const std::string expected = "one of " + quoted_list(scene::output_field_names);
  if (!node.present() || !node.value->is_string()) values.fail(node, expected);
  const std::string& name = node.value->get_ref<const std::string&>();
  if (std::find(scene::output_field_names.begin(), scene::output_field_names.end(), name) ==
      scene::output_field_names.end()) {
    values.fail(node, expected);
  }
  if (std::find(earlier.begin(), earlier.end(), name) != earlier.end()) values.fail(node, "a field not listed before");
  return name;
}

}  // namespace

std::span<const Key<scene::Time>> time_keys() {
  static constexpr std::array<Key<scene::Time>, 3> keys{{
      {"start", "number", "s", "`0`", "Simulated time of the initial state.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Time& time) {
         time.start = values.number(value, any_number);
       }},
      {"end", "number > `start`", "s", "", "Simulated time at which the run stops.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Time& time) {
         time.end = values.number(value, "a number > the start time (" + format_number(time.start) + ")",
                                  [&](double end) { return end > time.start; });
       }},
      {"output_interval", "number > 0", "s", "`0.01`", "Simulated time between output frames.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Time& time) {
         time.output_interval = values.number(value, positive);
       }},
  }};
  return keys;
}

std::span<const Key<scene::Output>> output_keys() {
  static constexpr std::array<Key<scene::Output>, 4> keys{{
      {"fields", "non-empty array of distinct field names", "–",
       "`[\"position\", \"velocity\", \"density\", \"pressure\"]`", "Per-particle fields written to each frame.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Output& output) {
         output.fields.clear();
         for (const Node& entry : values.elements(value, 1, "a non-empty array of field names"))
           output.fields.push_back(field_name(values, entry, output.fields));
       }},
      {"probe_interval", "number > 0", "s", "`time.output_interval`",
       "Simulated time between rows of `probes.csv` (and `recovery.csv`). A row is written at the start and at the "
       "first step at or after each multiple of the interval, with that step's time.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Output& output) {
         output.probe_interval = values.number(value, positive);
       }},
      {"recovery", "object", "–", "none",
       "`{\"material\": NAME, \"region\": BOX}`: writes `recovery.csv`, the share of the material's mass in the "
       "region at the start that has left it, 1 − M(t)/M(0) ([docs/output.md](output.md#recoverycsv)).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Output& output) {
         read_section(values, value, recovery_keys(), output.recovery.emplace());
       }},
      {"vtk", "boolean", "–", "`false`",
       "Also write each frame as a VTK file, `frames_NNNNNN.vtu`, and the collection `frames.pvd` that names them "
       "with their times, for tools that do not read XDMF ([docs/output.md](output.md#vtk-files)).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Output& output) { output.vtk = values.boolean(value); }},
  }};
  return keys;
}

/// The recovery of a material from a region: a material some fluid block starts with, and a
/// region inside the domain.
std::span<const Key<scene::Recovery>> recovery_keys() {
  static constexpr std::array<Key<scene::Recovery>, 2> keys{{
      {"material", "string", "–", "", "The name of a material some fluid block starts with.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Recovery& recovery) {
         const scene::Scene& scene = values.scene();
         recovery.material = values.material_index(value, scene.materials);
         const auto starts_with = [&](const scene::FluidBlock& block) { return block.material == recovery.material; };
         if (std::none_of(scene.fluid.begin(), scene.fluid.end(), starts_with))
           values.fail(value, "a material that some fluid block starts with");
       }},
      {"region", "[box](#box) inside the domain", "m", "", "The region whose share of the material is measured.",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::Recovery& recovery) {
         recovery.region = read_box(values, value);
         const scene::Box& domain = values.scene().domain.box;
         for (int d = 0; d < values.dimension(); ++d) {
           if (recovery.region.min[d] < domain.min[d] - values.tolerance() ||
               recovery.region.max[d] > domain.max[d] + values.tolerance()) {
             values.fail(value, "a box inside the domain [" + format_number(domain.min[d]) + ", " +
                                    format_number(domain.max[d]) + "] on axis " + std::to_string(d));
           }
         }
       }},
  }};
  return keys;
}

std::span<const Key<scene::Probe>> probe_keys() {
  static constexpr std::array<Key<scene::Probe>, 4> keys{{
      // A probe's name heads its column of probes.csv, so it must need no CSV quoting.
      {"name", "string of letters, digits, `_`, `-`, `.`; unique; not `time`", "–", "",
       "The probe's column in `probes.csv`.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Probe& probe) {
         const std::string name = value.present() && value.value->is_string() ? value.value->get<std::string>() : "";
         const auto allowed = [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-' || c == '.'; };
         const auto& earlier = values.scene().probes;
         const auto same_name = [&](const scene::Probe& other) { return other.name == name; };
         if (name.empty() || name == "time" || !std::all_of(name.begin(), name.end(), allowed) ||
             std::any_of(earlier.begin(), earlier.end(), same_name)) {
           values.fail(value,
                       "a name of letters, digits, '_', '-' and '.', other than \"time\", that no earlier probe has");
         }
         probe.name = name;
       }},
      {"type", "string: `\"pressure\"` or `\"water_height\"`", "–", "", "What the probe measures.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Probe& probe) {
         probe.type = values.choice(value, probe_type_names);
       }},
      {"position", "vector inside the domain", "m", "",
       "Where: the sensor's point, or the base of the gauge's vertical line.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::Probe& probe) {
         probe.position = values.vector(value);
         const scene::Box& domain = values.scene().domain.box;
         for (int d = 0; d < values.dimension(); ++d) {
           if (probe.position[d] < domain.min[d] - values.tolerance() ||
               probe.position[d] > domain.max[d] + values.tolerance()) {
             values.fail(element(value, d), "a number in [" + format_number(domain.min[d]) + ", " +
                                                format_number(domain.max[d]) + "] (the domain's extent on axis " +
                                                std::to_string(d) + ")");
           }
         }
       }},
      {"sensor", "object", "–", "none",
       "Pressure probes only: the sensing face of a transducer, whose reading is the pressure over that face "
       "(see below).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Probe& probe) {
         read_section(values, value, probe_sensor_keys(), probe.sensor.emplace());
       }},
  }};
  return keys;
}

std::span<const Key<scene::ProbeSensor>> probe_sensor_keys() {
  static constexpr std::array<Key<scene::ProbeSensor>, 2> keys{{
      {"diameter", "number > 0", "m", "",
       "The diameter of the sensing face: a disc in 3D, a segment of that length in 2D.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::ProbeSensor& sensor) {
         sensor.diameter = values.number(value, positive);
       }},
      {"normal", "non-zero vector", "–", "",
       "The normal of the sensing face (the wall's normal, either way); the face is perpendicular to it.",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::ProbeSensor& sensor) {
         sensor.normal = values.vector(value);
         if (sensor.normal == scene::Vec{}) values.fail(value, "a non-zero vector");
       }},
  }};
  return keys;
}

void read_time(const ValueReader& values, const Node& node, scene::Scene& scene) {
  read_section(values, node, time_keys(), scene.time);
}

void read_output(const ValueReader& values, const Node& node, scene::Scene& scene) {
  scene.output.probe_interval = scene.time.output_interval;
  if (node.present()) read_section(values, node, output_keys(), scene.output);
}

void read_probes(const ValueReader& values, const Node& node, scene::Scene& scene) {
  for (const Node& entry : values.elements(node, 0, "an array of probes")) {
    scene::Probe probe;
    read_section(values, entry, probe_keys(), probe);
    if (probe.sensor && probe.type != scene::ProbeType::pressure)
      values.fail(child(entry, "sensor"), "no sensor: only a pressure probe has a sensing face");
    scene.probes.push_back(std::move(probe));
  }
}

}  // namespace tide::io
