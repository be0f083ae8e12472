// Where the bytes per particle go (issue 8, target 4): builds step_bench's dam break, runs it, and
// lists every buffer the simulation keeps (Simulation::memory_usage, at capacity) in bytes per
// fluid particle, next to the process's resident memory as Linux counts it (VmRSS, and VmHWM: the
// peak while the scene is built and the peak of the steps after the warm-up).
//
//   memory_report [--dimension 2|3] [--particles N] [--scheme wcsph|dfsph|iisph] [--steps K]
//                 [--skin S] [--json FILE] [--allocator-default]
//
// Defaults: 3D, 10^6 particles, WCSPH, 25 steps (step_bench's 20 warm-up steps and 5 timed
// ones), the scheme's default neighbour skin; --skin sets solver.neighbor_skin in particle
// spacings (0: no candidate lists, the lists rebuilt every step, as in step_bench's BM_Step
// rows). The table is Markdown; --json also writes the figures for
// scripts/performance_report.py. Like the `tide` app, it first calls
// release_large_blocks_to_the_system(); --allocator-default leaves the C allocator as it is, to
// see what that costs in resident memory.

#include <cstddef>
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "dam_break_scenes.hpp"
#include "process_memory.hpp"
#include "tide/core/config.hpp"
#include "tide/core/large_block_release.hpp"
#include "tide/core/memory_usage.hpp"
#include "tide/solvers/simulation.hpp"

