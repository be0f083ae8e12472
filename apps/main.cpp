// The `tide` command: run, check and describe TideSPH scenes, turn runs into surfaces, and run the
// validation study, the stress suite and the oil-displacement study.

#include <CLI/CLI.hpp>

#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "oil_study_command.hpp"
#include "render_command.hpp"
#include "run_command.hpp"
#include "scene_keys_command.hpp"
#include "serve_command.hpp"
#include "stress_command.hpp"
#include "surface_command.hpp"
#include "tide/core/config.hpp"
#include "tide/core/large_block_release.hpp"
#include "tide/core/parallel.hpp"
#include "validate_command.hpp"

namespace {

// A shipped file or folder: next to an installed binary (../share/tide/<installed>), else
// `in_source` in the source tree the binary was built from.
std::filesystem::path shipped(const std::string& installed, const std::filesystem::path& in_source) {
  std::error_code error;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const auto path = executable.parent_path().parent_path() / "share/tide" / installed;
    if (std::filesystem::exists(path)) return path;
  }
  return in_source;
}

// The shipped default scene of tide run.
std::filesystem::path default_scene() {
  return shipped("scenes/dam_break_2d.json", std::filesystem::path(TIDE_SOURCE_SCENES_DIR) / "dam_break_2d.json");
}

// The run directory, --frames, --out and --spacing of a command that turns frames into pictures.
void add_frame_selection(CLI::App& command, tide::app::FrameSelection& selection, const std::string& folder) {
  command.add_option("run", selection.run_directory, "run directory (where tide run wrote the frames)")->required();
  command.add_option("--frames", selection.frames, "frames A:B (both included), A:, :B or A (default: all)");
  command.add_option("--out", selection.output_directory, "output directory (default: RUN/" + folder + ")");
  command
      .add_option("--spacing", selection.particle_spacing,
                  "particle spacing in m (default: the median nearest-neighbour distance in the first frame)")
      ->check(CLI::PositiveNumber);
}

