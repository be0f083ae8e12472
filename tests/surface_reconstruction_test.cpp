// Surface reconstruction (surface/): closed, oriented meshes of the right volume and area from
// particles, the same for any thread count; outlines in 2D; the mesh files read back.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "particle_lattices.hpp"
#include "tide/core/kernels/cubic_spline.hpp"
#include "tide/core/parallel.hpp"
#include "tide/io/mesh_reader.hpp"
#include "tide/io/mesh_repair.hpp"
#include "tide/surface/marching_cases.hpp"
#include "tide/surface/mesh_checks.hpp"
#include "tide/surface/mesh_smoothing.hpp"
#include "tide/surface/particle_spacing.hpp"
#include "tide/surface/surface_files.hpp"
#include "tide/surface/surface_mesh.hpp"
#include "tide/surface/surface_outline.hpp"

namespace tide::surface {
namespace {

using testing_support::ball_of_particles;
using testing_support::box_of_particles;

void expect_closed_sphere_topology(const scene::TriangleMesh& mesh) {
  const MeshTopology topology = mesh_topology(mesh);
  EXPECT_EQ(topology.open_edges, 0u);
  EXPECT_EQ(topology.crowded_edges, 0u);
  EXPECT_EQ(topology.misoriented_edges, 0u);
  EXPECT_EQ(topology.euler_characteristic(), 2);  // one closed surface of genus 0
}

// Issue 38's acceptance case: a ball of 20 particles per radius. Measured (double, h = 1.2 Δx,
// cells of 0.48 Δx): 32 976 vertices, volume −0.25% and area +1.07% off the sphere's (the area's
// excess is the bumps the lattice leaves in the field; h = 1.5 Δx halves it but rounds more). The
// bounds are the issue's, 2% and 3%.
TEST(SurfaceReconstruction, BallOfParticlesGivesAClosedSphereOfItsVolumeAndArea) {
  const double radius = 1, spacing = radius / 20;
  const scene::TriangleMesh mesh =
      reconstruct_surface(ball_of_particles<3>(radius, spacing), {.particle_spacing = spacing});
  expect_closed_sphere_topology(mesh);
  EXPECT_NEAR(io::signed_volume(mesh) / (4.0 / 3.0 * std::numbers::pi * radius * radius * radius), 1.0, 0.02);
  EXPECT_NEAR(surface_area(mesh) / (4 * std::numbers::pi * radius * radius), 1.0, 0.03);
}

// A flat face lies where the particles' volume ends, Δx/2 beyond the outer particles (the
// reflection argument of surface_mesh.hpp): measured within 0.006 Δx on all six faces, the kernel's
// lattice-sum ripple; bound 0.01 Δx. Edges and corners are rounded on the kernel's scale, so the
// volume is not the particles' here (−3.2% for this small box) and is not asserted.
TEST(SurfaceReconstruction, BoxFacesLieWhereTheParticleVolumeEnds) {
  const double spacing = 0.05;
  const std::array<int, 3> counts = {16, 12, 8};
  const scene::TriangleMesh mesh =
      reconstruct_surface(box_of_particles(counts, spacing), {.particle_spacing = spacing});
  expect_closed_sphere_topology(mesh);
  for (int d = 0; d < 3; ++d) {
    double lowest = mesh.vertices[0][d], highest = mesh.vertices[0][d];
    for (const auto& vertex : mesh.vertices) {
      lowest = std::min(lowest, vertex[d]);
      highest = std::max(highest, vertex[d]);
    }
    EXPECT_NEAR(lowest, 0.0, 0.01 * spacing) << "axis " << d;
    EXPECT_NEAR(highest, counts[d] * spacing, 0.01 * spacing) << "axis " << d;
  }
}

TEST(SurfaceReconstruction, MeshIsTheSameForOneAndTwoThreads) {
  const double spacing = 0.05;
  const std::vector<double> particles = ball_of_particles<3>(1.0, spacing);
  const auto reconstruct = [&](int threads) {
    const ThreadLimit limit(threads);
    scene::TriangleMesh mesh = reconstruct_surface(particles, {.particle_spacing = spacing});
    smooth_taubin(mesh);
    return mesh;
  };
  const scene::TriangleMesh one = reconstruct(1), two = reconstruct(2);
  EXPECT_EQ(one.vertices, two.vertices);
  EXPECT_EQ(one.triangles, two.triangles);
}

// The field is not summed on blocks deep in the fluid (colour_field.cpp, blocks_inside): a ball
// of 32 particles per radius with a cavity of 3 Δx radius off its centre. Its blocks holding the
// interior value exactly are the blocks taken as inside; the colour field summed directly over the
// particles (the cubic spline itself) must exceed the surface level at every one of their points,
// and the cavity must still be meshed: two closed surfaces. Measured: 4 094 blocks taken as inside
// (1 280 when only whole tiles of 4^3 blocks were), the lowest direct value on them 0.9980 against
// the level 0.5004; volume −0.06% off the ball's less the cavity's (bound: issue 38's 2%).
TEST(SurfaceReconstruction, BlocksTakenAsInsideHoldFluidAndTheCavityIsMeshed) {
  const double spacing = 1.0, radius = 32.0, cavity_radius = 3.0;
  const std::array<double, 3> cavity = {8.0, -5.0, 3.0};
  std::vector<double> particles;
  {
    const std::vector<double> ball = ball_of_particles<3>(radius, spacing);
    for (std::size_t i = 0; i < ball.size(); i += 3) {
      double squared = 0;
      for (int d = 0; d < 3; ++d) squared += (ball[i + d] - cavity[d]) * (ball[i + d] - cavity[d]);
      if (squared >= cavity_radius * cavity_radius) particles.insert(particles.end(), &ball[i], &ball[i] + 3);
    }
  }
  const FieldSettings settings{.particle_spacing = spacing};
  const SparseGrid<3> grid = colour_field<3>(particles, settings);
  const double inside = interior_colour<3>(settings), level = surface_level<3>(settings, 0.5);

  // The particles binned by cells of one support radius, for the direct sums.
  const CubicSplineKernel<3> kernel(Real(settings.smoothing_ratio * spacing));
  const double support = kernel.support_radius();
  std::map<std::array<long, 3>, std::vector<std::size_t>> bins;
  const auto bin_of = [&](const double* x) {
    return std::array<long, 3>{long(std::floor(x[0] / support)), long(std::floor(x[1] / support)),
                               long(std::floor(x[2] / support))};
  };
  for (std::size_t i = 0; i < particles.size(); i += 3) bins[bin_of(&particles[i])].push_back(i);
  const double volume = std::pow(spacing, 3);
  const auto direct_colour = [&](const std::array<double, 3>& x) {
    const std::array<long, 3> centre = bin_of(x.data());
    double sum = 0;
    for (long dz = -1; dz <= 1; ++dz)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dx = -1; dx <= 1; ++dx) {
          const auto found = bins.find({centre[0] + dx, centre[1] + dy, centre[2] + dz});
          if (found == bins.end()) continue;
          for (const std::size_t i : found->second) {
            double squared = 0;
            for (int d = 0; d < 3; ++d) squared += (particles[i + d] - x[d]) * (particles[i + d] - x[d]);
            sum += volume * kernel.value(Real(std::sqrt(squared)));
          }
        }
    return sum;
  };

