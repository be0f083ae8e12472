#include "tide/io/scene_reader.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "tide/solvers/capabilities.hpp"

namespace tide::io {
namespace {

using nlohmann::json;

constexpr const char* file_name = "dam.json";

/// A complete 2D dam break that sets every key; the bad-input tests each break one thing in it.
json full_2d_scene() {
  return json::parse(R"({
    "dimension": 2,
    "particle_spacing": 0.005,
    "kernel": {"type": "cubic_spline", "smoothing_ratio": 1.2},
    "domain": {"min": [-0.1, -0.1], "max": [1.7, 2.0], "periodic": [false, true]},
    "materials": [{"name": "water", "rest_density": 998, "kinematic_viscosity": 1e-6, "max_speed": 3.1},
                  {"name": "oil", "rest_density": 900, "sound_speed": 40}],
    "fluid": [{"material": "water", "box": {"min": [0, 0], "max": [0.4, 0.8]}},
              {"material": "water", "ball": {"centre": [1.0, 0.5], "radius": 0.1}}],
    "walls": {"layers": 4, "slip": "free_slip", "container": {"min": [0, 0], "max": [1.6, 1.2], "open_top": false},
              "obstacles": [{"box": {"min": [0.8, 0], "max": [0.9, 0.1]}},
                            {"ball": {"centre": [1.2, 0.1], "radius": 0.05}},
                            {"plane": {"point": [0, 0.05], "normal": [0.1, 1]}}]},
    "gravity": [0.5, -9.8],
    "solver": {"scheme": "wcsph", "equation_of_state": "linear", "tait_exponent": 5, "density": "continuity",
               "delta_sph": 0.2, "viscosity": "laminar", "alpha": 0.05, "beta": 0.1, "cfl": 0.3,
               "viscous_number": 0.1, "force_number": 0.2, "max_density_ratio": 1.2,
               "gravity_ramp_time": 0.25},
    "time": {"start": 0.5, "end": 2.0, "output_interval": 0.02},
    "output": {"fields": ["position", "velocity", "id", "mass"], "probe_interval": 0.001},
    "probes": [{"name": "P1", "type": "pressure", "position": [1.6, 0.12]},
               {"name": "H1", "type": "water_height", "position": [0.8, 0]}]
  })");
}

/// The smallest valid scene: only the required keys and a domain.
json minimal_scene() {
  return json::parse(R"({
    "dimension": 2,
    "particle_spacing": 0.01,
    "domain": {"min": [0, 0], "max": [1, 1]},
    "materials": [{"name": "water", "max_speed": 2}],
    "fluid": [{"material": "water", "box": {"min": [0, 0], "max": [0.5, 0.5]}}],
    "time": {"end": 1}
  })");
}

scene::Scene parse(const json& document) { return parse_scene(document.dump(), file_name); }

json with(json document, const std::string& pointer, json value) {
  document[json::json_pointer(pointer)] = std::move(value);
  return document;
}

json without(json document, const std::string& pointer) {
  const json::json_pointer key(pointer);
  document[key.parent_pointer()].erase(key.back());
  return document;
}

/// Parses `text` and returns the error it must raise.
SceneError error_of(const std::string& text) {
  try {
    parse_scene(text, file_name);
  } catch (const SceneError& error) {
    return error;
  }
  ADD_FAILURE() << "no SceneError for " << text;
  return SceneError("", "", "", "");
}

/// `error` is at `key_path`, with a message naming the file, the key path and containing
/// `expectation`.
void expect_error_at(const SceneError& error, const std::string& key_path, const std::string& expectation) {
  const std::string message = error.what();
  EXPECT_EQ(error.file(), file_name) << message;
  EXPECT_EQ(error.key_path(), key_path) << message;
  EXPECT_NE(message.find(std::string(file_name) + ": " + key_path + ": expected "), std::string::npos) << message;
  EXPECT_NE(message.find(expectation), std::string::npos) << message;
  EXPECT_NE(error.expected().find(expectation), std::string::npos) << message;
}

/// The reader must refuse the scene at `key_path`.
void expect_refused(const json& document, const std::string& key_path, const std::string& expectation) {
  expect_error_at(error_of(document.dump()), key_path, expectation);
}

/// The reader accepts the scene, and the solvers' capability check refuses it at `key_path`, with
/// the same message form as the reader's.
void expect_unsupported(const json& document, const std::string& key_path, const std::string& expectation) {
  const scene::Scene scene = parse(document);
  try {
    check_capabilities(scene);
    ADD_FAILURE() << "no SceneError from check_capabilities for " << document.dump();
  } catch (const SceneError& error) {
    expect_error_at(error, key_path, expectation);
  }
}

scene::Vec vec(double x, double y, double z = 0) { return {x, y, z}; }

// ---------------------------------------------------------------------------------------------
// Valid scenes

TEST(SceneReader, Full2DSceneRoundTrips) {
  const scene::Scene s = parse(full_2d_scene());
  EXPECT_EQ(s.source, file_name);
  EXPECT_EQ(s.dimension, 2);
  EXPECT_EQ(s.particle_spacing, 0.005);
  EXPECT_EQ(s.kernel, KernelType::cubic_spline);
  EXPECT_EQ(s.smoothing_ratio, 1.2);
  EXPECT_EQ(s.domain.box.min, vec(-0.1, -0.1));
  EXPECT_EQ(s.domain.box.max, vec(1.7, 2.0));
  EXPECT_EQ(s.domain.periodic, (std::array<bool, 3>{false, true, false}));

  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "water");
  EXPECT_EQ(s.materials[0].rest_density, 998);
  EXPECT_EQ(s.materials[0].kinematic_viscosity, 1e-6);
  EXPECT_EQ(s.materials[0].max_speed, 3.1);
  EXPECT_FALSE(s.materials[0].sound_speed);
  EXPECT_EQ(s.materials[1].name, "oil");
  EXPECT_EQ(s.materials[1].kinematic_viscosity, 0);
  EXPECT_EQ(s.materials[1].sound_speed, 40);
  EXPECT_FALSE(s.materials[1].max_speed);

  ASSERT_EQ(s.fluid.size(), 2u);
  EXPECT_EQ(s.fluid[0].material, 0u);
  const auto& box = std::get<scene::Box>(s.fluid[0].shape);
  EXPECT_EQ(box.min, vec(0, 0));
  EXPECT_EQ(box.max, vec(0.4, 0.8));
  EXPECT_EQ(s.fluid[1].material, 0u);  // one fluid material: oil is listed but unused
  const auto& ball = std::get<scene::Ball>(s.fluid[1].shape);
  EXPECT_EQ(ball.centre, vec(1.0, 0.5));
  EXPECT_EQ(ball.radius, 0.1);

  EXPECT_EQ(s.walls.layers, 4);
  EXPECT_EQ(s.walls.slip, scene::WallSlip::free_slip);
  ASSERT_TRUE(s.walls.container);
  EXPECT_EQ(s.walls.container->inner.min, vec(0, 0));
  EXPECT_EQ(s.walls.container->inner.max, vec(1.6, 1.2));
  EXPECT_FALSE(s.walls.container->open_top);
  ASSERT_EQ(s.walls.obstacles.size(), 3u);
  EXPECT_EQ(std::get<scene::Box>(s.walls.obstacles[0].shape).max, vec(0.9, 0.1));
  EXPECT_EQ(std::get<scene::Ball>(s.walls.obstacles[1].shape).radius, 0.05);
  EXPECT_EQ(std::get<scene::Plane>(s.walls.obstacles[2].shape).point, vec(0, 0.05));
  EXPECT_EQ(std::get<scene::Plane>(s.walls.obstacles[2].shape).normal, vec(0.1, 1));

  EXPECT_EQ(s.gravity, vec(0.5, -9.8));
  EXPECT_EQ(s.solver.scheme, scene::Scheme::wcsph);
  EXPECT_EQ(s.solver.equation_of_state, scene::EquationOfState::linear);
  EXPECT_EQ(s.solver.tait_exponent, 5);
  EXPECT_EQ(s.solver.density, scene::DensityMethod::continuity);
  EXPECT_EQ(s.solver.delta_sph, 0.2);
  EXPECT_EQ(s.solver.viscosity, scene::ViscosityModel::laminar);
  EXPECT_EQ(s.solver.alpha, 0.05);
  EXPECT_EQ(s.solver.beta, 0.1);
  EXPECT_EQ(s.solver.cfl, 0.3);
  EXPECT_EQ(s.solver.viscous_number, 0.1);
  EXPECT_EQ(s.solver.force_number, 0.2);
  EXPECT_EQ(s.solver.max_density_ratio, 1.2);
  EXPECT_EQ(s.solver.gravity_ramp_time, 0.25);
  EXPECT_EQ(s.time.start, 0.5);
  EXPECT_EQ(s.time.end, 2.0);
  EXPECT_EQ(s.time.output_interval, 0.02);
  EXPECT_EQ(s.output.fields, (std::vector<std::string>{"position", "velocity", "id", "mass"}));
  EXPECT_EQ(s.output.probe_interval, 0.001);
  ASSERT_EQ(s.probes.size(), 2u);
  EXPECT_EQ(s.probes[0].name, "P1");
  EXPECT_EQ(s.probes[0].type, scene::ProbeType::pressure);
  EXPECT_EQ(s.probes[0].position, vec(1.6, 0.12));
  EXPECT_EQ(s.probes[1].name, "H1");
  EXPECT_EQ(s.probes[1].type, scene::ProbeType::water_height);
  EXPECT_EQ(s.probes[1].position, vec(0.8, 0));
}

