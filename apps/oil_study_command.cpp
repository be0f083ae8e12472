#include "oil_study_command.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "run_command.hpp"
#include "tide/io/scene_reader.hpp"
#include "tide/validation/report.hpp"
#include "tide/validation/text_output.hpp"

namespace tide::app {
namespace {

namespace fs = std::filesystem;

/// One scene of the study: the parameters its name carries (scripts/oil_scenes.py names them
/// oil_middle_h<height>_<orientation>_<wetting>, oil_upper_w<width>_<wetting> and, at a low Bond
/// number, oil_wetting_h<height>_<orientation>_<wetting> for the wetting comparison and
/// oil_capillary_h<height>_<orientation>_<wetting> for the orientation comparison, in mm) and its
/// recovery curve.
struct OilRun {
  fs::path scene;
  std::string name;
  std::string family;       // "middle", "upper", or "wetting" and "capillary" (middle-fractured cavities)
  double size = 0;          // middle-fractured: the fracture's height above the floor; upper: the throat's width (mm)
  std::string orientation;  // middle-fractured: horizontal, rising or falling
  std::string wetting;      // water_wet or oil_wet
  double end_time = 0;
  std::vector<double> times;
  std::vector<double> recoveries;
  bool ok = false;

  double final_recovery() const { return recoveries.empty() ? 0 : recoveries.back(); }
  /// The recovery gained over the last `span` seconds of the run: how far from a plateau it ended.
  double recent_gain(double span) const {
    if (times.empty()) return 0;
    const auto first = std::lower_bound(times.begin(), times.end(), times.back() - span);
    return recoveries.back() - recoveries[static_cast<std::size_t>(first - times.begin())];
  }
  bool middle_fractured() const { return family == "middle" || family == "wetting" || family == "capillary"; }
  std::string label() const {
    if (middle_fractured()) return "h = " + format(size) + " mm, " + orientation + ", " + wetting;
    return "w = " + format(size) + " mm, " + wetting;
  }
  static std::string format(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
  }
};

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, separator);) parts.push_back(part);
  return parts;
}

/// The parameters in a scene's name; false for a name that does not follow the pattern.
bool parse_name(OilRun& run) {
  const std::vector<std::string> parts = split(run.name, '_');
  if (parts.size() < 4 || parts[0] != "oil") return false;
  run.family = parts[1];
  const std::string& size = parts[2];
  if (size.size() < 2) return false;
  run.size = std::stod(size.substr(1));
  if (run.middle_fractured() && parts.size() == 6 && size[0] == 'h') {
    run.orientation = parts[3];
    run.wetting = parts[4] + "_" + parts[5];
    return true;
  }
  if (run.family == "upper" && parts.size() == 5 && size[0] == 'w') {
    run.wetting = parts[3] + "_" + parts[4];
    return true;
  }
  return false;
}

/// Reads recovery.csv (docs/output.md): the rows after the comments and the column line.
void read_recovery(const fs::path& file, OilRun& run) {
  run.times.clear();
  run.recoveries.clear();
  std::ifstream in(file);
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    const std::vector<std::string> columns = split(line, ',');
    if (columns.size() != 3) continue;
    run.times.push_back(std::stod(columns[0]));
    run.recoveries.push_back(std::stod(columns[2]));
  }
}

bool reached_end(const OilRun& run) {
  return !run.times.empty() && run.times.back() >= run.end_time - 1e-9 * std::max(1.0, run.end_time);
}

std::vector<OilRun> find_scenes(const fs::path& directory) {
  std::vector<OilRun> runs;
  if (!fs::is_directory(directory)) return runs;
  for (const auto& entry : fs::directory_iterator(directory)) {
    const fs::path& path = entry.path();
    if (path.extension() != ".json" || !path.stem().string().starts_with("oil_")) continue;
    OilRun run;
    run.scene = path;
    run.name = path.stem().string();
    if (parse_name(run)) runs.push_back(run);
  }
  std::sort(runs.begin(), runs.end(), [](const OilRun& a, const OilRun& b) {
    return std::tie(a.family, a.wetting, a.size, a.orientation) < std::tie(b.family, b.wetting, b.size, b.orientation);
  });
  return runs;
}

