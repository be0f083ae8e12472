#include <optional>

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "tide/core/config.hpp"
#include "tide/core/parallel.hpp"

namespace py = pybind11;

namespace tide::python {

void bind_build(py::module_& module) {
  module.attr("__version__") = TIDE_VERSION;
  module.attr("precision") = TIDE_REAL_NAME;
  module.def("thread_count", &thread_count, "Worker threads the steps use now.");
  module.def(
      "set_threads",
      [](int threads) {
        // oneTBB's limit is process-wide, like the threads it caps: one for the module.
        static std::optional<ThreadLimit> limit;
        limit.reset();
        if (threads < 0) throw py::value_error("set_threads: expected a count >= 0, got " + std::to_string(threads));
        if (threads > 0) limit.emplace(threads);
      },
      py::arg("threads"),
      "Caps the worker threads (0: no cap, all cores). Results are bitwise the same for any count.");
}

}  // namespace tide::python
