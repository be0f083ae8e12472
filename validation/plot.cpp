// The study's figures, drawn by the gnuplot program from a generated script.

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "report_support.hpp"
#include "tide/validation/report.hpp"

extern char** environ;

namespace tide::validation {
namespace {

namespace fs = std::filesystem;

// The runs of one scheme/kernel, sorted by resolution: one line in a figure.
struct Series {
  std::string label;
  std::vector<RunRecord> records;
};

std::vector<Series> plot_series(std::span<const StudyRun> runs) {
  std::vector<Series> series;
  for (const StudyRun& run : runs) {
    if (!detail::plottable(run)) continue;
    const std::string label = run.record.scheme + " / " + run.record.kernel;
    auto line = std::find_if(series.begin(), series.end(), [&](const Series& s) { return s.label == label; });
    if (line == series.end()) line = series.insert(series.end(), Series{label, {}});
    line->records.push_back(run.record);
  }
  for (Series& line : series) {
    std::stable_sort(line.records.begin(), line.records.end(),
                     [](const RunRecord& a, const RunRecord& b) { return a.resolution < b.resolution; });
  }
  return series;
}

// Metrics are dimensionless unless their name ends in a unit (case.hpp's Metric).
std::string metric_axis_label(std::string_view metric) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 5> units{
      {{"_m_per_s", "m/s"}, {"_percent", "%"}, {"_pa", "Pa"}, {"_m", "m"}, {"_s", "s"}}};
  for (const auto& [suffix, unit] : units) {
    if (metric.ends_with(suffix)) return std::string(metric) + " (" + std::string(unit) + ")";
  }
  return std::string(metric) + " (dimensionless)";
}

// An x range a little wider than the resolutions, with a tic at each of them.
std::string resolution_axis(const std::vector<Series>& series) {
  std::vector<int> resolutions;
  for (const Series& line : series) {
    for (const RunRecord& record : line.records) resolutions.push_back(record.resolution);
  }
  std::sort(resolutions.begin(), resolutions.end());
  resolutions.erase(std::unique(resolutions.begin(), resolutions.end()), resolutions.end());
  std::ostringstream axis;
  axis << "set xrange [" << resolutions.front() / 1.3 << ':' << resolutions.back() * 1.3 << "]\nset xtics (";
  for (std::size_t k = 0; k < resolutions.size(); ++k) axis << (k > 0 ? ", " : "") << resolutions[k];
  axis << ")\n";
  return axis.str();
}

enum class Abscissa { wall_seconds, resolution };

std::string plot_script(const fs::path& output, const Case& study_case, const std::vector<Series>& series,
                        Abscissa abscissa) {
  const std::string& metric = series.front().records.front().metrics.front().name;
  std::ostringstream script;
  script.precision(17);
  script << png_terminal(output.string())
         << "set logscale xy\nset grid\nset key top right\nset format x '%g'\nset format y '%g'\n"
         << "set ylabel " << gnuplot_string(metric_axis_label(metric)) << '\n';
  if (abscissa == Abscissa::wall_seconds) {
    script << "set title " << gnuplot_string(study_case.title) << '\n'
           << "set xlabel 'wall time of the time stepping (s); points labelled by resolution'\n";
  } else {
    script << "set title " << gnuplot_string(study_case.title + ": error against resolution") << '\n'
           << "set xlabel " << gnuplot_string("resolution (" + study_case.resolution_meaning + ")") << '\n'
           << resolution_axis(series);
  }
  for (std::size_t k = 0; k < series.size(); ++k) {
    script << "$series" << k << " << EOD\n";
    for (const RunRecord& record : series[k].records) {
      const double x =
          abscissa == Abscissa::wall_seconds ? record.wall_seconds : static_cast<double>(record.resolution);
      script << x << ' ' << record.metrics.front().value << ' ' << record.resolution << '\n';
    }
    script << "EOD\n";
  }
  script << "plot ";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const std::size_t style = k + 1;
    script << (k > 0 ? ", \\\n     " : "") << "$series" << k << " using 1:2 with linespoints linetype " << style
           << " pointtype 7 title " << gnuplot_string(series[k].label);
    if (abscissa == Abscissa::wall_seconds) {
      script << ", $series" << k << " using 1:2:3 with labels offset character 0.8,0.8 textcolor linetype " << style
             << " notitle";
    }
  }
  script << '\n';
  return script.str();
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs `gnuplot <script>` and throws with gnuplot's own error output if it fails.
void run_gnuplot(const fs::path& script) {
  const fs::path log = fs::path(script).concat(".log");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::string program = "gnuplot";
  std::string argument = script.string();
  char* arguments[] = {program.data(), argument.data(), nullptr};
  pid_t child = 0;
  const int spawned = posix_spawnp(&child, program.c_str(), &actions, nullptr, arguments, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    fs::remove(log);
    if (spawned == ENOENT) {
      throw std::runtime_error("gnuplot is not on the PATH; install it (Debian: apt-get install gnuplot-nox)");
    }
    throw std::runtime_error(std::string("cannot start gnuplot: ") + std::strerror(spawned));
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string messages = read_file(log);
  fs::remove(log);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error("gnuplot failed on " + script.string() + " (kept for inspection):\n" + messages);
  }
}

fs::path draw(const fs::path& png, const Case& study_case, const std::vector<Series>& series, Abscissa abscissa) {
  draw_png(png, [&](const fs::path& output) { return plot_script(output, study_case, series, abscissa); });
  return png;
}

}  // namespace

