#include "render_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <vector>

#include "movie.hpp"
#include "run_command.hpp"
#include "run_frames.hpp"
#include "run_walls.hpp"
#include "tide/core/parallel.hpp"
#include "tide/io/frame_writer.hpp"
#include "tide/render/camera.hpp"
#include "tide/render/density_heatmap.hpp"
#include "tide/render/mesh_shading.hpp"
#include "tide/render/particle_splats.hpp"
#include "tide/render/picture_labels.hpp"
#include "tide/render/png_file.hpp"
#include "tide/surface/surface_mesh.hpp"

namespace tide::app {
namespace {

/// A frame's positions (row-major), its dimension and the values to colour its particles by.
struct ColouredFrame {
  FramePositions positions;
  std::vector<double> values;
  std::string label;  // the field's name, |name| for a vector field's magnitude
};

/// The frame's positions and, unless `field` is empty, the field's values.
ColouredFrame read_coloured_frame(const std::filesystem::path& file, const std::string& field) {
  io::Frame frame = io::read_frame(file);
  ColouredFrame result;
  result.positions = take_positions(frame);
  if (field.empty()) return result;
  const auto found = frame.datasets.find(field);
  if (found == frame.datasets.end()) {
    std::string names;
    for (const auto& [name, dataset] : frame.datasets) names += (names.empty() ? "" : ", ") + name;
    throw std::invalid_argument(file.string() + ": no field '" + field + "' (the frame has " + names + ")");
  }
  const io::FrameDataset& dataset = found->second;
  const std::size_t count = dataset.shape[0], columns = dataset.shape.size() == 2 ? dataset.shape[1] : 1;
  result.label = columns == 1 ? field : "|" + field + "|";
  result.values.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    double squared = 0;
    for (std::size_t c = 0; c < columns; ++c)
      squared += dataset.values[i * columns + c] * dataset.values[i * columns + c];
    result.values[i] = columns == 1 ? dataset.values[i] : std::sqrt(squared);
  }
  return result;
}

struct PictureSize {
  int width = 0;
  int height = 0;
};

PictureSize parse_size(const std::string& text) {
  int width = 0, height = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &end) != 2 || width < 320 || height < 240 || width > 8192 ||
      height > 8192)
    throw std::invalid_argument("--size " + text + ": expected WxH, from 320x240 to 8192x8192 pixels");
  return {width, height};
}

/// What every frame shares: the box the particles stay in (the fluid's, and with the walls and
/// bodies), the range of the field, the spacing.
struct RunExtent {
  render::Point3 lowest;
  render::Point3 highest;
  render::Point3 fluid_lowest;
  render::Point3 fluid_highest;
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  int dimension = 0;
  std::string label;
};

/// Grows [lowest, highest] to hold `positions` (row-major, `dimension` per point).
void grow_box(render::Point3& lowest, render::Point3& highest, const std::vector<double>& positions, int dimension) {
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const auto d = k % static_cast<std::size_t>(dimension);
    lowest[d] = std::min(lowest[d], positions[k]);
    highest[d] = std::max(highest[d], positions[k]);
  }
}

/// The extent of the selected frames; with `walls`, the box holds their walls and bodies too.
RunExtent measure(const std::vector<FrameFile>& frames, const std::string& field, const RunWalls* walls) {
  RunExtent extent;
  const double infinity = std::numeric_limits<double>::infinity();
  extent.fluid_lowest = {infinity, infinity, infinity};
  extent.fluid_highest = {-infinity, -infinity, -infinity};
  for (const FrameFile& file : frames) {
    const ColouredFrame frame = read_coloured_frame(file.path, field);
    const FramePositions& positions = frame.positions;
    extent.dimension = positions.dimension;
    extent.label = frame.label;
    grow_box(extent.fluid_lowest, extent.fluid_highest, positions.values, positions.dimension);
    for (const double value : frame.values) {
      extent.low = std::min(extent.low, value);
      extent.high = std::max(extent.high, value);
    }
  }
  if (extent.dimension == 2) extent.fluid_lowest[2] = extent.fluid_highest[2] = 0;
  extent.lowest = extent.fluid_lowest;
  extent.highest = extent.fluid_highest;
  for (const FrameFile& file : frames) {
    if (walls == nullptr || walls->empty()) break;
    const WallParticles particles = walls->at(file.number);
    grow_box(extent.lowest, extent.highest, particles.walls, extent.dimension);
    grow_box(extent.lowest, extent.highest, particles.bodies, extent.dimension);
  }
  if (extent.dimension == 2) extent.lowest[2] = extent.highest[2] = 0;
  return extent;
}

/// The colour of a surface drawn by --surface, of the walls and of the rigid bodies.
constexpr render::Colour water = {0x4a, 0x90, 0xd9};
constexpr render::Colour wall_grey = {0x9a, 0x9a, 0x9a};
constexpr render::Colour body_brown = {0x8b, 0x5a, 0x2b};

/// The wall particles a 3D picture shows: those beyond the fluid's box on a side that faces the
/// camera, and on none that faces away, would stand between the camera and the fluid and are left
/// out (the near walls of a tank, a lid); the floor and the far walls, beyond the box on a side
/// facing away, stay along their whole length.
std::vector<double> walls_not_in_front(const std::vector<double>& walls, const render::Camera& camera,
                                       const RunExtent& extent) {
  std::vector<double> kept;
  for (std::size_t i = 0; i + 3 <= walls.size(); i += 3) {
    bool near_side = false, far_side = false;
    for (std::size_t d = 0; d < 3; ++d) {
      const bool above = walls[i + d] > extent.fluid_highest[d], below = walls[i + d] < extent.fluid_lowest[d];
      near_side = near_side || (camera.forward[d] < 0 && above) || (camera.forward[d] > 0 && below);
      far_side = far_side || (camera.forward[d] > 0 && above) || (camera.forward[d] < 0 && below);
    }
    if (!near_side || far_side)
      kept.insert(kept.end(), walls.begin() + static_cast<std::ptrdiff_t>(i),
                  walls.begin() + static_cast<std::ptrdiff_t>(i + 3));
  }
  return kept;
}