  std::size_t inside_blocks = 0;
  double lowest = inside;
  const std::size_t points = grid.points_per_block();
  for (std::size_t b = 0; b < grid.block_keys.size(); ++b) {
    const double* values = grid.values.data() + b * points;
    if (!std::all_of(values, values + points, [&](double value) { return value == inside; })) continue;
    ++inside_blocks;
    const GridPoint<3> block = unpack<3>(grid.block_keys[b]);
    for (std::size_t p = 0; p < points; ++p) {
      GridPoint<3> g{};
      for (int d = 0, rest = int(p); d < 3; ++d, rest /= grid.block_points)
        g[d] = block[d] * grid.block_points + rest % grid.block_points;
      lowest = std::min(lowest, direct_colour(grid.position(g)));
    }
  }
  std::printf("%zu blocks taken as inside, lowest direct value on them %.4f, level %.4f\n", inside_blocks, lowest,
              level);
  EXPECT_GT(inside_blocks, 1000u);
  EXPECT_GT(lowest, level);

  const scene::TriangleMesh mesh = marching_cubes(grid, level);
  const MeshTopology topology = mesh_topology(mesh);
  EXPECT_EQ(topology.open_edges, 0u);
  EXPECT_EQ(topology.crowded_edges, 0u);
  EXPECT_EQ(topology.misoriented_edges, 0u);
  EXPECT_EQ(topology.euler_characteristic(), 4);  // two closed surfaces of genus 0
  const double expected = 4.0 / 3.0 * std::numbers::pi * (std::pow(radius, 3) - std::pow(cavity_radius, 3));
  std::printf("volume %+.2f%% off the ball's less the cavity's\n", 100 * (io::signed_volume(mesh) / expected - 1));
  EXPECT_NEAR(io::signed_volume(mesh) / expected, 1.0, 0.02);
}

/// Random values in [0, 1) on blocks 1..3 along each axis of four points, zero on the grid's
/// lowest layer of points, as the colour field is next to the blocks it does not store.
template <int D>
SparseGrid<D> random_grid(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  SparseGrid<D> grid;
  grid.block_points = 4;
  grid.cell_size = 0.1;
  for (int n = 0; n < (D == 2 ? 9 : 27); ++n) {
    GridPoint<D> block{};
    for (int d = 0, rest = n; d < D; ++d, rest /= 3) block[d] = 1 + rest % 3;
    grid.block_keys.push_back(pack<D>(block));
  }
  std::sort(grid.block_keys.begin(), grid.block_keys.end());
  for (const std::uint64_t key : grid.block_keys) {
    const GridPoint<D> block = unpack<D>(key);
    for (std::size_t p = 0; p < grid.points_per_block(); ++p) {
      bool lowest_layer = false;
      for (int d = 0, rest = int(p); d < D; ++d, rest /= 4)
        lowest_layer = lowest_layer || (block[d] == 1 && rest % 4 == 0);
      grid.values.push_back(lowest_layer ? 0.0 : uniform(random));
    }
  }
  return grid;
}

// Taubin smoothing (10 iterations, k_PB = 0.1) of the 20-particles-per-radius ball: measured, the
// area's excess over the sphere's 1.07% -> 0.93% and the volume −0.245% -> −0.229% of the sphere's
// (a change of 0.016%; Laplacian smoothing alone would shrink it). Bound on the volume change
// 0.05%, three times the measured; the area must come down.
TEST(SurfaceReconstruction, TaubinSmoothingKeepsTheVolumeAndFlattensTheBumps) {
  const double spacing = 0.05;
  const scene::TriangleMesh mesh =
      reconstruct_surface(ball_of_particles<3>(1.0, spacing), {.particle_spacing = spacing});
  scene::TriangleMesh smoothed = mesh;
  smooth_taubin(smoothed);
  EXPECT_EQ(smoothed.triangles, mesh.triangles);
  EXPECT_NEAR(io::signed_volume(smoothed) / io::signed_volume(mesh), 1.0, 0.0005);
  EXPECT_LT(surface_area(smoothed), surface_area(mesh));
  EXPECT_GT(surface_area(smoothed), 4 * std::numbers::pi);  // still not below the sphere's
}

// Marching cubes on random values meets every case and every face ambiguity many times: the cells
// must still agree on each shared face.
TEST(SurfaceReconstruction, RandomFieldsGiveClosedOrientedSurfaces) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    for (const double level : {0.3, 0.5, 0.7}) {
      const scene::TriangleMesh mesh = marching_cubes(random_grid<3>(seed), level);
      const MeshTopology topology = mesh_topology(mesh);
      EXPECT_GT(mesh.triangles.size(), 1000u);
      EXPECT_TRUE(topology.closed_and_oriented())
          << "seed " << seed << ", level " << level << ": " << topology.open_edges << " open, "
          << topology.crowded_edges << " crowded, " << topology.misoriented_edges << " misoriented";
      EXPECT_GT(io::signed_volume(mesh), 0.0);  // normals out of the region above the level
    }
  }
}