TEST(SceneReader, Full3DSceneRoundTrips) {
  const scene::Scene s = parse_scene(R"({
    "dimension": 3,
    "particle_spacing": 0.02,
    "kernel": {"type": "wendland_c4", "smoothing_ratio": 1.5},
    "materials": [{"name": "water", "max_speed": 4}],
    "fluid": [{"material": "water", "box": {"min": [0, 0, 0], "max": [0.5, 0.4, 0.6]}},
              {"material": "water", "ball": {"centre": [0.8, 0.2, 0.3], "radius": 0.1}}],
    "walls": {"layers": 4, "container": {"min": [0, 0, 0], "max": [1.2, 0.4, 0.8]},
              "obstacles": [{"plane": {"point": [0, 0, 0.01], "normal": [0, 0, 1]}}]},
    "gravity": [0, 0, -9.81],
    "solver": {"cfl": 0.2},
    "time": {"end": 1.5, "output_interval": 0.05},
    "output": {"fields": ["position", "pressure", "acceleration"]}
  })",
                                     file_name);
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.particle_spacing, 0.02);
  EXPECT_EQ(s.kernel, KernelType::wendland_c4);
  EXPECT_EQ(s.smoothing_ratio, 1.5);
  EXPECT_EQ(std::get<scene::Box>(s.fluid[0].shape).max, vec(0.5, 0.4, 0.6));
  EXPECT_EQ(std::get<scene::Ball>(s.fluid[1].shape).centre, vec(0.8, 0.2, 0.3));
  EXPECT_EQ(s.walls.layers, 4);
  EXPECT_TRUE(s.walls.container->open_top);
  EXPECT_EQ(std::get<scene::Plane>(s.walls.obstacles[0].shape).normal, vec(0, 0, 1));
  EXPECT_EQ(s.gravity, vec(0, 0, -9.81));
  EXPECT_EQ(s.solver.cfl, 0.2);
  EXPECT_EQ(s.time.end, 1.5);
  EXPECT_EQ(s.time.output_interval, 0.05);
  EXPECT_EQ(s.output.fields, (std::vector<std::string>{"position", "pressure", "acceleration"}));
  // Derived domain: 4 layers of 0.02 around the container, plus its height above the open top.
  EXPECT_NEAR(s.domain.box.min[0], -0.08, 1e-12);
  EXPECT_NEAR(s.domain.box.max[1], 0.48, 1e-12);
  EXPECT_NEAR(s.domain.box.max[2], 0.8 + 0.08 + 0.8, 1e-12);
}

TEST(SceneReader, DefaultsComeFromTheSceneModel) {
  const scene::Scene s = parse(minimal_scene());
  const scene::Scene model;
  EXPECT_EQ(s.kernel, model.kernel);
  EXPECT_EQ(s.smoothing_ratio, model.smoothing_ratio);
  EXPECT_EQ(s.domain.periodic, (std::array<bool, 3>{}));
  EXPECT_EQ(s.materials[0].rest_density, 1000);
  EXPECT_EQ(s.materials[0].kinematic_viscosity, 0);
  EXPECT_EQ(s.walls.layers, model.walls.layers);
  EXPECT_EQ(s.walls.slip, model.walls.slip);
  EXPECT_FALSE(s.walls.container);
  EXPECT_TRUE(s.walls.obstacles.empty());
  EXPECT_EQ(s.gravity, vec(0, -9.81));
  EXPECT_EQ(s.solver.equation_of_state, model.solver.equation_of_state);
  EXPECT_EQ(s.solver.tait_exponent, model.solver.tait_exponent);
  EXPECT_EQ(s.solver.density, model.solver.density);
  EXPECT_EQ(s.solver.delta_sph, model.solver.delta_sph);
  EXPECT_EQ(s.solver.viscosity, model.solver.viscosity);
  EXPECT_EQ(s.solver.alpha, model.solver.alpha);
  EXPECT_EQ(s.solver.beta, model.solver.beta);
  EXPECT_EQ(s.solver.cfl, model.solver.cfl);
  EXPECT_EQ(s.solver.viscous_number, model.solver.viscous_number);
  EXPECT_EQ(s.solver.force_number, model.solver.force_number);
  EXPECT_EQ(s.solver.max_density_ratio, model.solver.max_density_ratio);
  EXPECT_EQ(s.solver.max_density_error, 0.0005);  // the issue's 0.05% of ρ0
  EXPECT_EQ(s.solver.max_divergence_error, model.solver.max_divergence_error);
  EXPECT_EQ(s.solver.max_solver_iterations, model.solver.max_solver_iterations);
  EXPECT_EQ(s.solver.max_failed_solves, model.solver.max_failed_solves);
  EXPECT_EQ(s.time.start, model.time.start);
  EXPECT_EQ(s.time.output_interval, model.time.output_interval);
  EXPECT_EQ(s.output.fields, model.output.fields);
  EXPECT_TRUE(s.probes.empty());
  EXPECT_EQ(s.output.probe_interval, s.time.output_interval);  // probes are read with the frames
}

TEST(SceneReader, ThreeDimensionalGravityPointsDownTheLastAxis) {
  json document = minimal_scene();
  document["dimension"] = 3;
  document["domain"] = json::parse(R"({"min": [0, 0, 0], "max": [1, 1, 1]})");
  document["fluid"][0]["box"] = json::parse(R"({"min": [0, 0, 0], "max": [0.5, 0.5, 0.5]})");
  EXPECT_EQ(parse(document).gravity, vec(0, 0, -9.81));
}

TEST(SceneReader, DomainIsDerivedFromTheContainer) {
  json document = without(minimal_scene(), "/domain");
  document["walls"] = json::parse(R"({"container": {"min": [0, 0], "max": [2, 1]}})");
  const scene::Scene open = parse(document);
  // Three layers of 0.01 on every side, and the container's height of 1 again above its open top.
  EXPECT_NEAR(open.domain.box.min[0], -0.03, 1e-12);
  EXPECT_NEAR(open.domain.box.min[1], -0.03, 1e-12);
  EXPECT_NEAR(open.domain.box.max[0], 2.03, 1e-12);
  EXPECT_NEAR(open.domain.box.max[1], 2.03, 1e-12);
  EXPECT_EQ(open.domain.periodic, (std::array<bool, 3>{}));

  document["walls"]["container"]["open_top"] = false;
  EXPECT_NEAR(parse(document).domain.box.max[1], 1.03, 1e-12);
}

TEST(SceneReader, DefaultWallLayersCoverTheKernelSupport) {
  // The quintic spline reaches 3 h = 3.9 spacings at h = 1.3 spacings: 4 layers.
  json document = with(minimal_scene(), "/kernel", {{"type", "quintic_spline"}});
  EXPECT_EQ(parse(document).walls.layers, 4);
}

TEST(SceneReader, ReadsWallAndFluidVelocities) {
  json document = with(full_2d_scene(), "/walls/obstacles/0/velocity", {1.5, 0});
  document = with(document, "/fluid/0/velocity", {{"taylor_green", {{"amplitude", 2}}}});
  document = with(document, "/fluid/1/velocity", {0, -1});
  document = with(document, "/solver/background_pressure", 50);
  document = with(document, "/solver/shifting", "fickian");
  const scene::Scene s = parse(document);
  EXPECT_EQ(s.walls.obstacles[0].velocity, vec(1.5, 0));
  EXPECT_EQ(s.walls.obstacles[1].velocity, vec(0, 0));
  const auto& vortex = std::get<scene::TaylorGreenVelocity>(s.fluid[0].velocity);
  EXPECT_EQ(vortex.amplitude, 2);
  EXPECT_EQ(vortex.length, 1);
  EXPECT_EQ(std::get<scene::Vec>(s.fluid[1].velocity), vec(0, -1));
  EXPECT_EQ(s.solver.background_pressure, 50);
  EXPECT_EQ(s.solver.shifting, scene::Shifting::fickian);
}

