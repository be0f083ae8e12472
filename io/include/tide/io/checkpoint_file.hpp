#pragma once

// A run's checkpoint (docs/output.md, "Checkpoints"): one HDF5 file holding a StateArchive and
// what it was written for, read back only by a run of the same scene, precision and format.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "tide/core/state_archive.hpp"

namespace tide::io {

/// The layout version of checkpoint files: raised whenever what a checkpoint holds changes, so
/// that an older file is refused rather than misread.
inline constexpr int checkpoint_format_version = 1;

/// What a checkpoint was written for: a resume refuses any difference.
struct CheckpointIdentity {
  int format_version = checkpoint_format_version;
  std::string scene_hash;  // scene_file_hash of the scene file
  std::string precision;   // "double" or "float", the build's Real
  int dimension = 0;
  std::filesystem::path scene_file;  // not compared: where a resume that names no scene finds it
};

/// The identity of a checkpoint of `scene_file` written by this build.
CheckpointIdentity checkpoint_identity(const std::filesystem::path& scene_file, int dimension);

/// 64-bit FNV-1a of the file's bytes, as 16 hex digits; std::runtime_error naming the file when it
/// cannot be read.
std::string scene_file_hash(const std::filesystem::path& scene_file);

/// A checkpoint that is readable but was written for another scene, precision, dimension or
/// format version: the message names the file, what differs, and both values.
class CheckpointMismatch : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `archive` with `identity`, the step and the time (for h5dump) to `file`, through a
/// temporary beside it renamed into place: a run killed while writing leaves the previous
/// checkpoint as it was. std::runtime_error naming the file on failure.
void write_checkpoint(const std::filesystem::path& file, const CheckpointIdentity& identity, std::uint64_t step,
                      double time, const StateArchive& archive);

/// The scene file a checkpoint was written for (its identity's scene_file); std::runtime_error
/// naming the file when it is missing or not a checkpoint.
std::filesystem::path checkpoint_scene_file(const std::filesystem::path& file);

/// Reads a checkpoint written for `expected`. A file that is missing, not HDF5 or not laid out
/// as write_checkpoint writes it gives std::runtime_error naming the file and what was expected;
/// another identity gives CheckpointMismatch.
StateArchive read_checkpoint(const std::filesystem::path& file, const CheckpointIdentity& expected);

}  // namespace tide::io
