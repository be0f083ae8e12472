#include "tide/io/checkpoint_file.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <type_traits>
#include <vector>

#include "hdf5_calls.hpp"
#include "tide/io/atomic_file.hpp"

namespace tide::io {
namespace {

constexpr const char* format_name = "TideSPH checkpoint";

// The archive's four kinds, each a group of datasets named by the archive's paths, in its type.
constexpr const char* reals_group = "reals";
constexpr const char* doubles_group = "doubles";
constexpr const char* counts_group = "counts";
constexpr const char* texts_group = "texts";

template <class T>
void write_entries(const CheckedCalls& h5, hid_t file, hid_t links, const char* group,
                   const std::map<std::string, T>& entries, hid_t file_type, hid_t memory_type) {
  for (const auto& [path, values] : entries) {
    const hsize_t shape[] = {values.size()};
    write_dataset(h5, file, std::string(group) + "/" + path, shape, file_type, memory_type, values.data(), H5P_DEFAULT,
                  links);
  }
}

void write_file(const fs::path& path, const CheckpointIdentity& identity, std::uint64_t step, double time,
                const StateArchive& archive) {
  const QuietHdf5Errors quiet;
  const CheckedCalls h5{path, "checkpoint"};
  Handle file =
      h5.own(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "cannot create the HDF5 file");
  {
    const std::int64_t version = identity.format_version, dimension = identity.dimension;
    write_string_attribute(h5, file.get(), "format", format_name);
    write_attribute(h5, file.get(), "format_version", H5T_STD_I64LE, H5T_NATIVE_INT64, &version);
    write_string_attribute(h5, file.get(), "scene_hash", identity.scene_hash);
    write_string_attribute(h5, file.get(), "precision", identity.precision);
    write_string_attribute(h5, file.get(), "scene_file", identity.scene_file.string());
    write_attribute(h5, file.get(), "dimension", H5T_STD_I64LE, H5T_NATIVE_INT64, &dimension);
    write_attribute(h5, file.get(), "step", H5T_STD_U64LE, H5T_NATIVE_UINT64, &step);
    write_attribute(h5, file.get(), "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &time);
    const Handle links = h5.own(H5Pcreate(H5P_LINK_CREATE), H5Pclose, "cannot create link properties");
    h5.check(H5Pset_create_intermediate_group(links.get(), 1), "cannot set link properties");
    write_entries(h5, file.get(), links.get(), reals_group, archive.all_reals(), real_file_type(), real_memory_type());
    write_entries(h5, file.get(), links.get(), doubles_group, archive.all_doubles(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
    write_entries(h5, file.get(), links.get(), counts_group, archive.all_counts(), H5T_STD_U64LE, H5T_NATIVE_UINT64);
    write_entries(h5, file.get(), links.get(), texts_group, archive.all_texts(), H5T_STD_U8LE, H5T_NATIVE_UCHAR);
  }
  h5.check(file.close(), "cannot close the HDF5 file (flushing it failed)");
}

herr_t collect_visited_name(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

/// The values of a one-dimensional dataset of numbers, read as `memory_type` into T.
template <class T>
T read_values(const CheckedCalls& h5, hid_t group, const std::string& name, const std::string& what,
              hid_t memory_type) {
  const Handle dataset = h5.own(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "cannot open " + what);
  const Handle space = h5.own(H5Dget_space(dataset.get()), H5Sclose, "cannot read the shape of " + what);
  const Handle type = h5.own(H5Dget_type(dataset.get()), H5Tclose, "cannot read the type of " + what);
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (H5Sget_simple_extent_ndims(space.get()) != 1 || (type_class != H5T_FLOAT && type_class != H5T_INTEGER))
    throw_layout_error(h5, what + ": expected a one-dimensional dataset of numbers");
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  // A damaged header can claim any shape: the stored bytes bound it (stored contiguous, uncompressed).
  const hsize_t value_size = H5Tget_size(type.get());
  if (count < 0 ||
      (count > 0 && (value_size == 0 || H5Dget_storage_size(dataset.get()) / value_size < static_cast<hsize_t>(count))))
    throw_layout_error(h5, what + " claims more values than it stores");
  T values(static_cast<std::size_t>(count), {});
  h5.check(H5Dread(dataset.get(), memory_type, space.get(), space.get(), H5P_DEFAULT, values.data()),
           "cannot read " + what);
  return values;
}

/// Every dataset under `group` (at any depth), by its path there.
template <class T, class Put>
void read_entries(const CheckedCalls& h5, hid_t file, const char* group, hid_t memory_type, Put put) {
  if (H5Lexists(file, group, H5P_DEFAULT) <= 0) return;
  const Handle root = h5.own(H5Gopen2(file, group, H5P_DEFAULT), H5Gclose, "cannot open group /" + std::string(group));
  std::vector<std::string> names;
  h5.check(H5Lvisit(root.get(), H5_INDEX_NAME, H5_ITER_INC, collect_visited_name, &names),
           "cannot list group /" + std::string(group));
  for (const std::string& name : names) {
    const Handle object = h5.own(H5Oopen(root.get(), name.c_str(), H5P_DEFAULT), H5Oclose, "cannot open " + name);
    if (H5Iget_type(object.get()) != H5I_DATASET) continue;
    put(name, read_values<T>(h5, root.get(), name, "dataset /" + std::string(group) + "/" + name, memory_type));
  }
}

std::int64_t read_integer(const CheckedCalls& h5, hid_t file, const char* name) {
  return read_number_attribute<std::int64_t>(h5, file, "/", name, H5T_NATIVE_INT64);
}

[[noreturn]] void throw_mismatch(const fs::path& file, const std::string& what, const std::string& found,
                                 const std::string& expected) {
  throw CheckpointMismatch(file.string() + ": this checkpoint is of " + what + " " + found + ", not " + expected +
                           ": it cannot continue this run");
}

void check_format(const CheckedCalls& h5, hid_t file) {
  if (H5Aexists(file, "format") <= 0 || read_string_attribute(h5, file, "/", "format") != format_name)
    throw_layout_error(h5, "expected a string attribute 'format' = \"" + std::string(format_name) + "\" at the root");
}

/// The checkpoint `file`, open for reading: std::runtime_error naming it when it is missing or not
/// a checkpoint.
Handle open_checkpoint(const CheckedCalls& h5) {
  std::error_code error;
  if (!fs::is_regular_file(h5.file, error)) throw std::runtime_error(h5.file.string() + ": no checkpoint file there");
  Handle file = h5.own(H5Fopen(h5.file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open as an HDF5 file");
  check_format(h5, file.get());
  return file;
}

void check_identity(const CheckedCalls& h5, hid_t file, const CheckpointIdentity& expected) {
  const std::int64_t version = read_integer(h5, file, "format_version");
  if (version != expected.format_version)
    throw_mismatch(h5.file, "format version", std::to_string(version),
                   std::to_string(expected.format_version) + " (the version this tide reads)");
  const std::string precision = read_string_attribute(h5, file, "/", "precision");
  if (precision != expected.precision)
    throw_mismatch(h5.file, "precision", precision, expected.precision + " (this tide's build)");
  const std::int64_t dimension = read_integer(h5, file, "dimension");
  if (dimension != expected.dimension)
    throw_mismatch(h5.file, "dimension", std::to_string(dimension), std::to_string(expected.dimension));
  const std::string hash = read_string_attribute(h5, file, "/", "scene_hash");
  if (hash != expected.scene_hash)
    throw_mismatch(h5.file, "a scene with hash", hash,
                   expected.scene_hash + " (the scene file given: another scene, or the same one edited)");
}

}  // namespace

CheckpointIdentity checkpoint_identity(const fs::path& scene_file, int dimension) {
  return {checkpoint_format_version, scene_file_hash(scene_file), std::is_same_v<Real, double> ? "double" : "float",
          dimension, fs::absolute(scene_file)};
}

std::string scene_file_hash(const fs::path& scene_file) {
  std::ifstream in(scene_file, std::ios::binary);
  if (!in) throw std::runtime_error(scene_file.string() + ": cannot read the scene file");
  // FNV-1a, 64 bits (Fowler, Noll & Vo): the offset basis and prime of its specification.
  std::uint64_t hash = 14695981039346656037ULL;
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
    hash ^= static_cast<unsigned char>(*it);
    hash *= 1099511628211ULL;
  }
  std::array<char, 17> text{};
  std::snprintf(text.data(), text.size(), "%016llx", static_cast<unsigned long long>(hash));
  return text.data();
}

void write_checkpoint(const fs::path& file, const CheckpointIdentity& identity, std::uint64_t step, double time,
                      const StateArchive& archive) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  replace_atomically(file, [&](const fs::path& temporary) { write_file(temporary, identity, step, time, archive); });
}

fs::path checkpoint_scene_file(const fs::path& file) {
  const QuietHdf5Errors quiet;
  const CheckedCalls h5{file, "checkpoint"};
  const Handle handle = open_checkpoint(h5);
  return read_string_attribute(h5, handle.get(), "/", "scene_file");
}

StateArchive read_checkpoint(const fs::path& file, const CheckpointIdentity& expected) {
  const QuietHdf5Errors quiet;
  const CheckedCalls h5{file, "checkpoint"};
  const Handle handle = open_checkpoint(h5);
  check_identity(h5, handle.get(), expected);
  StateArchive archive;
  read_entries<std::vector<Real>>(h5, handle.get(), reals_group, real_memory_type(),
                                  [&](const std::string& path, std::vector<Real> v) { archive.put_reals(path, v); });
  read_entries<std::vector<double>>(
      h5, handle.get(), doubles_group, H5T_NATIVE_DOUBLE,
      [&](const std::string& path, std::vector<double> v) { archive.put_doubles(path, std::move(v)); });
  read_entries<std::vector<std::uint64_t>>(
      h5, handle.get(), counts_group, H5T_NATIVE_UINT64,
      [&](const std::string& path, std::vector<std::uint64_t> v) { archive.put_counts(path, std::move(v)); });
  read_entries<std::string>(h5, handle.get(), texts_group, H5T_NATIVE_UCHAR,
                            [&](const std::string& path, std::string v) { archive.put_text(path, std::move(v)); });
  return archive;
}

}  // namespace tide::io