// An obstacle's own slip is read where given and left unset (the walls' slip) where not.
TEST(SceneReader, ReadsAnObstaclesOwnSlip) {
  const scene::Scene s = parse(with(full_2d_scene(), "/walls/obstacles/1/slip", "free_slip"));
  EXPECT_FALSE(s.walls.obstacles[0].slip.has_value());
  EXPECT_EQ(s.walls.obstacles[1].slip, scene::WallSlip::free_slip);
  expect_refused(with(full_2d_scene(), "/walls/obstacles/0/slip", "sticky"), "/walls/obstacles/0/slip", "no_slip");
}

TEST(SceneReader, ReadsAnObstaclesMotion) {
  const json rotation = {{"rotation", {{"centre", {0.85, 0.05}}, {"angular_velocity", 2.5}, {"ramp_time", 0.5}}}};
  scene::Scene s = parse(with(full_2d_scene(), "/walls/obstacles/0/motion", rotation));
  ASSERT_TRUE(s.walls.obstacles[0].motion.has_value());
  const auto& turning = std::get<scene::Rotation>(*s.walls.obstacles[0].motion);
  EXPECT_EQ(turning.centre, vec(0.85, 0.05));
  EXPECT_EQ(turning.axis, vec(0, 0, 1));
  EXPECT_EQ(turning.angular_velocity, 2.5);
  EXPECT_EQ(turning.ramp_time, 0.5);
  EXPECT_FALSE(s.walls.obstacles[1].motion.has_value());

  const json piston = {{"oscillation", {{"amplitude", {0.02, 0}}, {"frequency", 1.5}, {"phase", -1.5}}}};
  s = parse(with(full_2d_scene(), "/walls/obstacles/1/motion", piston));
  const auto& oscillation = std::get<scene::Oscillation>(*s.walls.obstacles[1].motion);
  EXPECT_EQ(oscillation.amplitude, vec(0.02, 0));
  EXPECT_EQ(oscillation.frequency, 1.5);
  EXPECT_EQ(oscillation.phase, -1.5);

  const json flap = {{"flap", {{"hinge", {0.8, 0}}, {"amplitude", 0.1}, {"frequency", 0.5}}}};
  s = parse(with(full_2d_scene(), "/walls/obstacles/0/motion", flap));
  EXPECT_EQ(std::get<scene::FlapOscillation>(*s.walls.obstacles[0].motion).hinge, vec(0.8, 0));

  s = parse(with(full_2d_scene(), "/walls/obstacles/0/motion", json{{"steered", {{"max_speed", 1.5}}}}));
  EXPECT_EQ(std::get<scene::Steered>(*s.walls.obstacles[0].motion).max_speed, 1.5);
  s = parse(with(full_2d_scene(), "/walls/obstacles/0/motion", json{{"steered", json::object()}}));
  EXPECT_EQ(std::get<scene::Steered>(*s.walls.obstacles[0].motion).max_speed, 1) << "the default";
  expect_refused(with(full_2d_scene(), "/walls/obstacles/0/motion", json{{"steered", {{"max_speed", 0}}}}),
                 "/walls/obstacles/0/motion/steered/max_speed", "a number > 0");
}

TEST(SceneReader, RefusesBadMotions) {
  const json document = full_2d_scene();
  const json turning = {{"centre", {0.85, 0.05}}, {"angular_velocity", 1}};
  expect_refused(with(document, "/walls/obstacles/0/motion", {{"rotation", turning}, {"flap", turning}}),
                 "/walls/obstacles/0/motion", "exactly one motion key");
  expect_refused(with(document, "/walls/obstacles/0/motion", {{"spin", turning}}), "/walls/obstacles/0/motion/spin",
                 "one of the keys");
  json axis = turning;
  axis["axis"] = {0, 1};
  expect_refused(with(document, "/walls/obstacles/0/motion", {{"rotation", axis}}),
                 "/walls/obstacles/0/motion/rotation/axis", "2D scenes rotate about z");
  expect_refused(
      with(document, "/walls/obstacles/0/motion", {{"oscillation", {{"amplitude", {0.1, 0}}, {"frequency", 0}}}}),
      "/walls/obstacles/0/motion/oscillation/frequency", "a number > 0");
  expect_refused(
      with(with(document, "/walls/obstacles/0/velocity", {1, 0}), "/walls/obstacles/0/motion", {{"rotation", turning}}),
      "/walls/obstacles/0/motion", "no motion on an obstacle with a velocity");
  expect_refused(with(document, "/walls/obstacles/2/motion", {{"rotation", turning}}), "/walls/obstacles/2/motion",
                 "no motion on a plane");
}

TEST(SceneReader, ReadsABody) {
  const json body = {{"density", 500}, {"constraints", {{"locked_translation", {true, false}}, {"pivot", {0.8, 0.1}}}}};
  const scene::Scene s = parse(with(full_2d_scene(), "/walls/obstacles/0/body", body));
  ASSERT_TRUE(s.walls.obstacles[0].body.has_value());
  EXPECT_EQ(s.walls.obstacles[0].body->density, 500);
  const scene::BodyConstraints& constraints = s.walls.obstacles[0].body->constraints;
  EXPECT_EQ(constraints.locked_translation, (std::array<bool, 3>{true, false, false}));
  EXPECT_FALSE(constraints.locked_rotation);
  EXPECT_EQ(constraints.pivot, vec(0.8, 0.1));
  EXPECT_FALSE(s.walls.obstacles[1].body.has_value());
}

TEST(SceneReader, RefusesBadBodies) {
  const json document = full_2d_scene();
  expect_refused(with(document, "/walls/obstacles/0/body", json::object()), "/walls/obstacles/0/body/density",
                 "a number > 0");
  expect_refused(with(document, "/walls/obstacles/0/body", {{"density", -1}}), "/walls/obstacles/0/body/density",
                 "a number > 0");
  expect_refused(with(document, "/walls/obstacles/2/body", {{"density", 500}}), "/walls/obstacles/2/body",
                 "no body on a plane");
  const json turning = {{"rotation", {{"centre", {0.85, 0.05}}, {"angular_velocity", 1}}}};
  expect_refused(
      with(with(document, "/walls/obstacles/0/motion", turning), "/walls/obstacles/0/body", {{"density", 500}}),
      "/walls/obstacles/0/body", "no body on an obstacle with a motion");
  expect_refused(
      with(document, "/walls/obstacles/0/body", {{"density", 500}, {"constraints", {{"rotation_axis", {0, 1}}}}}),
      "/walls/obstacles/0/body/constraints/rotation_axis", "2D bodies turn about z");
  expect_refused(with(document, "/walls/obstacles/0/body",
                      {{"density", 500}, {"constraints", {{"locked_rotation", true}, {"spin", 1}}}}),
                 "/walls/obstacles/0/body/constraints/spin", "one of the keys");
  expect_unsupported(with(with(document, "/walls/obstacles/0/body", {{"density", 500}}), "/solver/scheme", "dfsph"),
                     "/solver/scheme", "\"wcsph\" with a rigid body");
}

