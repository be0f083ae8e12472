#pragma once

// The HDF5 plumbing of io/'s files (frames, checkpoints): handles that close themselves, every
// failure one exception naming the file, the on-disk types, and the readers and writers of
// attributes and datasets they share.

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "tide/core/types.hpp"

namespace tide::io {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// HDF5 plumbing: handles that close themselves, and every failure as one exception naming the file.

/// While alive, HDF5 keeps its error stack to itself instead of printing it to stderr, so a failure
/// reaches the caller as one std::runtime_error. The previous setting comes back afterwards: an
/// embedding program that wants HDF5's printing keeps it for its own calls.
class QuietHdf5Errors {
 public:
  QuietHdf5Errors() {
    H5Eget_auto2(H5E_DEFAULT, &previous_function_, &previous_data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, previous_function_, previous_data_); }
  QuietHdf5Errors(const QuietHdf5Errors&) = delete;
  QuietHdf5Errors& operator=(const QuietHdf5Errors&) = delete;

 private:
  H5E_auto2_t previous_function_ = nullptr;
  void* previous_data_ = nullptr;
};

/// The most specific message on HDF5's error stack, the one raised deepest in the library (e.g.
/// "truncated file: eof = 512, ..."), which says more than the API call that failed; clears the stack.
inline std::string take_hdf5_error_detail() {
  std::string detail;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned position, const H5E_error2_t* error, void* out) -> herr_t {
        if (position == 0 && error->desc != nullptr) *static_cast<std::string*>(out) = error->desc;
        return 0;
      },
      &detail);
  H5Eclear2(H5E_DEFAULT);
  return detail;
}

[[noreturn]] inline void throw_hdf5_failure(const fs::path& file, std::string_view what) {
  std::string message = file.string() + ": " + std::string(what);
  if (const std::string detail = take_hdf5_error_detail(); !detail.empty()) message += " (HDF5: " + detail + ")";
  throw std::runtime_error(message);
}

/// An HDF5 identifier that closes itself.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Handle() {
    if (id_ >= 0) closer_(id_);
  }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }

  /// Closes now and returns the status, for the close whose failure matters: H5Fclose flushes.
  herr_t close() { return closer_(std::exchange(id_, H5I_INVALID_HID)); }

 private:
  hid_t id_;
  Closer closer_;
};

/// HDF5 calls on one file, checked: a failure throws with the file's name and what was being done.
struct CheckedCalls {
  const fs::path& file;
  std::string_view format = "frame file";  // what the file should be, for layout errors

  Handle own(hid_t id, Handle::Closer closer, std::string_view what) const {
    if (id < 0) throw_hdf5_failure(file, what);
    return Handle(id, closer);
  }
  void check(herr_t status, std::string_view what) const {
    if (status < 0) throw_hdf5_failure(file, what);
  }
};

/// A file that HDF5 reads fine but that is not laid out as TideSPH writes its `format`.
[[noreturn]] inline void throw_layout_error(const CheckedCalls& h5, std::string_view what) {
  throw std::runtime_error(h5.file.string() + ": not a TideSPH " + std::string(h5.format) + ": " + std::string(what));
}

// ---------------------------------------------------------------------------------------------
// Types on disk. Little-endian IEEE and fixed-width integers whatever the machine, so a file
// reads the same everywhere; in memory the native types, HDF5 converts if they differ.

static_assert(std::is_same_v<Index, std::uint32_t>, "index fields are written as 32-bit unsigned integers");
constexpr bool real_is_double = std::is_same_v<Real, double>;

inline hid_t real_memory_type() { return real_is_double ? H5T_NATIVE_DOUBLE : H5T_NATIVE_FLOAT; }
inline hid_t real_file_type() { return real_is_double ? H5T_IEEE_F64LE : H5T_IEEE_F32LE; }

// ---------------------------------------------------------------------------------------------
// Writing attributes and datasets.

