#pragma once

// A validation case: a scene built at a chosen resolution, run to its end time, and error
// metrics computed by the code against an analytic solution or an experiment. The registry
// (cases()) is what `tide validate` runs and what the regression tests check at low resolution.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "tide/core/kernels/kernel.hpp"

namespace tide::validation {

/// The scheme that moves people (docs/crowds.md): its cases name it, and only they run it.
inline constexpr std::string_view crowd_scheme = "crowd";

/// One error metric of a run (dimensionless unless its name says otherwise).
struct Metric {
  std::string name;  // snake_case, also the CSV column, e.g. "velocity_l2_error"
  double value = 0;
};

/// How a case is run: the scheme and the kernel.
/// Schemes: "wcsph" (summation density), "wcsph_continuity" (continuity density with δ-SPH diffusion, δ = 0.1),
/// "dfsph" and "iisph" (incompressible, summation density), and "crowd" (people, for the crowd cases only).
struct Variant {
  std::string scheme = "wcsph";
  KernelType kernel = KernelType::wendland_c2;
};

/// What one run of a case at one resolution produced.
struct RunRecord {
  std::string case_name;
  std::string scheme;
  std::string kernel;         // kernel_name() of the variant's kernel
  int resolution = 0;         // particles across the case's reference length (Case::resolution_meaning)
  std::size_t particles = 0;  // fluid particles
  std::uint64_t steps = 0;
  double wall_seconds = 0;      // of the time stepping alone, not set-up or metrics
  std::vector<Metric> metrics;  // metrics[0] is the case's primary error, the one plotted
  double particle_steps_per_second() const {
    return wall_seconds > 0 ? static_cast<double>(particles) * static_cast<double>(steps) / wall_seconds : 0;
  }
};

/// A figure a case draws from its runs beside the error plots every case has (e.g. the fundamental
/// diagram against Weidmann's curve): `script` returns the gnuplot script that writes the PNG
/// `output` from the case's successful runs.
struct Figure {
  std::string file;     // e.g. "crowd_fundamental_diagram_speed.png"
  std::string caption;  // the image's alternative text on the page
  std::function<std::string(const std::string& output, const std::vector<RunRecord>& runs)> script;
};

struct Case {
  std::string name;                       // command-line name, e.g. "poiseuille"
  std::string title;                      // e.g. "Poiseuille flow start-up"
  std::string reference;                  // what the errors are measured against, with the citation
  std::string resolution_meaning;         // e.g. "particles across the channel"
  std::vector<std::string> metric_notes;  // one line per metric: name and definition
  std::vector<int> resolutions;           // the study's default ladder (doubling where the cost allows)
  int test_resolution = 0;                // the low resolution the regression test runs
  std::vector<std::string> schemes;  // the schemes it applies to (e.g. only those with bodies); empty: the fluid ones
  std::vector<KernelType> kernels;   // the kernels it applies to; empty: all
  std::vector<Figure> figures;       // its own figures, beside the error plots
  bool runs_scheme(std::string_view scheme) const {
    return schemes.empty() ? scheme != crowd_scheme
                           : std::find(schemes.begin(), schemes.end(), scheme) != schemes.end();
  }
  bool runs_kernel(KernelType kernel) const {
    return kernels.empty() || std::find(kernels.begin(), kernels.end(), kernel) != kernels.end();
  }
  std::function<RunRecord(int resolution, const Variant& variant)> run;
};

/// Every validation case, in the order the study runs and documents them.
const std::vector<Case>& cases();

/// The case called `name`, or nullptr.
const Case* find_case(std::string_view name);

/// The schemes a Variant may name, the fluid ones then "crowd".
const std::vector<std::string>& scheme_names();

/// The schemes the study runs when none are named: scheme_names() less the `_cg` variants, DFSPH
/// and IISPH with solver.pressure_solver "conjugate_gradients", and `wcsph_riemann` (continuity
/// density with solver.riemann_solver "low_dissipation") and `wcsph_riemann_kgc` (that with
/// solver.kernel_gradient_correction), which are run by name.
const std::vector<std::string>& default_scheme_names();

}  // namespace tide::validation
