#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "tide/io/frame_files.hpp"
#include "tide/io/frame_writer.hpp"
#include "tide/io/series_reader.hpp"

namespace py = pybind11;

namespace tide::python {
namespace {

/// A NumPy array that takes over `values` (no copy), of the given shape.
py::array array_of(std::vector<double>&& values, const std::vector<std::size_t>& shape) {
  auto* held = new std::vector<double>(std::move(values));
  const py::capsule owner(held, [](void* data) { delete static_cast<std::vector<double>*>(data); });
  return py::array(py::dtype::of<double>(), shape, held->data(), owner);
}

py::dict frame_dict(io::Frame&& frame) {
  py::dict d;
  d["time"] = frame.time;
  d["step"] = frame.step;
  py::dict attributes;
  for (const auto& [name, value] : frame.attributes) attributes[py::str(name)] = value;
  d["attributes"] = attributes;
  py::dict fields;
  for (auto& [name, dataset] : frame.datasets)
    fields[py::str(name)] = array_of(std::move(dataset.values), dataset.shape);
  d["fields"] = fields;
  return d;
}

py::dict series_dict(io::Series&& series) {
  py::dict columns;
  for (std::size_t c = 0; c < series.columns.size(); ++c) {
    const std::size_t rows = series.values[c].size();
    columns[py::str(series.columns[c])] = array_of(std::move(series.values[c]), {rows});
  }
  return columns;
}

}  // namespace

void bind_run_files(py::module_& module) {
  module.def(
      "frame_files",
      [](const std::filesystem::path& run_directory) {
        py::list paths;
        for (const io::FrameFile& file : io::list_frames(run_directory)) paths.append(file.path.string());
        return paths;
      },
      py::arg("run_directory"), "The frame files (frames_NNNNNN.h5) of a run directory, in frame order.");
  module.def(
      "read_frame", [](const std::filesystem::path& file) { return frame_dict(io::read_frame(file)); }, py::arg("path"),
      "One frame file: {'time', 'step', 'attributes', 'fields'}, each field an (N) or (N, D) float64 array.");
  module.def(
      "read_series", [](const std::filesystem::path& file) { return series_dict(io::read_series(file)); },
      py::arg("path"),
      "A CSV series a run wrote (probes.csv, recovery.csv, bodies.csv, crowd.csv): column name -> float64 array, "
      "'time' first.");
}

}  // namespace tide::python