/// A run's line: its colour by its fracture's size (the sizes of its family in order), black for
/// oil-wet walls; dashed by its orientation.
std::string line_style(const OilRun& run, const std::vector<OilRun>& runs) {
  std::vector<double> sizes;
  for (const OilRun& other : runs)
    if (other.family == run.family) sizes.push_back(other.size);
  std::sort(sizes.begin(), sizes.end());
  sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  const auto colour = std::find(sizes.begin(), sizes.end(), run.size) - sizes.begin() + 1;
  const int dashes = run.orientation == "rising" ? 2 : run.orientation == "falling" ? 4 : 1;
  return (run.wetting == "oil_wet" ? std::string("linecolor rgb 'black'") : "linecolor " + std::to_string(colour)) +
         " dashtype " + std::to_string(dashes);
}

/// Recovery against time, one line per run of `family`.
std::string curves_script(const fs::path& png, const std::vector<OilRun>& runs, const std::string& family,
                          const std::string& title, const fs::path& output_directory) {
  std::ostringstream script;
  script << "set terminal pngcairo size 900,600 noenhanced\nset output " << validation::gnuplot_string(png.string())
         << "\nset title " << validation::gnuplot_string(title)
         << "\nset xlabel 'time (s)'\nset ylabel 'oil recovery of the cavity'\nset yrange [-0.05:1]\nset grid\n"
         << "set key left top font ',9'\nset datafile separator ','\nplot ";
  bool first = true;
  for (const OilRun& run : runs) {
    if (run.family != family || !run.ok) continue;
    script << (first ? "" : ", ") << validation::gnuplot_string((output_directory / run.name / "recovery.csv").string())
           << " using 1:3 every ::1 with lines linewidth 2 " << line_style(run, runs) << " title "
           << validation::gnuplot_string(run.label());
    first = false;
  }
  return script.str() + "\n";
}

/// The final recovery of the upper-fractured runs against the throat's width.
std::string width_script(const fs::path& png, const std::vector<OilRun>& runs) {
  std::ostringstream script;
  script << "set terminal pngcairo size 800,550 noenhanced\nset output " << validation::gnuplot_string(png.string())
         << "\nset title 'upper-fractured cavity: recovery at the end of the run against the fracture width'"
         << "\nset xlabel 'width of the fracture above the cavity (mm)'\nset ylabel 'oil recovery'\nset yrange "
            "[-0.05:1]\nset grid\nplot '-' using 1:2 with linespoints pointtype 7 linewidth 2 notitle\n";
  for (const OilRun& run : runs)
    if (run.family == "upper" && run.ok) script << run.size << ' ' << run.final_recovery() << '\n';
  return script.str() + "e\n";
}

std::string summary_csv(const std::vector<OilRun>& runs) {
  std::ostringstream csv;
  csv << "scene,family,size_mm,orientation,wetting,end_time_s,final_recovery,gain_last_0.5s,ok\n";
  for (const OilRun& run : runs) {
    csv << run.name << ',' << run.family << ',' << run.size << ',' << run.orientation << ',' << run.wetting << ','
        << (run.times.empty() ? 0 : run.times.back()) << ',' << run.final_recovery() << ',' << run.recent_gain(0.5)
        << ',' << (run.ok ? "yes" : "no") << '\n';
  }
  return csv.str();
}

std::string summary_markdown(const std::vector<OilRun>& runs) {
  std::ostringstream table;
  table << "| scene | fracture | wetting | t end (s) | recovery | gain over the last 0.5 s |\n"
        << "| --- | --- | --- | --- | --- | --- |\n";
  char numbers[96];
  for (const OilRun& run : runs) {
    const std::string fracture = run.middle_fractured()
                                     ? "height " + OilRun::format(run.size) + " mm, " + run.orientation
                                     : "width " + OilRun::format(run.size) + " mm";
    std::snprintf(numbers, sizeof numbers, "%.3g | %.3f | %+.3f", run.times.empty() ? 0.0 : run.times.back(),
                  run.final_recovery(), run.recent_gain(0.5));
    table << "| " << run.name << " | " << fracture << " | " << run.wetting << " | " << (run.ok ? numbers : "failed")
          << " |\n";
  }
  return table.str();
}

}  // namespace

