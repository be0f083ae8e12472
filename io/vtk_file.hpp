#pragma once

// Particles as VTK XML files (docs/output.md, "VTK files"): one UnstructuredGrid file (.vtu) per
// frame, every particle a vertex cell, the data appended raw after the XML header; and the
// ParaView collection (.pvd) that names the frames with their times.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tide/core/particle_set.hpp"

namespace tide::io {

/// Writes `fields` of `set` (each a field of it; "position" becomes the points, 2D padded with
/// z = 0, the others point data with their own component count) and the frame's time and step as
/// field data. std::runtime_error naming the file if it cannot be written.
template <int D>
void write_vtu_file(const std::filesystem::path& path, const ParticleSet<D>& set, const std::vector<FieldInfo>& fields,
                    double time, std::uint64_t step);

/// One frame of a collection: its file, relative to the collection, and its time.
struct CollectionEntry {
  std::string file;
  double time = 0;
};

/// The .pvd document that names `entries` in order.
std::string pvd_document(const std::vector<CollectionEntry>& entries);

}  // namespace tide::io