int info() {
  std::cout << "TideSPH " << TIDE_VERSION << '\n'
            << "  precision   " << TIDE_REAL_NAME << '\n'
            << "  threads     " << tide::thread_count() << " (oneTBB; --threads N caps it)\n"
            << "  build type  " << TIDE_BUILD_TYPE << '\n'
            << "  compiler    " << TIDE_CXX_COMPILER << '\n'
            << "  flags       " << TIDE_CXX_FLAGS << '\n'
            << "  scenes      " << default_scene().parent_path().string() << '\n';
  return tide::app::exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
  tide::release_large_blocks_to_the_system();
  CLI::App app{"TideSPH: smoothed-particle hydrodynamics. Runs scene files (docs/scenes.md)."};
  app.require_subcommand(1);
  int threads = 0;
  app.add_option("--threads", threads, "number of worker threads (default: all cores)")->check(CLI::PositiveNumber);

  tide::app::RunOptions run_options;
  std::string until;
  CLI::App* run = app.add_subcommand("run", "run a scene (default: the shipped 2D dam break)");
  run->add_option("scene", run_options.scene_file, "scene file (JSON)");
  run->add_option("--out", run_options.output_directory, "output directory (default: runs/<scene name>)");
  run->add_option("--until", run_options.until, "end time in s, overriding the scene's");
  run->add_flag("--quiet", run_options.quiet, "no progress output");
  run->add_flag("--vtk", run_options.vtk, "also write each frame as a VTK file (.vtu, .pvd), as output.vtk does");
  run->add_option("--checkpoint-every", run_options.checkpoint_every,
                  "write <out>/checkpoint.h5 every T s of simulated time (and after the last step)")
      ->check(CLI::PositiveNumber);
  run->add_option("--checkpoint-wall", run_options.checkpoint_wall,
                  "write <out>/checkpoint.h5 every S s of wall-clock time (and after the last step)")
      ->check(CLI::PositiveNumber);
  run->add_option("--resume", run_options.resume,
                  "continue the run in DIR from its checkpoint.h5 (the scene: the one given, else the checkpoint's)");
  bool render_after_run = false;
  run->add_flag("--render", render_after_run, "render the frames as PNG (and MP4 with ffmpeg) at the end: tide render");
  run->add_option("--threads", threads, "number of worker threads (default: all cores)")->check(CLI::PositiveNumber);

  std::filesystem::path check_file;
  CLI::App* check = app.add_subcommand("check", "validate a scene file without running it");
  check->add_option("scene", check_file, "scene file (JSON)")->required();

  tide::app::ValidateOptions validate_options;
  CLI::App* validate = app.add_subcommand(
      "validate", "run the validation study: cases x schemes x kernels x resolutions; CSVs, plots, docs page");
  validate->add_option("case", validate_options.cases, "cases to run (default: all; --list names them)");
  validate->add_option("--resolutions", validate_options.resolutions, "e.g. 20,40,80 (default: each case's ladder)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::PositiveNumber);
  validate
      ->add_option("--schemes", validate_options.schemes,
                   "comma-separated (default: not *_cg or wcsph_riemann*; --list names them)")
      ->delimiter(',')
      ->allow_extra_args(false);
  validate->add_option("--kernels", validate_options.kernels, "comma-separated (default: wendland_c2,cubic_spline)")
      ->delimiter(',')
      ->allow_extra_args(false);
  validate->add_option("--out", validate_options.output_directory,
                       "directory for results.csv, orders.csv and the plots (default: validation-results)");
  validate->add_option("--docs", validate_options.docs_page,
                       "also write this markdown page, its plots beside it in <page name>/ (docs/validation.md)");
  validate
      ->add_option("--reuse", validate_options.reuse,
                   "take the runs of earlier results.csv files (same case, scheme, kernel and "
                   "resolution) instead of running them again; their wall times are from those studies")
      ->delimiter(',')
      ->allow_extra_args(false);
  validate->add_flag("--list", validate_options.list,
                     "list the cases, their default resolutions, the schemes and the kernels");
  validate->add_option("--threads", threads, "number of worker threads (default: all cores)")
      ->check(CLI::PositiveNumber);

  tide::app::StressOptions stress_options;
  CLI::App* stress = app.add_subcommand(
      "stress", "run the stress suite (docs/stability.md): tension, impacts, extremes, time step; prints the table");
  stress->add_option("case", stress_options.cases, "cases to run (default: all; --list names them)");
  stress->add_flag("--short", stress_options.short_runs, "the short forms of the cases, as the tests run them");
  stress->add_option("--out", stress_options.output_directory,
                     "directory for stress.md and stress.csv (default: stress-results)");
  stress->add_flag("--list", stress_options.list, "list the cases");
  stress->add_option("--threads", threads, "number of worker threads (default: all cores)")->check(CLI::PositiveNumber);

  tide::app::OilStudyOptions oil_options;
  oil_options.scenes_directory = default_scene().parent_path();
  CLI::App* oil = app.add_subcommand(
      "oil-study", "run the oil-displacement scenes (Zhou et al. 2010; docs/multiphase.md) and plot their recovery");
  oil->add_option("--out", oil_options.output_directory,
                  "directory for each run, oil_study.csv/.md and the plots (default: oil-study)");
  oil->add_option("--scenes", oil_options.scenes_directory, "directory of the oil_*.json scenes (default: shipped)");
  oil->add_option("--until", oil_options.until, "end time in s, overriding each scene's");
  oil->add_flag("--reuse", oil_options.reuse, "keep the runs in --out that reached their end time");
  oil->add_option("--threads", threads, "number of worker threads (default: all cores)")->check(CLI::PositiveNumber);

  tide::app::SurfaceOptions surface_options;
  CLI::App* surface = app.add_subcommand(
      "surface", "turn a run's frames into fluid surfaces: PLY and OBJ meshes in 3D, SVG and CSV outlines in 2D");
  add_frame_selection(*surface, surface_options.input, "surface");
  surface->add_option("--smoothing-ratio", surface_options.field.smoothing_ratio, "kernel h / spacing (default: 1.2)")
      ->check(CLI::PositiveNumber);
  surface->add_option("--cell-ratio", surface_options.field.cell_ratio, "grid cell / spacing (default: 0.5)")
      ->check(CLI::PositiveNumber);
  surface
      ->add_option("--smooth", surface_options.smoothing_iterations,
                   "Taubin smoothing iterations, which keep the volume (3D; default: 0, none)")
      ->check(CLI::NonNegativeNumber);
  bool render_surfaces = false;
  surface->add_flag("--render", render_surfaces,
                    "3D: then draw the same frames' surfaces as PNG (and MP4 with ffmpeg): tide render --surface");
  surface->add_option("--threads", threads, "number of worker threads (default: all cores)")
      ->check(CLI::PositiveNumber);

  tide::app::RenderOptions render_options;
  CLI::App* render = app.add_subcommand(
      "render", "draw a run's frames as PNG pictures (particles coloured by a field) and, with ffmpeg, an MP4");
  add_frame_selection(*render, render_options.input, "render");
  render->add_option("--field", render_options.field,
                     "field to colour by; a vector by its magnitude (default: velocity)");
  render->add_option("--colormap", render_options.colormap, "viridis, inferno or gray (default: viridis)");
  render->add_option("--size", render_options.size, "picture size WxH in pixels (default: 1280x720)");
  CLI::Option* surface_flag =
      render->add_flag("--surface", render_options.surface,
                       "3D: draw the fluid surface (as tide surface reconstructs it) instead of the particles");
  render
      ->add_flag("--heatmap", render_options.heatmap,
                 "2D: colour the floor by the points' kernel-summed density (a crowd's agents/m^2)")
      ->excludes(surface_flag);
  render
      ->add_option("--smoothing-length", render_options.smoothing_length,
                   "h in m of the heat map's Wendland C2 kernel (default: 0.5, the shipped crowd scenes')")
      ->check(CLI::PositiveNumber);
  render
      ->add_option("--heatmap-max", render_options.heatmap_max,
                   "top of the heat map's colour scale (default: 6 agents/m^2)")
      ->check(CLI::PositiveNumber);
  render->add_option("--threads", threads, "number of worker threads (default: all cores)")->check(CLI::PositiveNumber);

  tide::app::ServeOptions serve_options;
  CLI::App* serve = app.add_subcommand(
      "serve",
      "run a 2D scene live in a web page: drag the obstacle, change gravity, viscosity, particles (docs/serve.md)");
  serve->add_option("scene", serve_options.scene_file, "2D scene file (default: the shipped tank, serve_tank_2d.json)");
  serve->add_option("--port", serve_options.port, "TCP port; 0 takes a free one (default: 8080)")
      ->check(CLI::Range(0, 65535));
  serve->add_option("--host", serve_options.host, "address to listen on (default: 127.0.0.1, this machine only)");
  serve
      ->add_option("--pace", serve_options.pace,
                   "simulated seconds per wall second at most; 0 runs as fast as it can (default: 1)")
      ->check(CLI::Range(0.0, 100.0));
  serve->add_option("--threads", threads, "number of worker threads (default: all cores)")->check(CLI::PositiveNumber);

  std::filesystem::path keys_docs = "docs/scenes.md", keys_dictionary = "fuzz/scene.dict";
  CLI::App* scene_keys = app.add_subcommand(
      "scene-keys", "rewrite the key tables of docs/scenes.md and fuzz/scene.dict from the scene reader's tables");
  scene_keys->group("");  // for maintainers: not listed in --help
  scene_keys->add_option("--docs", keys_docs, "the scenes page (default: docs/scenes.md)");
  scene_keys->add_option("--dict", keys_dictionary, "the fuzz dictionary (default: fuzz/scene.dict)");

  CLI::App* info_command = app.add_subcommand("info", "version, precision, threads and build flags");
  info_command->add_option("--threads", threads, "number of worker threads")->check(CLI::PositiveNumber);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? tide::app::exit_ok : tide::app::exit_bad_input;
  }

  try {
    std::optional<tide::ThreadLimit> limit;
    if (threads > 0) limit.emplace(threads);
    if (*run) {
      if (run_options.scene_file.empty() && run_options.resume.empty()) run_options.scene_file = default_scene();
      const int status = tide::app::run_scene(run_options);
      if (status != tide::app::exit_ok || !render_after_run) return status;
      render_options.input.run_directory = tide::app::run_output_directory(run_options);
      return tide::app::render_frames(render_options);
    }
    if (*check) return tide::app::check_scene(check_file);
    if (*serve) {
      if (serve_options.scene_file.empty())
        serve_options.scene_file =
            shipped("scenes/serve_tank_2d.json", std::filesystem::path(TIDE_SOURCE_SCENES_DIR) / "serve_tank_2d.json");
      serve_options.web_root = shipped("web", TIDE_SOURCE_WEB_DIR);
      return tide::app::serve_scene(serve_options);
    }
    if (*validate) {
      validate_options.command_line = tide::app::quoted_command_line(argc, argv);
      return tide::app::validate(validate_options);
    }
    if (*stress) return tide::app::stress(stress_options);
    if (*oil) return tide::app::oil_study(oil_options);
    if (*render) return tide::app::render_frames(render_options);
    if (*surface) {
      const int status = tide::app::reconstruct_surfaces(surface_options);
      if (status != tide::app::exit_ok || !render_surfaces) return status;
      // The same frames drawn as the shaded surface into RUN/render (and its MP4).
      tide::app::RenderOptions surface_pictures;
      surface_pictures.input = surface_options.input;
      surface_pictures.input.output_directory.clear();
      surface_pictures.surface = true;
      return tide::app::render_frames(surface_pictures);
    }
    if (*scene_keys) return tide::app::write_scene_keys(keys_docs, keys_dictionary);
    return info();
  } catch (const std::exception& error) {
    std::cerr << "tide: error: " << error.what() << '\n';
    return tide::app::exit_failure;
  }
}