// Every segment end is another's start (marching_squares throws otherwise), and the loops enclose
// the region above the level counter-clockwise.
TEST(SurfaceOutline, RandomFieldsGiveClosedLoops) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const Outline outline = marching_squares(random_grid<2>(seed), 0.5);
    EXPECT_GT(outline.loops.size(), 5u);
    EXPECT_GT(enclosed_area(outline), 0.0);
  }
}

TEST(SurfaceReconstruction, EveryCubeCaseIsTrianglesOfItsCrossedEdges) {
  for (unsigned mask = 0; mask < 256; ++mask) {
    const CubeCase& cell = cube_case(mask);
    int crossed = 0;
    for (int edge = 0; edge < 12; ++edge) {
      const std::array<int, 3> start = cube_edge_origin(edge);
      const int first = start[0] | start[1] << 1 | start[2] << 2;
      const int second = first | 1 << (edge / 4);
      crossed += ((mask >> first) & 1) != ((mask >> second) & 1);
    }
    // Each loop of k crossed edges is a fan of k − 2 triangles: at least crossed / 3 loops.
    EXPECT_LE(cell.triangle_count, crossed - 2 * ((crossed + 2) / 3 > 0 ? 1 : 0)) << "case " << mask;
    EXPECT_EQ(cell.triangle_count == 0, crossed == 0) << "case " << mask;
  }
}

