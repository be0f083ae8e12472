#pragma once

// The validation study's report: the results and convergence-order CSVs, the gnuplot figures
// and the markdown page (docs/validation.md) that `tide validate` writes.

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tide/validation/case.hpp"

namespace tide::validation {

/// One run of the study: what it produced, or why it failed.
struct StudyRun {
  RunRecord record;     // on failure only case_name, scheme, kernel and resolution are set
  std::string failure;  // empty when the run succeeded, else the reason (e.g. an InstabilityError's text)
  bool ok() const { return failure.empty(); }
  std::string status() const { return ok() ? "ok" : "failed: " + failure; }
};

/// An observed order of convergence p of one metric e of one (case, scheme, kernel), e ∝ r^-p.
struct ConvergenceOrder {
  std::string case_name;
  std::string scheme;
  std::string kernel;
  std::string metric;
  int from = 0;  // the coarser resolution
  int to = 0;    // the finer resolution
  double order = 0;
  bool least_squares = false;  // fitted over every resolution from..to, not between two neighbours
};

/// Writes results.csv: a header, then one row per run with the columns case, scheme, kernel,
/// resolution, particles, steps, wall_seconds, particle_steps_per_second, status, then one
/// column per metric name (the union over all runs, first seen first). A failed run's
/// measurements and metrics are empty cells. The file is replaced atomically.
void write_csv(const std::filesystem::path& path, std::span<const StudyRun> runs);

/// Reads back a results.csv that write_csv wrote: one StudyRun per row, metrics from the
/// non-empty metric cells. Throws std::runtime_error naming the file, the line and what was
/// expected when the file cannot be read or is not in that layout.
std::vector<StudyRun> read_csv(const std::filesystem::path& path);

/// For each (case, scheme, kernel) group of successful runs sorted by resolution r, and each of
/// its metrics e: p = ln(e_coarse / e_fine) / ln(r_fine / r_coarse) between consecutive
/// resolutions, then (for three or more) the least-squares slope of ln e against ln r over the
/// whole ladder. Groups and metrics keep the order in which the runs first show them; zero or
/// non-finite errors are left out, negative ones count by magnitude.
std::vector<ConvergenceOrder> convergence_orders(std::span<const StudyRun> runs);

/// Writes orders.csv: case, scheme, kernel, metric, from, to, order, fit ("consecutive" or
/// "least_squares"), one row per order. The file is replaced atomically.
void write_orders_csv(const std::filesystem::path& path, std::span<const ConvergenceOrder> orders);

/// Whether a `gnuplot` executable is on the PATH.
bool gnuplot_available();

/// Draws `png` by running gnuplot on the script that `script` returns for an output file (a
/// temporary beside `png`, renamed to it once complete). The script is kept beside `png` (.gp)
/// only when gnuplot fails. Throws std::runtime_error when gnuplot is missing, fails or writes
/// no image.
void draw_png(const std::filesystem::path& png, const std::function<std::string(const std::filesystem::path&)>& script);

/// The lines of a gnuplot script that send its plot to the PNG `output`, 960×640 (cairo where
/// gnuplot has it).
std::string png_terminal(const std::string& output);

/// A gnuplot single-quoted string: only the quote itself is special, written twice.
std::string gnuplot_string(std::string_view text);

/// The figures of one case, drawn by gnuplot into `directory`: `<case>.png`, the primary error
/// (metrics[0]) against wall seconds on log–log axes, one line per scheme/kernel with each point
/// labelled by its resolution, and `<case>_resolution.png`, the same error against resolution.
/// Then the case's own figures (Case::figures). Returns the files written: none when no
/// successful run of the case has a positive error.
/// Throws std::runtime_error when gnuplot is missing or fails.
std::vector<std::filesystem::path> write_plots(const std::filesystem::path& directory, const Case& study_case,
                                               std::span<const StudyRun> runs);

/// Where and how the study was run, for the page's introduction.
struct StudyContext {
  std::string command;    // the command line that reproduces the study
  std::string machine;    // CPU model and logical core count
  int threads = 0;        // worker threads the runs used
  std::string precision;  // the Real type of the particle data
  std::string build;      // build type and compiler, where known
  std::string date;       // UTC date of the study, YYYY-MM-DD
  std::string reused;     // which runs were taken from an earlier study (tide validate --reuse); empty: none
};

/// The context of a study run now by `command` in this process: machine from /proc/cpuinfo,
/// threads from tide::thread_count(), precision from tide::Real, today's date. `build` is left empty.
StudyContext current_context(std::string command);

/// Where the hand-written notes of the page `page` are kept: `<page's folder>/<page stem>-notes/`
/// (docs/validation.md: docs/validation-notes/).
std::filesystem::path notes_directory(const std::filesystem::path& page);

/// Writes the markdown page: an introduction (`context`), then per case in `cases` its title,
/// reference, metric definitions, resolution meaning, a table of its runs, its convergence
/// orders and its figures, linked as `<image_directory>/<case>.png` relative to the page, and
/// last the case's hand-written notes, `notes_directory(path)/<case>.md`, where that file exists.
/// The file is replaced atomically.
void write_markdown(const std::filesystem::path& path, const StudyContext& context, std::span<const Case> cases,
                    std::span<const StudyRun> runs, const std::string& image_directory);

}  // namespace tide::validation
