#pragma once

// Files of reconstructed surfaces, each written atomically (io/include/tide/io/atomic_file.hpp): a
// killed run leaves the previous file or the new one, never a truncated one. std::runtime_error
// naming the file on failure.

#include <filesystem>

#include "tide/core/triangle_mesh.hpp"
#include "tide/surface/surface_outline.hpp"

namespace tide::surface {

/// Binary little-endian PLY: vertex x, y, z as float, face vertex_indices as uchar count + int.
void write_ply(const std::filesystem::path& path, const scene::TriangleMesh& mesh);

/// Wavefront OBJ: "v x y z" lines, then "f a b c" (1-based), at full double precision.
void write_obj(const std::filesystem::path& path, const scene::TriangleMesh& mesh);

/// CSV with the header "loop,x,y": each loop's points in order, loops numbered from 0.
void write_outline_csv(const std::filesystem::path& path, const Outline& outline);

/// SVG of the outline filled (even-odd, so holes show), y up, scaled to `width` pixels across.
void write_outline_svg(const std::filesystem::path& path, const Outline& outline, int width = 800);

}  // namespace tide::surface