/// The walls in grey and the bodies in brown, as discs of the particles' size (2D) or shaded
/// spheres against `depth` (3D, the walls in front of the fluid left out).
void draw_walls(render::Image& image, const render::Camera& camera, const RunExtent& extent,
                const WallParticles& particles, double radius, std::vector<double>& depth) {
  const std::vector<double> walls =
      extent.dimension == 3 ? walls_not_in_front(particles.walls, camera, extent) : particles.walls;
  render::draw_particles(image, camera, extent.dimension, walls, wall_grey, radius, depth);
  render::draw_particles(image, camera, extent.dimension, particles.bodies, body_brown, radius, depth);
}

}  // namespace

int render_frames(const RenderOptions& options) {
  const std::string field = options.surface || options.heatmap ? "" : options.field;
  std::vector<FrameFile> frames;
  PictureSize size;
  std::optional<render::ColourScale> scale;
  RunExtent extent;
  std::optional<RunWalls> walls;
  double spacing = 0;
  try {
    const std::vector<FrameFile> all_frames = list_frames(options.input.run_directory);
    frames = select_frames(all_frames, options.input.frames);
    size = parse_size(options.size);
    scale.emplace(render::ColourScale{render::Colormap(options.colormap), 0, 1});
    walls.emplace(options.input.run_directory);
    extent = measure(frames, field, options.heatmap ? nullptr : &*walls);
    if (options.surface && extent.dimension != 3)
      throw std::invalid_argument("--surface draws the surfaces of 3D runs; tide surface writes a 2D run's outlines");
    if (options.heatmap && extent.dimension != 2)
      throw std::invalid_argument("--heatmap draws the density of a 2D run's points over its floor");
    if (options.heatmap) {
      // Every frame on one scale from an empty floor, and the points' kernels whole in the picture.
      scale->low = 0;
      scale->high = options.heatmap_max;
      extent.label = "agents/m2";
      for (int d = 0; d < 2; ++d) {
        extent.lowest[static_cast<std::size_t>(d)] -= 2 * options.smoothing_length;
        extent.highest[static_cast<std::size_t>(d)] += 2 * options.smoothing_length;
      }
    } else {
      scale->low = extent.low;
      scale->high = extent.high;
    }
    spacing = particle_spacing(options.input, all_frames.front());
  } catch (const std::exception& error) {
    std::cerr << "tide render: " << error.what() << '\n';
    return exit_bad_input;
  }

  const std::filesystem::path directory = picture_directory(options.input, "render");
  const render::PixelRegion plot = {10, 40, size.width - 170, size.height - 50};
  const render::PixelRegion bar = {size.width - 140, 70, 24, size.height - 120};
  const render::Camera camera = extent.dimension == 2 ? render::camera_2d(extent.lowest, extent.highest, plot)
                                                      : render::camera_3d(extent.lowest, extent.highest, plot);
  // Frames are drawn in parallel, one a task; HDF5 (Debian's build is not thread-safe) reads one
  // frame at a time. A frame that cannot be read is reported after the others, the first in
  // frame order, whatever the threads' order.
  std::mutex reading;
  std::vector<std::string> read_errors(frames.size());
  parallel_blocks(frames.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const FrameFile& file = frames[f];
      ColouredFrame frame;
      WallParticles wall_particles;
      try {
        const std::lock_guard<std::mutex> lock(reading);
        frame = read_coloured_frame(file.path, field);
        if (!options.heatmap) wall_particles = walls->at(file.number);
      } catch (const std::exception& error) {
        read_errors[f] = error.what();
        continue;
      }
      render::Image image(size.width, size.height, {0xff, 0xff, 0xff});
      std::vector<double> depth = extent.dimension == 3 ? render::empty_depth(camera) : std::vector<double>();
      if (!options.heatmap) draw_walls(image, camera, extent, wall_particles, spacing / 2, depth);
      if (options.surface) {
        const scene::TriangleMesh mesh =
            surface::reconstruct_surface(frame.positions.values, {.particle_spacing = spacing});
        render::draw_mesh(image, camera, mesh, water, depth);
      } else if (options.heatmap) {
        render::draw_density_heatmap(image, camera, frame.positions.values, options.smoothing_length, *scale);
      } else {
        render::draw_particles(image, camera, frame.positions.dimension, frame.positions.values, frame.values, *scale,
                               spacing / 2, depth);
      }
      if (!options.surface) render::draw_colour_bar(image, bar, *scale, extent.label);
      render::draw_time_stamp(image, frame.positions.time);
      render::write_png(directory / numbered_file_name("frame", file.number, ".png"), image);
    }
  });
  for (const std::string& error : read_errors) {
    if (error.empty()) continue;
    std::cerr << "tide render: " << error << '\n';
    return exit_bad_input;
  }
  const std::string what = options.surface ? "the surface" : options.heatmap ? "the density heat map" : options.field;
  std::cout << "tide render: " << frames.size() << " PNG frame(s) of " << what << " in " << directory.string() << '\n';
  if (assemble_movie(directory, frames.front().number, directory / "movie.mp4"))
    std::cout << "tide render: movie " << (directory / "movie.mp4").string() << '\n';
  return exit_ok;
}

}  // namespace tide::app