inline void write_attribute(const CheckedCalls& h5, hid_t group, const std::string& name, hid_t file_type,
                            hid_t memory_type, const void* value) {
  const Handle space = h5.own(H5Screate(H5S_SCALAR), H5Sclose, "cannot create a dataspace");
  const Handle attribute = h5.own(H5Acreate2(group, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                                  H5Aclose, "cannot create attribute '" + name + "'");
  h5.check(H5Awrite(attribute.get(), memory_type, value), "cannot write attribute '" + name + "'");
}

/// A fixed-length UTF-8 string: h5dump prints it as text and every HDF5 binding reads it as a string.
inline void write_string_attribute(const CheckedCalls& h5, hid_t group, const std::string& name,
                                   const std::string& value) {
  const Handle type = h5.own(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create a string type");
  h5.check(H5Tset_size(type.get(), value.size() + 1), "cannot size the string type of attribute '" + name + "'");
  h5.check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot set the character set of attribute '" + name + "'");
  write_attribute(h5, group, name, type.get(), type.get(), value.c_str());
}

inline void write_dataset(const CheckedCalls& h5, hid_t group, const std::string& name, std::span<const hsize_t> shape,
                          hid_t file_type, hid_t memory_type, const void* values,
                          hid_t creation_properties = H5P_DEFAULT, hid_t link_properties = H5P_DEFAULT) {
  const Handle space = h5.own(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose,
                              "cannot create the dataspace of dataset '" + name + "'");
  const Handle dataset =
      h5.own(H5Dcreate2(group, name.c_str(), file_type, space.get(), link_properties, creation_properties, H5P_DEFAULT),
             H5Dclose, "cannot create dataset '" + name + "'");
  // The dataspace, not H5S_ALL, as selection: HDF5 then accepts a null buffer for zero particles.
  h5.check(H5Dwrite(dataset.get(), memory_type, space.get(), space.get(), H5P_DEFAULT, values),
           "cannot write dataset '" + name + "'");
}

// ---------------------------------------------------------------------------------------------
// Reading attributes and listing a group.

inline herr_t collect_link_name(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

inline herr_t collect_attribute_name(hid_t, const char* name, const H5A_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

inline std::vector<std::string> link_names(const CheckedCalls& h5, hid_t group, std::string_view group_name) {
  std::vector<std::string> names;
  h5.check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_link_name, &names),
           "cannot list the contents of " + std::string(group_name));
  return names;
}

inline std::vector<std::string> attribute_names(const CheckedCalls& h5, hid_t object, std::string_view object_name) {
  std::vector<std::string> names;
  h5.check(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute_name, &names),
           "cannot list the attributes of " + std::string(object_name));
  return names;
}

/// What an HDF5 object is, for messages.
inline std::string kind_name(H5I_type_t type) {
  switch (type) {
    case H5I_GROUP:
      return "a group";
    case H5I_DATASET:
      return "a dataset";
    case H5I_DATATYPE:
      return "a named datatype";
    default:
      return "another kind of object";
  }
}

/// `object` (described by `what`, e.g. "dataset 'density' of /frame_000012") is of `expected` kind.
inline void expect_kind(const CheckedCalls& h5, const Handle& object, H5I_type_t expected, const std::string& what) {
  const H5I_type_t found = H5Iget_type(object.get());
  if (found != expected)
    throw_layout_error(h5, what + ": expected " + kind_name(expected) + ", found " + kind_name(found));
}

/// Elements in an attribute: 1 for a scalar one. H5Aread writes them all, so readers with room for
/// one value check this first.
inline hssize_t element_count(const CheckedCalls& h5, hid_t attribute, const std::string& what) {
  const Handle space = h5.own(H5Aget_space(attribute), H5Sclose, "cannot read the shape of " + what);
  return H5Sget_simple_extent_npoints(space.get());
}

template <class T>
T read_number_attribute(const CheckedCalls& h5, hid_t group, const std::string& group_path, const std::string& name,
                        hid_t memory_type) {
  if (H5Aexists(group, name.c_str()) <= 0)
    throw_layout_error(h5, "group " + group_path + " has no '" + name + "' attribute");
  const std::string what = "attribute '" + name + "' of " + group_path;
  const Handle attribute = h5.own(H5Aopen(group, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open " + what);
  const Handle type = h5.own(H5Aget_type(attribute.get()), H5Tclose, "cannot read the type of " + what);
  const H5T_class_t type_class = H5Tget_class(type.get());
  if ((type_class != H5T_INTEGER && type_class != H5T_FLOAT) || element_count(h5, attribute.get(), what) != 1)
    throw_layout_error(h5, what + ": expected one number (a scalar integer or floating-point attribute)");
  T value{};
  h5.check(H5Aread(attribute.get(), memory_type, &value), "cannot read " + what);
  return value;
}

inline std::string read_string_attribute(const CheckedCalls& h5, hid_t group, const std::string& group_path,
                                         const std::string& name) {
  const std::string what = "attribute '" + name + "' of " + group_path;
  const Handle attribute = h5.own(H5Aopen(group, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open " + what);
  const Handle type = h5.own(H5Aget_type(attribute.get()), H5Tclose, "cannot read the type of " + what);
  const bool fixed_length_string = H5Tget_class(type.get()) == H5T_STRING && H5Tis_variable_str(type.get()) == 0;
  if (!fixed_length_string || element_count(h5, attribute.get(), what) != 1)
    throw_layout_error(h5, what + ": expected one fixed-length string");
  std::string value(H5Tget_size(type.get()), '\0');
  h5.check(H5Aread(attribute.get(), type.get(), value.data()), "cannot read " + what);
  value.erase(std::find(value.begin(), value.end(), '\0'), value.end());
  return value;
}

}  // namespace tide::io