// A motion table is read from its CSV file; a bad row is refused with the file and its line.
TEST(SceneReader, ReadsAMotionTableAndRefusesABadOne) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / "tide_motion_table_test";
  std::filesystem::create_directories(directory);
  const auto table_scene = [&](const std::string& name, const std::string& text) {
    std::ofstream(directory / name) << text;
    return with(full_2d_scene(), "/walls/obstacles/0/motion",
                {{"table", {{"file", (directory / name).string()}, {"centre", {0.85, 0.05}}}}});
  };
  const scene::Scene s = parse(table_scene("good.csv", "time,x,y,angle\n0,0,0,0\n0.5,0.01,0,0.1\n1.5,0.01,0.02,0\n"));
  const auto& table = std::get<scene::MotionTable>(*s.walls.obstacles[0].motion);
  ASSERT_EQ(table.samples.size(), 3u);
  EXPECT_EQ(table.samples[1].time, 0.5);
  EXPECT_EQ(table.samples[1].displacement, vec(0.01, 0));
  EXPECT_EQ(table.samples[1].angle, 0.1);
  EXPECT_EQ(table.samples[2].displacement, vec(0.01, 0.02));

  const std::string at = "/walls/obstacles/0/motion/table/file";
  expect_refused(table_scene("columns.csv", "time,x,y,angle\n0,0,0,0\n1,2,3\n"), at, "a motion table");
  const SceneError columns = error_of(table_scene("columns.csv", "t,x,y,a\n0,0,0,0\n1,2,3\n").dump());
  EXPECT_NE(std::string(columns.what()).find("columns.csv: line 3: expected 4 numbers"), std::string::npos)
      << columns.what();
  const SceneError order = error_of(table_scene("order.csv", "t,x,y,a\n0,0,0,0\n1,0,0,0\n1,0,0,0\n").dump());
  EXPECT_NE(std::string(order.what()).find("line 4: expected a time after 1"), std::string::npos) << order.what();
  const SceneError start = error_of(table_scene("start.csv", "t,x,y,a\n0,0.1,0,0\n1,0,0,0\n").dump());
  EXPECT_NE(std::string(start.what()).find("line 2: expected the first row at time 0"), std::string::npos)
      << start.what();
  const SceneError number = error_of(table_scene("nan.csv", "t,x,y,a\n0,0,0,0\n1,nan,0,0\n").dump());
  EXPECT_NE(std::string(number.what()).find("line 3: expected a finite number, got \"nan\""), std::string::npos)
      << number.what();
  expect_refused(
      with(full_2d_scene(), "/walls/obstacles/0/motion", {{"table", {{"file", (directory / "absent.csv").string()}}}}),
      at, "a motion table");
  std::filesystem::remove_all(directory);
}

TEST(SceneReader, ReadsTheIncompressibleSchemesAndTheirSolverKeys) {
  for (const auto& [name, scheme] :
       {std::pair{"dfsph", scene::Scheme::dfsph}, std::pair{"iisph", scene::Scheme::iisph}}) {
    json document = with(full_2d_scene(), "/solver/scheme", name);
    document = with(document, "/solver/max_density_error", 0.001);
    document = with(document, "/solver/max_divergence_error", 0.002);
    document = with(document, "/solver/max_solver_iterations", 250);
    document = with(document, "/solver/max_failed_solves", 3);
    const scene::Scene s = parse(document);
    EXPECT_EQ(s.solver.scheme, scheme);
    EXPECT_EQ(s.solver.max_density_error, 0.001);
    EXPECT_EQ(s.solver.max_divergence_error, 0.002);
    EXPECT_EQ(s.solver.max_solver_iterations, 250);
    EXPECT_EQ(s.solver.max_failed_solves, 3);
  }
}

TEST(SceneReader, ReadsARigidRotation) {
  const json document =
      with(full_2d_scene(), "/fluid/0/velocity", {{"rotation", {{"centre", {0.2, 0.4}}, {"angular_velocity", -1.5}}}});
  const scene::Scene s = parse(document);
  const auto& rotation = std::get<scene::RigidRotation>(s.fluid[0].velocity);
  EXPECT_EQ(rotation.centre, vec(0.2, 0.4));
  EXPECT_EQ(rotation.angular_velocity, -1.5);
}

TEST(SceneReader, ReadsTheStabilityOptions) {
  json document = with(full_2d_scene(), "/solver/artificial_stress", 0.2);
  document = with(document, "/solver/max_mach_number", 0.5);
  document = with(document, "/solver/cfl", 2.5);  // accepted; `tide run` warns above 1
  const scene::Scene s = parse(document);
  EXPECT_EQ(s.solver.artificial_stress, 0.2);
  EXPECT_EQ(s.solver.max_mach_number, 0.5);
  EXPECT_EQ(s.solver.cfl, 2.5);
  const scene::Scene defaults = parse(minimal_scene());
  EXPECT_EQ(defaults.solver.artificial_stress, 0);  // off
  EXPECT_EQ(defaults.solver.max_mach_number, 1);
}

TEST(SceneReader, ReadsTheRiemannSolverAndKernelGradientCorrection) {
  json document = with(full_2d_scene(), "/solver/riemann_solver", "low_dissipation");
  document = with(document, "/solver/kernel_gradient_correction", true);
  const scene::Scene s = parse(document);
  EXPECT_EQ(s.solver.riemann_solver, scene::RiemannSolver::low_dissipation);
  EXPECT_TRUE(s.solver.kernel_gradient_correction);
  EXPECT_NO_THROW(check_capabilities(s));  // wcsph, continuity density, one fluid, no body
  const scene::Scene defaults = parse(minimal_scene());
  EXPECT_EQ(defaults.solver.riemann_solver, scene::RiemannSolver::none);
  EXPECT_FALSE(defaults.solver.kernel_gradient_correction);
  expect_refused(with(full_2d_scene(), "/solver/riemann_solver", "hllc"), "/solver/riemann_solver",
                 "one of \"none\", \"low_dissipation\"");
  expect_refused(with(full_2d_scene(), "/solver/kernel_gradient_correction", 1), "/solver/kernel_gradient_correction",
                 "true or false");
  expect_unsupported(with(document, "/solver/density", "summation"), "/solver/riemann_solver",
                     "\"none\" with summation density");
  expect_unsupported(with(document, "/solver/scheme", "dfsph"), "/solver/riemann_solver",
                     "\"none\" for solver.scheme \"dfsph\"");
  expect_unsupported(with(full_2d_scene(), "/solver/kernel_gradient_correction", true),
                     "/solver/kernel_gradient_correction", "false without solver.riemann_solver");
}

TEST(SceneReader, ReadsTheNeighbourSkin) {
  EXPECT_EQ(parse(with(full_2d_scene(), "/solver/neighbor_skin", 0.5)).solver.neighbor_skin, 0.5);
  EXPECT_EQ(parse(with(full_2d_scene(), "/solver/neighbor_skin", 0)).solver.neighbor_skin, 0.0);
  EXPECT_FALSE(parse(minimal_scene()).solver.neighbor_skin.has_value());  // the scheme's default
  EXPECT_EQ(scene::default_neighbor_skin(scene::Scheme::wcsph), 0.3);
  EXPECT_EQ(scene::default_neighbor_skin(scene::Scheme::dfsph), 0);
  expect_refused(with(full_2d_scene(), "/solver/neighbor_skin", -0.1), "/solver/neighbor_skin", "a number >= 0");
}

TEST(SceneReaderRefuses, StabilityOptionsOutOfRange) {
  expect_refused(with(full_2d_scene(), "/solver/artificial_stress", -0.1), "/solver/artificial_stress",
                 "a number >= 0");
  expect_refused(with(full_2d_scene(), "/solver/artificial_stress", "on"), "/solver/artificial_stress",
                 "a number >= 0");
  expect_refused(with(full_2d_scene(), "/solver/max_mach_number", 0), "/solver/max_mach_number", "a number > 0");
  expect_refused(with(full_2d_scene(), "/solver/cfl", 0), "/solver/cfl", "a number > 0");
}

TEST(SceneReaderRefuses, MalformedVelocities) {
  const std::string velocity_expectation =
      "a velocity array of 2 numbers, {\"taylor_green\": {...}} or {\"rotation\": {...}}";
  expect_refused(with(full_2d_scene(), "/fluid/0/velocity", "fast"), "/fluid/0/velocity", velocity_expectation);
  expect_refused(with(full_2d_scene(), "/fluid/0/velocity", {{"vortex", 1}}), "/fluid/0/velocity/vortex",
                 "one of the keys \"taylor_green\", \"rotation\"");
  expect_refused(with(full_2d_scene(), "/fluid/0/velocity", json::object()), "/fluid/0/velocity", velocity_expectation);
  expect_refused(with(full_2d_scene(), "/fluid/0/velocity/rotation", {{"angular_velocity", 1}}),
                 "/fluid/0/velocity/rotation/centre", "an array of 2 numbers [x, y]");
  expect_refused(with(full_2d_scene(), "/walls/obstacles/0/velocity", {1, 0, 0}), "/walls/obstacles/0/velocity",
                 "an array of 2 numbers [x, y]");
}

/// Oil in water, two fluid materials: a multiphase scene with csf tension.
json two_fluid_scene() {
  json document = full_2d_scene();
  document["fluid"][1]["material"] = "oil";
  document["solver"] = json::parse(R"({"density": "summation",
                                       "surface_tension": {"model": "csf", "coefficient": 0.03}})");
  return document;
}