namespace {

using tide::bench::resident_memory;
using tide::bench::ResidentMemory;
namespace scene = tide::scene;

struct Options {
  int dimension = 3;
  std::size_t particles = 1'000'000;
  scene::Scheme scheme = scene::Scheme::wcsph;
  int steps = 25;
  std::optional<double> skin;  // solver.neighbor_skin; unset: the scheme's default
  std::string json;
  bool allocator_default = false;  // leave the allocator's large-block threshold as it is
};

scene::Scheme parse_scheme(std::string_view name) {
  for (scene::Scheme scheme : {scene::Scheme::wcsph, scene::Scheme::dfsph, scene::Scheme::iisph})
    if (tide::scheme_name(scheme) == name) return scheme;
  throw std::invalid_argument("unknown scheme '" + std::string(name) + "'");
}

// The whole of `value` as a number (std::stod, std::stoi, ...), or an error that names the option.
template <class Parse>
auto number(std::string_view flag, const std::string& value, Parse parse) {
  std::size_t used = 0;
  try {
    const auto parsed = parse(value, &used);
    if (used == value.size()) return parsed;
  } catch (const std::logic_error&) {
  }
  throw std::invalid_argument(std::string(flag) + " expects a number, got '" + value + "'");
}

Options parse(int argc, char** argv) {
  Options options;
  for (int k = 1; k < argc; ++k) {
    const std::string_view flag = argv[k];
    if (flag == "--allocator-default") {
      options.allocator_default = true;
      continue;
    }
    if (k + 1 >= argc) throw std::invalid_argument("missing value after " + std::string(flag));
    const std::string value = argv[++k];
    if (flag == "--dimension") {
      options.dimension =
          number(flag, value, [](const std::string& v, std::size_t* used) { return std::stoi(v, used); });
    } else if (flag == "--particles") {
      const long long particles =
          number(flag, value, [](const std::string& v, std::size_t* used) { return std::stoll(v, used); });
      if (particles < 1) throw std::invalid_argument("--particles is a count >= 1");
      options.particles = static_cast<std::size_t>(particles);
    } else if (flag == "--scheme") {
      options.scheme = parse_scheme(value);
    } else if (flag == "--steps") {
      options.steps = number(flag, value, [](const std::string& v, std::size_t* used) { return std::stoi(v, used); });
    } else if (flag == "--skin") {
      options.skin = number(flag, value, [](const std::string& v, std::size_t* used) { return std::stod(v, used); });
      if (!(*options.skin >= 0)) throw std::invalid_argument("--skin is a number of particle spacings >= 0");
    } else if (flag == "--json") {
      options.json = value;
    } else {
      throw std::invalid_argument("unknown option " + std::string(flag));
    }
  }
  if (options.dimension != 2 && options.dimension != 3) throw std::invalid_argument("--dimension is 2 or 3");
  if (options.steps < 0) throw std::invalid_argument("--steps is a count >= 0");
  return options;
}

// The owner of an item: what precedes its first '.' ("fluid", "walls grid", "fluid list", ...).
std::string owner(const std::string& name) { return name.substr(0, name.find('.')); }

struct Measurement {
  tide::MemoryUsage usage;
  std::size_t fluid = 0;
  std::size_t walls = 0;
  ResidentMemory baseline;       // before the simulation is built
  ResidentMemory built;          // after the build (peak: the build's)
  ResidentMemory after_steps;    // after the steps (peak: the steps', reset after the build)
  tide::bench::HeapMemory heap;  // after the steps
  bool peak_reset = false;
  double skin = 0;  // solver.neighbor_skin in particle spacings
};

template <int D>
Measurement measure(const Options& options) {
  Measurement m;
  m.baseline = resident_memory();
  scene::Scene dam_break = tide::bench::sized_dam_break(D, options.particles, options.scheme);
  if (options.skin) dam_break.solver.neighbor_skin = options.skin;
  m.skin = dam_break.solver.neighbor_skin.value_or(scene::default_neighbor_skin(options.scheme));
  const std::unique_ptr<tide::Simulation<D>> simulation = tide::make_simulation<D>(dam_break);
  m.built = resident_memory();
  m.peak_reset = tide::bench::reset_peak_resident_memory();
  for (int step = 0; step < options.steps; ++step) simulation->step();
  m.after_steps = resident_memory();
  m.heap = tide::bench::heap_memory();
  m.usage = simulation->memory_usage();
  m.fluid = simulation->fluid().size();
  m.walls = simulation->interactions().contact_particle_count();
  return m;
}

void print(const Options& options, const Measurement& m) {
  const double n = double(m.fluid);
  const auto per = [&](double bytes) { return bytes / n; };
  std::printf(
      "%dD %s, %s, %zu fluid and %zu wall particles (%.2f per fluid particle), neighbour skin %.2f spacings, after %d "
      "steps%s\n\n",
      options.dimension, std::string(tide::scheme_name(options.scheme)).c_str(), TIDE_REAL_NAME, m.fluid, m.walls,
      double(m.walls) / n, m.skin, options.steps, options.allocator_default ? ", C allocator left as it is" : "");
  std::printf("| item | B per fluid particle |\n|---|--:|\n");
  std::map<std::string, double> owners;
  std::string last_owner;
  for (const tide::MemoryItem& item : m.usage.items()) {
    if (item.bytes == 0) continue;
    std::printf("| %s | %.1f |\n", item.name.c_str(), per(double(item.bytes)));
    owners[owner(item.name)] += double(item.bytes);
  }
  std::printf("| **total** | **%.1f** |\n\n| owner | B per fluid particle |\n|---|--:|\n",
              per(double(m.usage.total())));
  for (const auto& [name, bytes] : owners) std::printf("| %s | %.1f |\n", name.c_str(), per(bytes));
  const auto above = [&](std::size_t bytes) { return per(double(bytes) - double(m.baseline.current)); };
  std::printf(
      "\nresident memory above the %.0f MB before the build, per fluid particle: after the build %.1f B (its peak "
      "%.1f B), after the steps %.1f B, peak of the steps %s%.1f B\n",
      double(m.baseline.current) / 1e6, above(m.built.current), above(m.built.peak), above(m.after_steps.current),
      m.peak_reset ? "" : "(not reset: the build's included) ", above(m.after_steps.peak));
  std::printf(
      "C heap after the steps, per fluid particle: in use %.1f B (of which mapped blocks %.1f B), freed but "
      "kept by the allocator %.1f B\n",
      per(double(m.heap.in_use)), per(double(m.heap.mapped)), per(double(m.heap.free_kept)));
}

void write_json(const Options& options, const Measurement& m) {
  std::ofstream out(options.json);
  const double n = double(m.fluid);
  const auto above = [&](std::size_t bytes) { return (double(bytes) - double(m.baseline.current)) / n; };
  out << "{\n  \"dimension\": " << options.dimension << ",\n  \"scheme\": \"" << tide::scheme_name(options.scheme)
      << "\",\n  \"allocator_default\": " << (options.allocator_default ? "true" : "false") << ",\n  \"real\": \""
      << TIDE_REAL_NAME << "\",\n  \"steps\": " << options.steps << ",\n  \"skin\": " << m.skin
      << ",\n  \"fluid\": " << m.fluid << ",\n  \"walls\": " << m.walls
      << ",\n  \"bytes_per_particle\": " << double(m.usage.total()) / n
      << ",\n  \"rss_after_build\": " << above(m.built.current) << ",\n  \"rss_peak_build\": " << above(m.built.peak)
      << ",\n  \"rss_after_steps\": " << above(m.after_steps.current)
      << ",\n  \"rss_peak_steps\": " << above(m.after_steps.peak)
      << ",\n  \"heap_in_use\": " << double(m.heap.in_use) / n
      << ",\n  \"heap_free_kept\": " << double(m.heap.free_kept) / n << ",\n  \"items\": [";
  bool first = true;
  for (const tide::MemoryItem& item : m.usage.items()) {
    out << (first ? "\n" : ",\n") << "    {\"name\": \"" << item.name
        << "\", \"bytes_per_particle\": " << double(item.bytes) / n << "}";
    first = false;
  }
  out << "\n  ]\n}\n";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse(argc, argv);
    if (!options.allocator_default) tide::release_large_blocks_to_the_system();
    const Measurement m = options.dimension == 2 ? measure<2>(options) : measure<3>(options);
    print(options, m);
    if (!options.json.empty()) write_json(options, m);
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "memory_report: %s\n", error.what());
    return 2;
  }
}
