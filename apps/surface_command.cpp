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
#include "tide/surface/mesh_smoothing.hpp"
#include "tide/surface/surface_files.hpp"
#include "tide/surface/surface_mesh.hpp"
#include "tide/surface/surface_outline.hpp"

namespace tide::app {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// One frame's surface into `directory`; a line of what it holds and how long it took.
void reconstruct_frame(const FrameFile& frame_file, const FramePositions& frame, const SurfaceOptions& options,
                       const surface::FieldSettings& settings, const std::filesystem::path& directory) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t particles = frame.values.size() / static_cast<std::size_t>(frame.dimension);
  std::printf("frame %zu (t = %g s, %zu particles): ", frame_file.number, frame.time, particles);
  if (frame.dimension == 3) {
    scene::TriangleMesh mesh = surface::reconstruct_surface(frame.values, settings);
    surface::smooth_taubin(mesh, {.iterations = options.smoothing_iterations});
    const double seconds = seconds_since(start);
    surface::write_ply(directory / numbered_file_name("surface", frame_file.number, ".ply"), mesh);
    surface::write_obj(directory / numbered_file_name("surface", frame_file.number, ".obj"), mesh);
    const surface::MeshTopology topology = surface::mesh_topology(mesh);
    const double particle_volume = static_cast<double>(particles) * std::pow(settings.particle_spacing, 3);
    std::printf("%zu vertices, %zu triangles, %s, volume %.4g m^3 (%.3f of the particles'), meshed in %.3f s\n",
                mesh.vertices.size(), mesh.triangles.size(), topology.closed_and_oriented() ? "closed" : "NOT closed",
                io::signed_volume(mesh), io::signed_volume(mesh) / particle_volume, seconds);
  } else {
    const surface::Outline outline = surface::reconstruct_outline(frame.values, settings);
    const double seconds = seconds_since(start);
    surface::write_outline_svg(directory / numbered_file_name("outline", frame_file.number, ".svg"), outline);
    surface::write_outline_csv(directory / numbered_file_name("outline", frame_file.number, ".csv"), outline);
    const double particle_area = static_cast<double>(particles) * settings.particle_spacing * settings.particle_spacing;
    std::printf("%zu loops, area %.4g m^2 (%.3f of the particles'), outlined in %.3f s\n", outline.loops.size(),
                surface::enclosed_area(outline), surface::enclosed_area(outline) / particle_area, seconds);
  }
  std::fflush(stdout);
}

}  // namespace

int reconstruct_surfaces(const SurfaceOptions& options) {
  std::vector<FrameFile> frames;
  surface::FieldSettings settings = options.field;
  try {
    const std::vector<FrameFile> all_frames = list_frames(options.input.run_directory);
    frames = select_frames(all_frames, options.input.frames);
    settings.particle_spacing = particle_spacing(options.input, all_frames.front());
  } catch (const std::exception& error) {
    std::cerr << "tide surface: " << error.what() << '\n';
    return exit_bad_input;
  }
  const std::filesystem::path directory = picture_directory(options.input, "surface");
  for (const FrameFile& frame_file : frames) {
    FramePositions frame;
    try {
      io::Frame read = io::read_frame(frame_file.path);
      frame = take_positions(read);
    } catch (const std::runtime_error& error) {
      std::cerr << "tide surface: " << error.what() << '\n';
      return exit_bad_input;
    }
    reconstruct_frame(frame_file, frame, options, settings, directory);
  }
  std::printf("tide surface: %zu frame(s) written to %s\n", frames.size(), directory.c_str());
  return exit_ok;
}

}  // namespace tide::app