TEST(SceneReader, ReadsSurfaceTensionModels) {
  scene::Scene s = parse(two_fluid_scene());
  EXPECT_EQ(s.fluid[1].material, 1u);
  EXPECT_EQ(scene::fluid_material_count(s), 2u);
  EXPECT_EQ(s.solver.surface_tension.model, scene::SurfaceTensionModel::csf);
  EXPECT_EQ(s.solver.surface_tension.coefficient, 0.03);
  s = parse(with(full_2d_scene(), "/solver/surface_tension",
                 {{"model", "pairwise"}, {"coefficient", 0.07}, {"contact_angle", 30}}));
  EXPECT_EQ(s.solver.surface_tension.model, scene::SurfaceTensionModel::pairwise);
  EXPECT_EQ(s.solver.surface_tension.contact_angle, 30);
  EXPECT_TRUE(s.solver.surface_tension.unlike_attraction);
  s = parse(with(full_2d_scene(), "/solver/surface_tension",
                 {{"model", "pairwise"}, {"coefficient", 0.07}, {"unlike_attraction", false}}));
  EXPECT_FALSE(s.solver.surface_tension.unlike_attraction);
  s = parse(
      with(full_2d_scene(), "/solver/surface_tension", {{"model", "akinci"}, {"coefficient", 2}, {"adhesion", 1}}));
  EXPECT_EQ(s.solver.surface_tension.model, scene::SurfaceTensionModel::akinci);
  EXPECT_EQ(s.solver.surface_tension.adhesion, 1);
  EXPECT_EQ(parse(full_2d_scene()).solver.surface_tension.model, scene::SurfaceTensionModel::none);
}

TEST(SceneReaderRefuses, BadSurfaceTensionAndMultiphaseSettings) {
  const std::string tension = "/solver/surface_tension";
  expect_refused(with(two_fluid_scene(), tension + "/model", "marangoni"), tension + "/model",
                 "one of \"csf\", \"akinci\", \"pairwise\"");
  expect_refused(without(two_fluid_scene(), tension + "/coefficient"), tension + "/coefficient", "a number > 0");
  expect_refused(with(two_fluid_scene(), tension + "/coefficient", -1), tension + "/coefficient", "a number > 0");
  expect_refused(with(two_fluid_scene(), tension + "/unknown", 1), tension + "/unknown", "one of the keys");
  expect_refused(with(two_fluid_scene(), tension + "/contact_angle", 30), tension + "/contact_angle",
                 "only the pairwise model");
  expect_refused(with(two_fluid_scene(), tension + "/adhesion", 1), tension + "/adhesion", "only the akinci model");
  expect_refused(with(two_fluid_scene(), tension + "/unlike_attraction", false), tension + "/unlike_attraction",
                 "only the pairwise model");
  expect_refused(with(with(two_fluid_scene(), tension + "/model", "pairwise"), tension + "/unlike_attraction", 0),
                 tension + "/unlike_attraction", "true or false");
  expect_refused(with(with(two_fluid_scene(), tension + "/model", "pairwise"), tension + "/contact_angle", 180),
                 tension + "/contact_angle", "an angle in degrees in (0, 180)");
  expect_unsupported(with(full_2d_scene(), tension, {{"model", "csf"}, {"coefficient", 1}}), tension + "/model",
                     "\"csf\" needs exactly two fluid materials");
  expect_unsupported(with(two_fluid_scene(), "/solver/density", "continuity"), "/solver/density",
                     "\"summation\" for a scene with several fluid materials");
  expect_unsupported(with(two_fluid_scene(), "/solver/scheme", "dfsph"), "/solver/scheme",
                     "\"wcsph\" with surface tension");
  const json incompressible_pair =
      with(without(two_fluid_scene(), "/solver/surface_tension"), "/solver/scheme", "iisph");
  EXPECT_EQ(parse(incompressible_pair).solver.scheme, scene::Scheme::iisph);
  expect_unsupported(with(incompressible_pair, "/materials/1/rest_density", 80), "/solver/scheme",
                     "\"wcsph\" for fluids whose rest densities differ by more than 10 times");
  expect_unsupported(with(two_fluid_scene(), "/solver/artificial_stress", 0.2), "/solver/artificial_stress",
                     "0 for a scene with several fluid materials");
  expect_unsupported(with(full_2d_scene(), "/output/fields", {"position", "phase"}), "/output/fields/1",
                     "\"phase\" needs several fluid materials");
}

TEST(SceneReader, AcceptsComments) {
  const std::string text = R"({
    // a comment line
    "dimension": 2, /* and a block */
    "particle_spacing": 0.01,
    "domain": {"min": [0, 0], "max": [1, 1]},
    "materials": [{"name": "water", "max_speed": 2}],
    "fluid": [{"material": "water", "box": {"min": [0, 0], "max": [0.5, 0.5]}}],
    "time": {"end": 1}
  })";
  EXPECT_EQ(parse_scene(text, file_name).particle_spacing, 0.01);
}

TEST(SceneReader, ReadsAFileAndNamesItInErrors) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / "tide_scene_reader_test";
  std::filesystem::create_directories(directory);
  const std::filesystem::path file = directory / "tank.json";
  std::ofstream(file) << minimal_scene().dump(2);
  EXPECT_EQ(read_scene_file(file).source, file.string());

  std::ofstream(file) << with(minimal_scene(), "/particle_spacing", 0).dump(2);
  try {
    read_scene_file(file);
    ADD_FAILURE() << "no SceneError";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(file.string() + ": /particle_spacing: expected", 0), 0u) << error.what();
  }

  const std::filesystem::path absent = directory / "absent.json";
  try {
    read_scene_file(absent);
    ADD_FAILURE() << "no SceneError";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()), absent.string() + ": expected a scene file, got no such file");
  }
  std::filesystem::remove_all(directory);
}

// ---------------------------------------------------------------------------------------------
// Bad input: each class of mistake is refused with the file, the key path and the expectation.

TEST(SceneReaderRefuses, WrongTypeWithTheExactMessage) {
  const SceneError error = error_of(with(full_2d_scene(), "/solver/cfl", "fast").dump());
  EXPECT_STREQ(error.what(), R"(dam.json: /solver/cfl: expected a number > 0, got "fast")");
  EXPECT_EQ(error.file(), "dam.json");
  EXPECT_EQ(error.key_path(), "/solver/cfl");
  EXPECT_EQ(error.expected(), "a number > 0");
  EXPECT_EQ(error.found(), R"("fast")");
}

TEST(SceneReaderRefuses, OtherWrongTypes) {
  expect_refused(with(full_2d_scene(), "/walls/container/open_top", "yes"), "/walls/container/open_top",
                 "true or false");
  expect_refused(with(full_2d_scene(), "/materials/0/name", 7), "/materials/0/name", "a non-empty string");
  expect_refused(with(full_2d_scene(), "/solver", json::array()), "/solver", "an object with the keys \"scheme\"");
  expect_refused(with(full_2d_scene(), "/fluid", json::object()), "/fluid", "a non-empty array of fluid blocks");
  expect_refused(with(full_2d_scene(), "/domain/periodic/1", 1), "/domain/periodic/1", "true or false");
}

TEST(SceneReaderRefuses, TextThatIsNotJson) {
  const SceneError error = error_of("{\n  \"dimension\": 2,\n  \"particle_spacing\": ,\n}");
  EXPECT_EQ(error.line(), 3u);
  EXPECT_EQ(error.column(), 23u);
  EXPECT_EQ(error.key_path(), "");
  const std::string message = error.what();
  EXPECT_EQ(message.rfind("dam.json: line 3, column 23: expected valid JSON, got syntax error", 0), 0u) << message;
}

TEST(SceneReaderRefuses, ADocumentThatIsNotAnObject) {
  const SceneError error = error_of("[1, 2]");
  EXPECT_EQ(std::string(error.what()).rfind("dam.json: expected an object with the keys \"dimension\"", 0), 0u)
      << error.what();
}

TEST(SceneReaderRefuses, UnknownKeysListingTheAllowedOnes) {
  expect_refused(with(full_2d_scene(), "/solver/cfll", 0.2), "/solver/cfll",
                 R"(one of the keys "scheme", "equation_of_state", "tait_exponent")");
  expect_refused(with(full_2d_scene(), "/fluid/1/ball/center", json::array({1, 1})), "/fluid/1/ball/center",
                 R"(one of the keys "centre", "radius")");
  expect_refused(with(full_2d_scene(), "/gravitation", 1), "/gravitation", R"("particle_spacing")");
  const SceneError error = error_of(with(full_2d_scene(), "/time/a~0b", 1).dump());
  EXPECT_EQ(error.key_path(), "/time/a~0b");
  EXPECT_EQ(error.found(), R"(the unknown key "a~b")");
}

