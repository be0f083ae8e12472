#include "surface_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "run_command.hpp"
#include "run_frames.hpp"
#include "tide/io/frame_writer.hpp"
#include "tide/io/mesh_repair.hpp"
#include "tide/surface/mesh_checks.hpp"
#include "tide/surface/particle_spacing.hpp"
#include "tide/surface/surface_files.hpp"
#include "tide/surface/surface_mesh.hpp"
#include "tide/surface/surface_outline.hpp"

namespace tide::app {
namespace {

/// A frame's positions, row-major, and its dimension.
struct FramePositions {
  double time = 0;
  int dimension = 0;
  std::vector<double> values;
};

FramePositions read_positions(const std::filesystem::path& file) {
  io::Frame frame = io::read_frame(file);
  io::FrameDataset& position = frame.datasets.at("position");  // read_frame checks it is there, (N, 2|3)
  return {frame.time, static_cast<int>(position.shape[1]), std::move(position.values)};
}

std::string numbered(const std::string& stem, std::size_t number, const std::string& extension) {
  char digits[24];
  std::snprintf(digits, sizeof digits, "%06zu", number);
  return stem + "_" + digits + extension;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// One frame's surface into `directory`; a line of what it holds and how long it took.
void reconstruct_frame(const FrameFile& frame_file, const FramePositions& frame, const surface::FieldSettings& settings,
                       const std::filesystem::path& directory) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t particles = frame.values.size() / static_cast<std::size_t>(frame.dimension);
  std::printf("frame %zu (t = %g s, %zu particles): ", frame_file.number, frame.time, particles);
  if (frame.dimension == 3) {
    const scene::TriangleMesh mesh = surface::reconstruct_surface(frame.values, settings);
    const double seconds = seconds_since(start);
    surface::write_ply(directory / numbered("surface", frame_file.number, ".ply"), mesh);
    surface::write_obj(directory / numbered("surface", frame_file.number, ".obj"), mesh);
    const surface::MeshTopology topology = surface::mesh_topology(mesh);
    const double particle_volume = static_cast<double>(particles) * std::pow(settings.particle_spacing, 3);
    std::printf("%zu vertices, %zu triangles, %s, volume %.4g m^3 (%.3f of the particles'), meshed in %.3f s\n",
                mesh.vertices.size(), mesh.triangles.size(), topology.closed_and_oriented() ? "closed" : "NOT closed",
                io::signed_volume(mesh), io::signed_volume(mesh) / particle_volume, seconds);
  } else {
    const surface::Outline outline = surface::reconstruct_outline(frame.values, settings);
    const double seconds = seconds_since(start);
    surface::write_outline_svg(directory / numbered("outline", frame_file.number, ".svg"), outline);
    surface::write_outline_csv(directory / numbered("outline", frame_file.number, ".csv"), outline);
    const double particle_area = static_cast<double>(particles) * settings.particle_spacing * settings.particle_spacing;
    std::printf("%zu loops, area %.4g m^2 (%.3f of the particles'), outlined in %.3f s\n", outline.loops.size(),
                surface::enclosed_area(outline), surface::enclosed_area(outline) / particle_area, seconds);
  }
  std::fflush(stdout);
}

}  // namespace

int reconstruct_surfaces(const SurfaceOptions& options) {
  std::vector<FrameFile> frames;
  surface::FieldSettings settings{.smoothing_ratio = options.smoothing_ratio, .cell_ratio = options.cell_ratio};
  try {
    const std::vector<FrameFile> all_frames = list_frames(options.run_directory);
    frames = select_frames(all_frames, options.frames);
    if (options.particle_spacing) {
      settings.particle_spacing = *options.particle_spacing;
    } else {
      const FramePositions first = read_positions(all_frames.front().path);
      settings.particle_spacing = first.dimension == 2 ? surface::median_neighbour_distance<2>(first.values)
                                                       : surface::median_neighbour_distance<3>(first.values);
      std::printf("particle spacing %g m: the median nearest-neighbour distance in %s (--spacing sets it)\n",
                  settings.particle_spacing, all_frames.front().path.filename().c_str());
    }
  } catch (const std::exception& error) {
    std::cerr << "tide surface: " << error.what() << '\n';
    return exit_bad_input;
  }
  const std::filesystem::path directory =
      options.output_directory.empty() ? options.run_directory / "surface" : options.output_directory;
  std::filesystem::create_directories(directory);
  for (const FrameFile& frame_file : frames) {
    FramePositions frame;
    try {
      frame = read_positions(frame_file.path);
    } catch (const std::runtime_error& error) {
      std::cerr << "tide surface: " << error.what() << '\n';
      return exit_bad_input;
    }
    reconstruct_frame(frame_file, frame, settings, directory);
  }
  std::printf("tide surface: %zu frame(s) written to %s\n", frames.size(), directory.c_str());
  return exit_ok;
}

}  // namespace tide::app