int oil_study(const OilStudyOptions& options) {
  std::vector<OilRun> runs = find_scenes(options.scenes_directory);
  if (runs.empty()) {
    std::cerr << "tide: oil-study: no oil_*.json scenes in " << options.scenes_directory.string() << '\n';
    return exit_bad_input;
  }
  const fs::path& out = options.output_directory;
  int failed = 0;
  for (OilRun& run : runs) {
    const scene::Scene scene = io::read_scene_file(run.scene);
    run.end_time = options.until.value_or(scene.time.end);
    const fs::path recovery = out / run.name / "recovery.csv";
    if (options.reuse && fs::exists(recovery)) read_recovery(recovery, run);
    if (!reached_end(run)) {
      std::printf("oil-study: running %s until t = %g s ...\n", run.name.c_str(), run.end_time);
      std::fflush(stdout);
      RunOptions run_options;
      run_options.scene_file = run.scene;
      run_options.output_directory = out / run.name;
      run_options.until = options.until;
      run_options.quiet = true;
      const int code = run_scene(run_options);
      if (code != exit_ok) std::cerr << "tide: oil-study: " << run.name << " stopped with exit code " << code << '\n';
      read_recovery(recovery, run);
    }
    run.ok = reached_end(run);
    if (!run.ok) ++failed;
    std::printf("oil-study: %s: recovery %.3f at t = %g s\n", run.name.c_str(), run.final_recovery(),
                run.times.empty() ? 0.0 : run.times.back());
    std::fflush(stdout);
  }
  validation::write_text_file(out / "oil_study.csv", summary_csv(runs));
  const std::string table = summary_markdown(runs);
  validation::write_text_file(out / "oil_study.md", table);
  std::cout << '\n' << table;
  // A family's plots only when one of its runs reached its end: gnuplot refuses an empty plot.
  const auto plotted = [&runs](const std::string& family) {
    return std::any_of(runs.begin(), runs.end(), [&](const OilRun& run) { return run.family == family && run.ok; });
  };
  if (validation::gnuplot_available()) {
    if (plotted("middle"))
      validation::draw_png(out / "middle_fractured.png", [&](const fs::path& png) {
        return curves_script(png, runs, "middle", "middle-fractured cavity: oil recovery", out);
      });
    if (plotted("upper")) {
      validation::draw_png(out / "upper_fractured.png", [&](const fs::path& png) {
        return curves_script(png, runs, "upper", "upper-fractured cavity: oil recovery", out);
      });
      validation::draw_png(out / "upper_fractured_width.png",
                           [&](const fs::path& png) { return width_script(png, runs); });
    }
    if (plotted("wetting"))
      validation::draw_png(out / "wetting.png", [&](const fs::path& png) {
        return curves_script(png, runs, "wetting",
                             "middle-fractured cavity at a low Bond number, water-wet and oil-wet: oil recovery", out);
      });
    if (plotted("capillary"))
      validation::draw_png(out / "capillary.png", [&](const fs::path& png) {
        return curves_script(png, runs, "capillary",
                             "middle-fractured cavity at cavity Bond number 7.8, each height and orientation: oil "
                             "recovery",
                             out);
      });
    std::cout << "tide: oil-study: plots in " << out.string() << '\n';
  } else {
    std::cerr << "tide: oil-study: gnuplot is not on the PATH: no plots (Debian: apt-get install gnuplot-nox)\n";
  }
  if (failed == 0) return exit_ok;
  std::cerr << "tide: oil-study: " << failed << " of " << runs.size() << " runs did not reach their end time\n";
  return exit_unstable;
}

}  // namespace tide::app