TEST(SceneReaderRefuses, KeysGivenTwice) {
  const std::string text = R"({"dimension": 2, "fluid": [{"box": {"min": [0, 0], "min": [1, 1]}}]})";
  const SceneError error = error_of(text);
  EXPECT_EQ(error.key_path(), "/fluid/0/box/min");
  EXPECT_STREQ(error.what(),
               R"(dam.json: /fluid/0/box/min: expected each key at most once in an object, got "min" a second time)");
}

TEST(SceneReaderRefuses, MissingRequiredKeys) {
  for (const char* key : {"/dimension", "/particle_spacing", "/materials", "/fluid", "/time"}) {
    const SceneError error = error_of(without(full_2d_scene(), key).dump());
    EXPECT_EQ(error.key_path(), key);
    EXPECT_EQ(error.found(), "nothing (the key is missing)");
  }
  expect_refused(without(full_2d_scene(), "/time/end"), "/time/end", "a number > the start time (0.5)");
  expect_refused(without(full_2d_scene(), "/fluid/0/box/max"), "/fluid/0/box/max", "an array of 2 numbers");
  expect_refused(without(full_2d_scene(), "/materials/1/name"), "/materials/1/name", "a non-empty string");
}

TEST(SceneReaderRefuses, NonPositiveSpacing) {
  expect_refused(with(full_2d_scene(), "/particle_spacing", 0), "/particle_spacing", "a number > 0");
  expect_refused(with(full_2d_scene(), "/particle_spacing", -0.01), "/particle_spacing", "a number > 0");
}

TEST(SceneReaderRefuses, OtherNumbersOutOfRange) {
  expect_refused(with(full_2d_scene(), "/kernel/smoothing_ratio", 0), "/kernel/smoothing_ratio", "a number > 0");
  expect_refused(with(full_2d_scene(), "/materials/0/rest_density", -1), "/materials/0/rest_density", "a number > 0");
  expect_refused(with(full_2d_scene(), "/materials/0/kinematic_viscosity", -1e-6), "/materials/0/kinematic_viscosity",
                 "a number >= 0");
  expect_refused(with(full_2d_scene(), "/solver/max_density_ratio", 1), "/solver/max_density_ratio", "a number > 1");
  expect_refused(with(full_2d_scene(), "/solver/gravity_ramp_time", -0.1), "/solver/gravity_ramp_time",
                 "a number >= 0");
  expect_refused(with(full_2d_scene(), "/fluid/1/ball/radius", 0), "/fluid/1/ball/radius", "a number > 0");
  expect_refused(with(full_2d_scene(), "/solver/max_density_error", 0), "/solver/max_density_error",
                 "a number in (0, 1]");
  expect_refused(with(full_2d_scene(), "/solver/max_divergence_error", 2), "/solver/max_divergence_error",
                 "a number in (0, 1]");
  expect_refused(with(full_2d_scene(), "/solver/max_solver_iterations", 0), "/solver/max_solver_iterations",
                 "an integer in [1, 1000000]");
  expect_refused(with(full_2d_scene(), "/solver/max_solver_iterations", 2.5), "/solver/max_solver_iterations",
                 "an integer in [1, 1000000]");
  expect_refused(with(full_2d_scene(), "/solver/max_failed_solves", -3), "/solver/max_failed_solves",
                 "an integer in [1, 1000000]");
}

TEST(SceneReaderRefuses, VectorsOfTheWrongLength) {
  expect_refused(with(full_2d_scene(), "/gravity", json::array({0, 0, -9.81})), "/gravity",
                 "an array of 2 numbers [x, y]");
  expect_refused(with(full_2d_scene(), "/fluid/0/box/max", json::array({0.4})), "/fluid/0/box/max",
                 "an array of 2 numbers [x, y]");
  expect_refused(with(full_2d_scene(), "/fluid/0/box/max/0", "0.4"), "/fluid/0/box/max/0", "a number");
  expect_refused(with(full_2d_scene(), "/domain/periodic", json::array({true})), "/domain/periodic",
                 "an array of 2 booleans");
}

TEST(SceneReaderRefuses, DimensionOtherThanTwoOrThree) {
  expect_refused(with(full_2d_scene(), "/dimension", 4), "/dimension", "2 or 3");
  expect_refused(with(full_2d_scene(), "/dimension", 2.5), "/dimension", "2 or 3");
  expect_refused(with(full_2d_scene(), "/dimension", "2"), "/dimension", "2 or 3");
}

TEST(SceneReaderRefuses, UnknownNamesListingTheValidOnes) {
  expect_refused(
      with(full_2d_scene(), "/kernel/type", "gaussian"), "/kernel/type",
      R"(one of "cubic_spline", "wendland_c2", "wendland_c4", "quintic_spline", "poly6", "spiky", "viscosity")");
  expect_refused(with(full_2d_scene(), "/solver/scheme", "sph"), "/solver/scheme",
                 R"(one of "wcsph", "dfsph", "iisph")");
  expect_refused(with(full_2d_scene(), "/solver/equation_of_state", "cole"), "/solver/equation_of_state",
                 R"(one of "tait", "linear")");
  expect_refused(with(full_2d_scene(), "/solver/density", "sum"), "/solver/density",
                 R"(one of "summation", "continuity")");
  expect_refused(with(full_2d_scene(), "/solver/shifting", "on"), "/solver/shifting", R"(one of "none", "fickian")");
  expect_refused(with(full_2d_scene(), "/solver/viscosity", "none"), "/solver/viscosity",
                 R"(one of "artificial", "laminar")");
  expect_refused(with(full_2d_scene(), "/walls/slip", "slip"), "/walls/slip", R"(one of "no_slip", "free_slip")");
}

TEST(SceneReaderRefuses, FluidOutsideTheDomain) {
  json document = without(full_2d_scene(), "/walls");
  expect_refused(with(document, "/fluid/0/box/max/1", 2.5), "/fluid/0/box/max/1",
                 "a number <= 2 (the max[1] of the domain)");
  expect_refused(with(document, "/fluid/0/box/min/0", -0.2), "/fluid/0/box/min/0",
                 "a number >= -0.1 (the min[0] of the domain)");
  expect_refused(with(document, "/fluid/1/ball/centre/0", 1.65), "/fluid/1/ball",
                 "a ball inside the domain [-0.1, 1.7] x [-0.1, 2]");
}

TEST(SceneReaderRefuses, ABoxWithNoInside) {
  expect_refused(with(full_2d_scene(), "/fluid/0/box/max/1", 0), "/fluid/0/box/max/1", "a number > min[1] (0)");
}

TEST(SceneReaderRefuses, AContainerWithNoRoomForFluid) {
  // An empty inner box.
  expect_refused(with(full_2d_scene(), "/walls/container/max/0", 0), "/walls/container/max/0", "a number > min[0] (0)");
  // Fluid outside the container's inner box.
  expect_refused(with(full_2d_scene(), "/fluid/0/box/max/1", 1.3), "/fluid/0/box/max/1",
                 "a number <= 1.2 (the max[1] of the container's inner box)");
  expect_refused(with(full_2d_scene(), "/fluid/1/ball/centre/1", 0.05), "/fluid/1/ball",
                 "a ball inside the container's inner box [0, 1.6] x [0, 1.2]");
  // Fewer wall layers than the kernel support in spacings: the cubic spline reaches 2 h = 2.4
  // spacings here.
  expect_refused(with(full_2d_scene(), "/walls/layers", 2), "/walls/layers",
                 "an integer >= 3 (ceil(kernel support / spacing), the support being 2.4 spacings)");
  expect_refused(with(full_2d_scene(), "/walls/layers", 3.5), "/walls/layers", "an integer >= 3");
}

TEST(SceneReaderRefuses, WallsOutsideTheDomain) {
  // The domain's min[0] is -0.1; 4 layers of 0.005 reach 0.02 below the container's min.
  expect_refused(with(full_2d_scene(), "/domain/min/0", 0), "/walls/container/min/0",
                 "a number >= 0.02 (the domain's min[0] plus 4 wall layers of 0.005)");
  expect_refused(with(full_2d_scene(), "/domain/max/0", 1.61), "/walls/container/max/0",
                 "a number <= 1.59 (the domain's max[0] minus 4 wall layers of 0.005)");
}