std::string png_terminal(const std::string& output) {
  return "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
         "  set terminal pngcairo size 960,640 noenhanced\n"
         "} else {\n"
         "  set terminal png size 960,640 noenhanced\n"
         "}\n"
         "set output " +
         gnuplot_string(output) + '\n';
}

std::string gnuplot_string(std::string_view text) {
  std::string result = "'";
  for (const char c : text) {
    if (c == '\'') result += '\'';
    result += c;
  }
  return result + "'";
}

void draw_png(const fs::path& png, const std::function<std::string(const fs::path&)>& script_for) {
  fs::path partial = png;
  partial += ".tmp";
  fs::path script = png;
  script.replace_extension(".gp");
  detail::write_text_file(script, script_for(partial));
  try {
    run_gnuplot(script);
  } catch (const std::runtime_error&) {
    fs::remove(partial);
    throw;
  }
  fs::remove(script);
  if (!fs::exists(partial) || fs::file_size(partial) == 0) {
    fs::remove(partial);
    throw std::runtime_error("gnuplot wrote no image for " + png.string());
  }
  fs::rename(partial, png);
}

bool gnuplot_available() {
  const char* path = std::getenv("PATH");
  std::istringstream directories(path != nullptr ? path : "");
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const fs::path candidate = fs::path(directory.empty() ? "." : directory) / "gnuplot";
    if (access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::vector<fs::path> write_plots(const fs::path& directory, const Case& study_case, std::span<const StudyRun> runs) {
  const std::vector<Series> series = plot_series(detail::runs_of_case(runs, study_case.name));
  if (series.empty()) return {};
  fs::create_directories(directory);
  std::vector<fs::path> written{
      draw(directory / (study_case.name + ".png"), study_case, series, Abscissa::wall_seconds),
      draw(directory / (study_case.name + "_resolution.png"), study_case, series, Abscissa::resolution)};
  std::vector<RunRecord> records;
  for (const StudyRun& run : detail::runs_of_case(runs, study_case.name)) {
    if (run.ok()) records.push_back(run.record);
  }
  for (const Figure& figure : study_case.figures) {
    const fs::path png = directory / figure.file;
    draw_png(png, [&](const fs::path& output) { return figure.script(output.string(), records); });
    written.push_back(png);
  }
  return written;
}

}  // namespace tide::validation
