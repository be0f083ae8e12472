// Probes against water at rest: a pressure probe reads ρ0 g depth within the 2% of the hydrostatic
// tank tests (wcsph_test.cpp), in the bulk and on the walls where sensors sit, and a water-height
// probe finds the free surface within half a particle spacing, in the middle of the tank and
// beside its walls. And probes.csv as ProbeWriter writes it.

#include "tide/solvers/probes.hpp"
#include "tide/solvers/wcsph.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "hydrostatic_scene.hpp"
#include "tide/io/probe_writer.hpp"
#include "tide/io/recovery_writer.hpp"

namespace tide {
namespace {

constexpr double gravity = 9.81;
constexpr double depth = 0.3;  // H
constexpr double width = 0.3;
constexpr int rows = 20;
constexpr double spacing = depth / rows;

// The hydrostatic tank of wcsph_test.cpp, 0.3 m deep and wide, with continuity density started
// from the hydrostatic density (Wcsph::set_hydrostatic_density), so that it is at rest from the
// first step, and h = 1.7 Δx as in the validation cases.
scene::Scene tank_scene(int dimension) {
  scene::Scene s = hydrostatic_scene(dimension, depth, width, rows);
  s.source = "probe test tank";
  s.smoothing_ratio = 1.7;
  s.solver.density = scene::DensityMethod::continuity;
  s.solver.delta_sph = 0;
  s.solver.gravity_ramp_time = 0;
  return s;
}

Vector<2> at(double x, double y) { return Vector<2>(Real(x), Real(y)); }

// Pressure probes in the bulk, on the bottom, on a side wall and in a bottom corner; height
// probes in the middle, one spacing from a wall and on it.
void expect_hydrostatic_readings(const Wcsph<2>& simulation) {
  for (const Vector<2>& point :
       {at(0.15, 0.15), at(0.15, 0.05), at(0.15, 0.0), at(0.0, 0.1), at(width, 0.05), at(0.0, 0.0), at(0.07, 0.2)}) {
    const double expected = 1000 * gravity * (depth - point[1]);
    EXPECT_NEAR(probe_pressure<2>(simulation, point), expected, 0.02 * expected)
        << "pressure at (" << point.transpose() << ") at t = " << simulation.time();
  }
  for (const double x : {0.15, spacing, 0.0, width}) {
    EXPECT_NEAR(probe_water_height<2>(simulation, at(x, 0)), depth, spacing / 2)
        << "height at x = " << x << " at t = " << simulation.time();
  }
  EXPECT_NEAR(probe_water_height<2>(simulation, at(0.15, 0.1)), depth - 0.1, spacing / 2);
}

TEST(Probes, ReadTheHydrostaticTankAtTheStart) { expect_hydrostatic_readings(Wcsph<2>(tank_scene(2))); }

// Settled for 1 s (about 3800 steps), with gravity raised over the first 0.5 s as in the 3D tank
// test of wcsph_test.cpp: started at once, the surface layer is kicked up and the pressures at
// depth end 2% high, a property of that start, not of the probes.
TEST(Probes, ReadTheHydrostaticTankAfterItSettles) {
  scene::Scene s = tank_scene(2);
  s.solver.gravity_ramp_time = 0.5;
  Wcsph<2> simulation(s);
  while (simulation.time() < 1.0) simulation.step();
  expect_hydrostatic_readings(simulation);
}

TEST(Probes, ReadTheHydrostaticTankIn3D) {
  const Wcsph<3> simulation(tank_scene(3));
  const Vector<3> bulk(Real(0.15), Real(0.15), Real(0.1));
  EXPECT_NEAR(probe_pressure<3>(simulation, bulk), 1000 * gravity * 0.2, 0.02 * 1000 * gravity * 0.2);
  const Vector<3> end_wall(Real(width), Real(0.15), Real(0.03));
  EXPECT_NEAR(probe_pressure<3>(simulation, end_wall), 1000 * gravity * 0.27, 0.02 * 1000 * gravity * 0.27);
  for (const double y : {0.15, 0.0}) {
    EXPECT_NEAR(probe_water_height<3>(simulation, Vector<3>(Real(0.15), Real(y), 0)), depth, spacing / 2) << y;
  }
}

// A sensing face on a wall reads the mean of ρ0 g (H − y) over it, which for a linear profile is
// the value at its centre: a 6Δx segment on the 2D tank's side wall and a 4Δx disc on the 3D
// tank's end wall, within the 2% of the point probes (the hydrostatic tank tests' tolerance for a
// tank that has moved; at this start on the hydrostatic lattice the three read within 0.02%).
// Through read_probes, as tide run reads them.
TEST(Probes, SensorOnAWallReadsTheHydrostaticPressureOverItsFace) {
  scene::Scene s = tank_scene(2);
  s.probes = {{"side", scene::ProbeType::pressure, {width, 0.1, 0}, scene::ProbeSensor{6 * spacing, {-1, 0, 0}}},
              {"bottom", scene::ProbeType::pressure, {0.15, 0, 0}, scene::ProbeSensor{6 * spacing, {0, 1, 0}}}};
  const Wcsph<2> simulation(s);
  const std::vector<double> values = read_probes<2>(simulation, s.probes);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_NEAR(values[0], 1000 * gravity * (depth - 0.1), 0.02 * 1000 * gravity * (depth - 0.1));
  EXPECT_NEAR(values[1], 1000 * gravity * depth, 0.02 * 1000 * gravity * depth);

  const Wcsph<3> tank(tank_scene(3));
  const double expected = 1000 * gravity * (depth - 0.1);
  const scene::ProbeSensor disc{4 * spacing, {1, 0, 0}};
  EXPECT_NEAR(sensor_pressure<3>(tank, Vector<3>(Real(width), Real(0.15), Real(0.1)), disc), expected, 0.02 * expected);
}

// A face half out of the water reads the force on its wetted half over its whole area: centred on
// the surface of the tank at rest, a face of diameter d reads ρ0 g d / 8 (the mean of ρ0 g (H − y)
// over the lower half, 0 over the upper), where the point probe at its centre reads 0 (measured:
// 0.14% low; checked to the 2% of the wall sensors).
TEST(Probes, SensorAcrossTheSurfaceReadsTheForceOnItsWettedPart) {
  const Wcsph<2> simulation(tank_scene(2));
  const double diameter = 0.2;
  const double expected = 1000 * gravity * diameter / 8;
  EXPECT_NEAR(sensor_pressure<2>(simulation, at(width, depth), scene::ProbeSensor{diameter, {1, 0, 0}}), expected,
              0.02 * expected);
}

// Outside the fluid a pressure probe reads the pressure at rest density and a height probe 0;
// read_probes returns the probes in the scene's order.
TEST(Probes, ReadNothingWhereThereIsNoFluid) {
  scene::Scene s = tank_scene(2);
  s.probes = {{"air", scene::ProbeType::pressure, {0.15, 0.4, 0}, std::nullopt},
              {"surface", scene::ProbeType::water_height, {0.15, 0, 0}, std::nullopt},
              {"above", scene::ProbeType::water_height, {0.15, 0.35, 0}, std::nullopt}};
  const Wcsph<2> simulation(s);
  const std::vector<double> values = read_probes<2>(simulation, s.probes);
  ASSERT_EQ(values.size(), 3u);
  EXPECT_EQ(values[0], 0);
  EXPECT_NEAR(values[1], depth, spacing / 2);
  EXPECT_EQ(values[2], 0);
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ProbeWriter, WritesTheHeaderAndRowsAndReplacesTheFileWhole) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / "tide_probe_writer_test";
  std::filesystem::remove_all(directory);
  scene::Scene s = tank_scene(2);
  s.probes = {{"P1", scene::ProbeType::pressure, {0.3, 0.05, 0}, scene::ProbeSensor{0.0045, {-1, 0, 0}}},
              {"H1", scene::ProbeType::water_height, {0.15, 0, 0}, std::nullopt}};
  io::ProbeWriter writer(directory / "probes.csv", s);
  writer.add(0, {2452.5, 0.3});
  writer.add(0.125, {2400, 0.29});
  EXPECT_THROW(writer.add(0.25, {1}), std::invalid_argument);
  writer.write();
  writer.add(0.25, {2300, 0.28});
  writer.write();
  EXPECT_EQ(file_text(directory / "probes.csv"),
            "# TideSPH probes of scene probe test tank\n"
            "# P1: pressure (Pa) at [0.3, 0.05], mean over a sensing face 0.0045 m across, normal [-1, 0]\n"
            "# H1: water_height (m) above [0.15, 0]\n"
            "time,P1,H1\n"
            "0,2452.5,0.3\n"
            "0.125,2400,0.29\n"
            "0.25,2300,0.28\n");
  EXPECT_EQ(writer.rows(), 3u);
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    ++files;
    EXPECT_EQ(entry.path().filename(), "probes.csv") << "a temporary was left behind";
  }
  EXPECT_EQ(files, 1u);
  std::filesystem::remove_all(directory);
}

TEST(RecoveryWriter, WritesTheMaterialTheRegionAndTheRows) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "tide_recovery_writer_test.csv";
  scene::Scene s = tank_scene(2);
  s.materials.push_back({"oil", 800, 0, 10.0, std::nullopt});
  s.output.recovery = scene::Recovery{1, {{0.1, 0.2, 0}, {0.5, 0.25, 0}}};
  io::RecoveryWriter writer(file, s, 2.5);
  writer.add(0, {2.5, 0});
  writer.add(0.5, {2, 0.2});
  EXPECT_THROW(writer.add(1, {1}), std::invalid_argument);
  writer.write();
  EXPECT_EQ(file_text(file),
            "# TideSPH recovery of scene probe test tank\n"
            "# material oil in the region [0.1, 0.2] to [0.5, 0.25]; initial mass 2.5 kg/m; recovery = 1 - mass / "
            "initial mass\n"
            "time,mass,recovery\n"
            "0,2.5,0\n"
            "0.5,2,0.2\n");
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace tide