TEST(SceneReaderRefuses, EndTimeNotAfterStartTime) {
  expect_refused(with(full_2d_scene(), "/time/end", 0.5), "/time/end", "a number > the start time (0.5)");
  expect_refused(with(full_2d_scene(), "/time/end", 0.1), "/time/end", "a number > the start time (0.5)");
}

TEST(SceneReaderRefuses, NonPositiveOutputInterval) {
  expect_refused(with(full_2d_scene(), "/time/output_interval", 0), "/time/output_interval", "a number > 0");
}

TEST(SceneReaderRefuses, AMaterialThatDoesNotExist) {
  expect_refused(with(full_2d_scene(), "/fluid/1/material", "air"), "/fluid/1/material",
                 R"(the name of a material: "water", "oil")");
  expect_refused(with(full_2d_scene(), "/materials/1/name", "water"), "/materials/1/name",
                 "a name no earlier material has");
}

TEST(SceneReaderRefuses, AFluidBlockWithNoLatticePoint) {
  // Particles sit at (k + 1/2) x 0.005 from the container's corner: 0.0025, 0.0075, ...
  expect_refused(with(with(full_2d_scene(), "/fluid/0/box/min/0", 0.003), "/fluid/0/box/max/0", 0.007), "/fluid/0/box",
                 "a shape holding at least one particle position");
  expect_refused(with(full_2d_scene(), "/fluid/1/ball", {{"centre", {0.005, 0.5}}, {"radius", 0.002}}), "/fluid/1/ball",
                 "a shape holding at least one particle position");
  // A ball as small, but centred on a lattice point, holds one.
  EXPECT_NO_THROW(parse(with(full_2d_scene(), "/fluid/1/ball", {{"centre", {0.0025, 0.5025}}, {"radius", 0.002}})));
}

TEST(SceneReaderRefuses, BothOrNeitherSpeedOfAMaterial) {
  const SceneError both = error_of(with(full_2d_scene(), "/materials/1/max_speed", 3).dump());
  EXPECT_STREQ(both.what(),
               R"(dam.json: /materials/1: expected exactly one of "sound_speed" and "max_speed", got both)");
  expect_refused(without(full_2d_scene(), "/materials/0/max_speed"), "/materials/0",
                 R"(exactly one of "sound_speed" and "max_speed")");
}

TEST(SceneReaderRefuses, UnknownOrRepeatedOutputFields) {
  expect_refused(with(full_2d_scene(), "/output/fields/2", "vorticity"), "/output/fields/2",
                 R"(one of "position", "velocity", "density", "pressure", "acceleration", "mass", "id")");
  expect_refused(with(full_2d_scene(), "/output/fields/2", "velocity"), "/output/fields/2",
                 "a field not listed before");
  expect_refused(with(full_2d_scene(), "/output/fields", json::array()), "/output/fields",
                 "a non-empty array of field names");
}

TEST(SceneReader, PseudoPeriodicInflow) {
  const json periodic = with(minimal_scene(), "/domain/periodic", json::array({true, false}));
  const scene::Scene s = parse(with(periodic, "/domain/inflow", json{{"velocity", 0.5}, {"length", 0.2}}));
  ASSERT_TRUE(s.domain.inflow);
  EXPECT_EQ(s.domain.inflow->velocity, 0.5);
  EXPECT_EQ(s.domain.inflow->length, 0.2);
  EXPECT_FALSE(parse(periodic).domain.inflow);
}

TEST(SceneReaderRefuses, AnInflowWithoutAPeriodicXAxisOrWcsph) {
  const json inflow{{"velocity", 0.5}, {"length", 0.2}};
  expect_refused(with(minimal_scene(), "/domain/inflow", inflow), "/domain/inflow",
                 "no inflow unless the x axis is periodic");
  const json periodic = with(minimal_scene(), "/domain/periodic", json::array({true, false}));
  const std::string length = "a number > 0 and < the domain's length along x (1)";
  expect_refused(with(periodic, "/domain/inflow", json{{"velocity", 0.5}, {"length", 1}}), "/domain/inflow/length",
                 length);
  expect_refused(with(periodic, "/domain/inflow", json{{"velocity", 0.5}}), "/domain/inflow/length", length);
  expect_refused(with(periodic, "/domain/inflow", json{{"velocity", "fast"}, {"length", 0.2}}),
                 "/domain/inflow/velocity", "a number");
  expect_unsupported(with(with(periodic, "/domain/inflow", inflow), "/solver", json{{"scheme", "dfsph"}}),
                     "/solver/scheme", "\"wcsph\" with a domain inflow");
}

TEST(SceneReader, AnInflowThatInjectsAPhase) {
  json periodic = with(minimal_scene(), "/domain/periodic", json::array({true, false}));
  periodic["materials"].push_back({{"name", "oil"}, {"rest_density", 800}, {"max_speed", 2}});
  const json injecting = with(periodic, "/domain/inflow", json{{"velocity", 0.5}, {"length", 0.2}, {"phase", "oil"}});
  const scene::Scene s = parse(injecting);
  ASSERT_TRUE(s.domain.inflow && s.domain.inflow->phase);
  EXPECT_EQ(*s.domain.inflow->phase, 1u);
  // The injected material makes the scene multiphase although every fluid block is water.
  EXPECT_EQ(scene::fluid_material_count(s), 2u);
  EXPECT_EQ(*parse(with(injecting, "/domain/inflow/phase", "water")).domain.inflow->phase, 0u);
  expect_refused(with(injecting, "/domain/inflow/phase", "air"), "/domain/inflow/phase",
                 R"(the name of a material: "water", "oil")");
  expect_refused(with(injecting, "/domain/inflow/phase", 1), "/domain/inflow/phase", "the name of a material");
  // Several fluid materials need WCSPH with summation density.
  expect_unsupported(with(injecting, "/solver", json{{"density", "continuity"}}), "/solver/density", "\"summation\"");
}

TEST(SceneReader, TheRecoveryOfAMaterialFromARegion) {
  json two = minimal_scene();
  two["materials"].push_back({{"name", "oil"}, {"rest_density", 800}, {"max_speed", 2}});
  two["fluid"].push_back({{"material", "oil"}, {"box", {{"min", {0.5, 0}}, {"max", {1, 0.5}}}}});
  const json recovery{{"material", "oil"}, {"region", {{"min", {0.5, 0}}, {"max", {1, 1}}}}};
  const scene::Scene s = parse(with(two, "/output/recovery", recovery));
  ASSERT_TRUE(s.output.recovery);
  EXPECT_EQ(s.output.recovery->material, 1u);
  EXPECT_EQ(s.output.recovery->region.max[1], 1);
  EXPECT_FALSE(parse(two).output.recovery);
  expect_refused(with(two, "/output/recovery/material", "air"), "/output/recovery/material", "the name of a material");
  json unused = minimal_scene();
  unused["materials"].push_back({{"name", "oil"}, {"rest_density", 800}, {"max_speed", 2}});
  expect_refused(with(unused, "/output/recovery", recovery), "/output/recovery/material",
                 "a material that some fluid block starts with");
  expect_refused(with(with(two, "/output/recovery", recovery), "/output/recovery/region/max/1", 1.5),
                 "/output/recovery/region", "a box inside the domain [0, 1] on axis 1");
  expect_refused(with(with(two, "/output/recovery", recovery), "/output/recovery/region/max/0", 0.4),
                 "/output/recovery/region/max/0", "a number > min[0] (0.5)");
  expect_refused(with(with(two, "/output/recovery", recovery), "/output/recovery/colour", 1), "/output/recovery/colour",
                 R"(one of the keys "material", "region")");
}

TEST(SceneReaderRefuses, NeitherDomainNorContainer) {
  expect_refused(without(without(full_2d_scene(), "/domain"), "/walls/container"), "/domain",
                 "only a scene with a wall container");
}

TEST(SceneReaderRefuses, ShapesThatAreNotExactlyOne) {
  expect_refused(with(full_2d_scene(), "/fluid/0/ball", {{"centre", {1, 1}}, {"radius", 0.1}}), "/fluid/0",
                 R"(exactly one shape key of "box", "ball")");
  expect_refused(without(full_2d_scene(), "/walls/obstacles/2/plane"), "/walls/obstacles/2",
                 R"(exactly one shape key of "box", "ball", "plane")");
  expect_refused(with(full_2d_scene(), "/walls/obstacles/2/plane/normal", {0, 0}), "/walls/obstacles/2/plane/normal",
                 "a non-zero vector");
}