// Measured: one loop, area +0.48% off the disc's (the particles' own area is +0.59% off it at
// this resolution); bound 1%.
TEST(SurfaceOutline, DiscOfParticlesGivesOneCounterClockwiseCircle) {
  const double radius = 1, spacing = radius / 20;
  const Outline outline = reconstruct_outline(ball_of_particles<2>(radius, spacing), {.particle_spacing = spacing});
  ASSERT_EQ(outline.loops.size(), 1u);
  EXPECT_NEAR(enclosed_area(outline) / (std::numbers::pi * radius * radius), 1.0, 0.01);
  for (const auto& point : outline.loops[0]) EXPECT_NEAR(std::hypot(point[0], point[1]), radius, spacing / 2);
}

TEST(SurfaceOutline, RingHasAHoleWalkedTheOtherWay) {
  const double spacing = 0.05;
  std::vector<double> ring;
  const std::vector<double> disc = ball_of_particles<2>(1.0, spacing);
  for (std::size_t i = 0; i < disc.size(); i += 2)
    if (std::hypot(disc[i], disc[i + 1]) > 0.5) ring.insert(ring.end(), {disc[i], disc[i + 1]});
  const Outline outline = reconstruct_outline(ring, {.particle_spacing = spacing});
  ASSERT_EQ(outline.loops.size(), 2u);
  int holes = 0;
  for (const auto& loop : outline.loops) holes += enclosed_area(Outline{{loop}}) < 0;
  EXPECT_EQ(holes, 1);
}

TEST(ParticleSpacing, MedianNeighbourDistanceOfALatticeIsItsSpacing) {
  const double spacing = 0.025;
  EXPECT_NEAR(median_neighbour_distance<3>(box_of_particles({10, 7, 5}, spacing)), spacing, 1e-12);
  EXPECT_NEAR(median_neighbour_distance<2>(ball_of_particles<2>(1.0, spacing)), spacing, 1e-12);
  EXPECT_THROW(median_neighbour_distance<3>(std::vector<double>{1, 2, 3}), std::invalid_argument);
}

TEST(SurfaceFiles, PlyAndObjReadBackAsWritten) {
  const double spacing = 0.1;
  const scene::TriangleMesh mesh =
      reconstruct_surface(ball_of_particles<3>(1.0, spacing), {.particle_spacing = spacing});
  const std::filesystem::path directory = std::filesystem::path(testing::TempDir()) / "surface_files_test";
  std::filesystem::create_directories(directory);
  write_ply(directory / "ball.ply", mesh);
  write_obj(directory / "ball.obj", mesh);
  for (const char* name : {"ball.ply", "ball.obj"}) {
    const scene::TriangleMesh read = io::read_mesh_file(directory / name);
    EXPECT_EQ(read.triangles, mesh.triangles) << name;
    ASSERT_EQ(read.vertices.size(), mesh.vertices.size()) << name;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(read.vertices[v][d], mesh.vertices[v][d], 1e-6) << name;  // PLY stores floats
  }
  EXPECT_FALSE(std::filesystem::exists(directory / ".ball.ply.tmp"));

  // A rewrite that fails (a directory where its hidden temporary file must go) throws and leaves
  // the good mesh whole, as a killed tide surface would.
  std::filesystem::create_directories(directory / ".ball.ply.tmp" / "blocker");
  EXPECT_THROW(write_ply(directory / "ball.ply", scene::TriangleMesh{}), std::runtime_error);
  EXPECT_EQ(io::read_mesh_file(directory / "ball.ply").triangles, mesh.triangles);
  std::filesystem::remove_all(directory / ".ball.ply.tmp");
}

TEST(SurfaceFiles, OutlineCsvListsEveryPoint) {
  const Outline outline{{{{0, 0}, {1, 0}, {1, 1}}, {{2, 2}, {3, 2}, {3, 3}, {2, 3}}}};
  const std::filesystem::path file = std::filesystem::path(testing::TempDir()) / "outline_test.csv";
  write_outline_csv(file, outline);
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 8u);
  EXPECT_EQ(lines[0], "loop,x,y");
  EXPECT_EQ(lines[1], "0,0,0");
  EXPECT_EQ(lines[7], "1,2,3");
}

}  // namespace
}  // namespace tide::surface
