#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tide/core/particle_set.hpp"

namespace tide::io {

/// One dataset of a frame file, converted to double.
struct FrameDataset {
  /// (N) for scalar and index fields, (N, D) for vector fields.
  std::vector<std::size_t> shape;
  /// Row-major: component d of particle i of a vector field is values[i * D + d].
  std::vector<double> values;
};

/// A frame file read back: the attributes of its group and every dataset in it.
struct Frame {
  std::string group;  ///< e.g. "frame_000012"
  double time = 0;
  std::uint64_t step = 0;
  std::map<std::string, std::string> attributes;  ///< the extra string attributes
  std::map<std::string, FrameDataset> datasets;   ///< by field name
};

/// Reads one frame file as FrameWriter writes it (for tests and tools). A missing, truncated or
/// foreign file, or one not laid out as docs/output.md describes (no single frame group, no scalar
/// numeric "time" and "step", another attribute that is not one string, no "position" (N, 2|3), a
/// dataset that is not numbers of shape (N) or (N, D)), gives a std::runtime_error that names the
/// file and what was expected. HDF5 prints nothing.
Frame read_frame(const std::filesystem::path& path);

/// Whether a frame writer also writes each frame as a VTK file (docs/output.md, "VTK files").
enum class VtkFiles { off, on };

/// Writes a run's output for ParaView: one HDF5 file per frame and an XDMF file that names them.
///
/// Layout of `directory` after frames 0..k (see docs/output.md):
///   <run>_000000.h5 ... <run>_00000k.h5   one group /frame_00000i per file, one dataset per field,
///                                          and /xdmf_connectivity, the vertex cells ParaView draws
///   <run>.xdmf                             XDMF 3 temporal collection of those frames
///   <run>_000000.vtu ..., <run>.pvd        with VtkFiles::on: the same frames as VTK XML files and
///                                          their ParaView collection
///
/// Crash safety: every file is written under a hidden temporary name and renamed into place only
/// once it is complete and on disk, and the XDMF file is rewritten the same way after each frame.
/// A run killed at any moment therefore leaves an XDMF file that names only complete frames.
///
/// Frames are numbered 0, 1, 2, ... in the order they are written (the solver step is an
/// attribute). A writer opened on a directory that already holds a run replaces its files one by
/// one as it goes.
template <int D>
class FrameWriter {
 public:
  /// `fields`: the names of the fields to write; "position" is always written, listed or not.
  /// Names are checked against the particle set at each write (std::invalid_argument names an
  /// unknown field). `run_name` is the stem of the file names. Creates `directory` if absent.
  FrameWriter(std::filesystem::path directory, std::vector<std::string> fields, std::string run_name = "frames",
              VtkFiles vtk = VtkFiles::off);

  /// Writes the next frame and rewrites the XDMF file (and with VTK files, the frame's .vtu file,
  /// then the .pvd file); returns the path of the frame file.
  /// `attributes` become extra string attributes of the frame's group ("time" and "step" are
  /// taken). HDF5 and file-system failures give std::runtime_error naming the file; the frames
  /// already written and the XDMF file naming them stay valid.
  std::filesystem::path write(const ParticleSet<D>& set, double time, std::uint64_t step,
                              const std::map<std::string, std::string>& attributes = {});

  const std::filesystem::path& directory() const { return directory_; }
  std::filesystem::path xdmf_path() const;
  std::filesystem::path pvd_path() const;
  std::size_t frames_written() const { return grids_.size(); }

  /// The XDMF <Grid> element of each frame written so far, in order: what a checkpoint keeps.
  const std::vector<std::string>& xdmf_grids() const { return grids_; }
  /// Continues a run that had written the frames of `grids` (xdmf_grids of its writer): the next
  /// frame is numbered grids.size() and the XDMF file (and the .pvd file, with the times of the
  /// grids) names them all.
  void continue_after(std::vector<std::string> grids);

 private:
  std::filesystem::path directory_;
  std::vector<std::string> fields_;
  std::string run_name_;
  VtkFiles vtk_;
  /// The XDMF <Grid> element of each frame written, in order.
  std::vector<std::string> grids_;
  /// Interleaving buffer for vector fields, kept to avoid one allocation per field and frame.
  std::vector<Real> interleaved_;
};

extern template class FrameWriter<2>;
extern template class FrameWriter<3>;

}  // namespace tide::io