TEST(SceneReader, ReadsAProbeSensor) {
  const scene::Scene s = parse(with(full_2d_scene(), "/probes/0/sensor", {{"diameter", 0.0045}, {"normal", {-1, 0}}}));
  ASSERT_TRUE(s.probes[0].sensor.has_value());
  EXPECT_EQ(s.probes[0].sensor->diameter, 0.0045);
  EXPECT_EQ(s.probes[0].sensor->normal, vec(-1, 0));
  EXPECT_FALSE(s.probes[1].sensor.has_value());
}

TEST(SceneReaderRefuses, BadProbes) {
  expect_refused(with(full_2d_scene(), "/probes/0/type", "velocity"), "/probes/0/type",
                 R"(one of "pressure", "water_height")");
  expect_refused(without(full_2d_scene(), "/probes/1/position"), "/probes/1/position", "an array of 2 numbers");
  expect_refused(with(full_2d_scene(), "/probes/0/position/1", 2.5), "/probes/0/position/1",
                 "a number in [-0.1, 2] (the domain's extent on axis 1)");
  expect_refused(with(full_2d_scene(), "/probes/1/name", "P1"), "/probes/1/name", "that no earlier probe has");
  for (const json& name : {json("P 1"), json("a,b"), json(""), json("time"), json(3)}) {
    expect_refused(with(full_2d_scene(), "/probes/0/name", name), "/probes/0/name",
                   "a name of letters, digits, '_', '-' and '.'");
  }
  expect_refused(with(full_2d_scene(), "/probes/0/where", 1), "/probes/0/where",
                 R"(one of the keys "name", "type", "position", "sensor")");
  expect_refused(with(full_2d_scene(), "/probes", json::object()), "/probes", "an array of probes");
  expect_refused(with(full_2d_scene(), "/probes/0/sensor", {{"diameter", 0}, {"normal", {-1, 0}}}),
                 "/probes/0/sensor/diameter", "a number > 0");
  expect_refused(with(full_2d_scene(), "/probes/0/sensor", {{"diameter", 0.01}, {"normal", {0, 0}}}),
                 "/probes/0/sensor/normal", "a non-zero vector");
  expect_refused(with(full_2d_scene(), "/probes/0/sensor", {{"diameter", 0.01}}), "/probes/0/sensor/normal",
                 "an array of 2 numbers");
  expect_refused(with(full_2d_scene(), "/probes/1/sensor", {{"diameter", 0.01}, {"normal", {0, 1}}}),
                 "/probes/1/sensor", "only a pressure probe has a sensing face");
  expect_refused(with(full_2d_scene(), "/output/probe_interval", 0), "/output/probe_interval", "a number > 0");
}

// ---------------------------------------------------------------------------------------------
// Scenes too large for the machine, and absurd values: refused before anything is allocated, at
// once. The bound of 1 s is generous: reading a scene is proportional to its text, never to the
// particles it implies (a scene of 10^20 particles is refused as fast as one of 10).

constexpr double seconds_to_refuse = 1.0;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Refused at `key_path`, the message giving the implied count, within seconds_to_refuse.
void expect_too_many_particles(const json& document, const std::string& key_path, const std::string& count) {
  const auto start = std::chrono::steady_clock::now();
  expect_refused(document, key_path, "a scene of at most ");
  EXPECT_LT(seconds_since(start), seconds_to_refuse);
  EXPECT_EQ(error_of(document.dump()).found(), count + " particles (lattice points to visit)");
}

TEST(SceneReaderRefuses, ATinySpacingInABigBox) {
  // [0, 0.5]² at 1e-7: (5e6 + 2)² lattice points visited, about 2.5e13.
  expect_too_many_particles(with(minimal_scene(), "/particle_spacing", 1e-7), "/fluid/0/box", "2.5e+13");
}

TEST(SceneReaderRefuses, WallsReachingAbsurdlyFar) {
  json obstacle = with(minimal_scene(), "/walls/obstacles",
                       json::array({{{"box", {{"min", {-1e300, 0}}, {"max", {1e300, 0.1}}}}}}));
  expect_refused(obstacle, "/walls/obstacles/0/box", "a shape within 2.14748e+09 particle spacings");
  // A container (open top) whose layers alone imply about (2·10^9) x (10^9) lattice points.
  const json thick = with(without(minimal_scene(), "/domain"), "/walls",
                          {{"layers", 1'000'000'000}, {"container", {{"min", {0, 0}}, {"max", {1, 1}}}}});
  expect_too_many_particles(thick, "/walls/container", "2e+18");
  // A plane's wall is sampled over the whole domain: (10^9 + 2) x 102 lattice points at 0.01.
  json plane = with(minimal_scene(), "/domain/max", {1e7, 1});
  plane["walls"] = {{"obstacles", {{{"plane", {{"point", {0, 0.1}}, {"normal", {0, 1}}}}}}}};
  expect_too_many_particles(plane, "/walls/obstacles/0/plane", "1.02e+11");
}

TEST(SceneReaderRefuses, ShapesEachWithinTheCapButTogetherBeyondIt) {
  // Two boxes [0, n] x [0, 1] at spacing 1 visit 3 (n + 2) lattice points each (anchor 0: from
  // k = -1 to n on x, -1 to 1 on y): each 60% of the cap, together 120%.
  const double n = std::floor(0.6 * static_cast<double>(largest_particle_count()) / 3) - 2;
  json two = with(with(minimal_scene(), "/particle_spacing", 1), "/domain", {{"min", {0, 0}}, {"max", {n + 1, 2}}});
  two["fluid"] = {{{"material", "water"}, {"box", {{"min", {0, 0}}, {"max", {n, 1}}}}},
                  {{"material", "water"}, {"box", {{"min", {0, 0}}, {"max", {n, 1}}}}}};
  const auto start = std::chrono::steady_clock::now();
  const SceneError error = error_of(two.dump());
  EXPECT_LT(seconds_since(start), seconds_to_refuse);
  EXPECT_EQ(error.key_path(), "/particle_spacing") << error.what();
  EXPECT_NE(error.found().find(" particles"), std::string::npos) << error.what();
}

TEST(SceneReader, ExtremeValuesGiveASceneOrAnErrorAtOnce) {
  const std::vector<std::pair<std::string, json>> changes{
      {"/particle_spacing", 1e308},
      {"/particle_spacing", 5e-324},
      {"/domain/max", {1e308, 1e308}},
      {"/domain/min", {-1e308, -1e308}},
      {"/fluid/0/box/min", {-1e308, 0}},
      {"/fluid/0/box/max", {1e308, 0.5}},
      {"/dimension", 18446744073709551615u},
      {"/dimension", -9223372036854775807},
      {"/solver/max_solver_iterations", 9223372036854775807},
      {"/solver/max_failed_solves", 18446744073709551615u},
      {"/walls/layers", 2147483647},
      {"/kernel/smoothing_ratio", 1e308},
      {"/time/end", 1e308},
      {"/gravity", {1e308, -1e308}},
      {"/materials/0/rest_density", 1e-308},
  };
  for (const auto& [pointer, value] : changes) {
    const auto start = std::chrono::steady_clock::now();
    try {
      const scene::Scene s = parse(with(minimal_scene(), pointer, value));
      EXPECT_EQ(s.dimension, 2) << pointer;
    } catch (const SceneError& error) {
      EXPECT_EQ(error.file(), file_name) << error.what();
    }
    EXPECT_LT(seconds_since(start), seconds_to_refuse) << pointer << " = " << value.dump();
  }
  // Not JSON at all: NaN, infinity, a number beyond a double.
  for (const std::string number : {"NaN", "nan", "Infinity", "-inf", "1e400", "-1e999"}) {
    json document = minimal_scene();
    std::string text = document.dump();
    text.replace(text.find("0.01"), 4, number);
    const SceneError error = error_of(text);
    EXPECT_EQ(error.expected(), "valid JSON") << number << ": " << error.what();
  }
}

TEST(SceneReaderRefuses, EveryTruncationOfAScene) {
  const std::string text = full_2d_scene().dump(2);
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t length = 0; length < text.size(); ++length) {
    const SceneError error = error_of(text.substr(0, length));
    EXPECT_EQ(error.expected(), "valid JSON") << length << ": " << error.what();
  }
  EXPECT_LT(seconds_since(start), seconds_to_refuse * 10) << text.size() << " truncations";
}

}  // namespace
}  // namespace tide::io
