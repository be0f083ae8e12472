#include "validate_command.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <span>
#include <string_view>

#include "run_command.hpp"
#include "tide/core/kernels/kernel.hpp"
#include "tide/validation/case.hpp"
#include "tide/validation/report.hpp"

namespace tide::app {
namespace {

namespace fs = std::filesystem;
using validation::Case;
using validation::StudyRun;

// The kernels compared when --kernels is not given: the default one and the classic one.
constexpr std::array default_kernels{KernelType::wendland_c2, KernelType::cubic_spline};

struct Plan {
  std::vector<Case> cases;
  std::vector<std::string> schemes;
  std::vector<KernelType> kernels;
};

template <typename Names>
std::string joined(const Names& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

std::vector<std::string_view> all_kernel_names() {
  std::vector<std::string_view> names;
  for (const KernelType type : all_kernel_types) names.push_back(kernel_name(type));
  return names;
}

std::vector<std::string_view> default_kernel_names() {
  std::vector<std::string_view> names;
  for (const KernelType type : default_kernels) names.push_back(kernel_name(type));
  return names;
}

std::string case_names() {
  std::vector<std::string> names;
  for (const Case& study_case : validation::cases()) names.push_back(study_case.name);
  return joined(names);
}

// The cases, schemes and kernels the options name, or nothing after a message naming the valid ones.
std::optional<Plan> make_plan(const ValidateOptions& options) {
  Plan plan;
  if (options.cases.empty()) plan.cases = validation::cases();
  for (const std::string& name : options.cases) {
    const Case* study_case = validation::find_case(name);
    if (study_case == nullptr) {
      std::cerr << "tide: validate: unknown case '" << name << "'; the cases are: " << case_names() << '\n';
      return std::nullopt;
    }
    plan.cases.push_back(*study_case);
  }
  const std::vector<std::string>& schemes = validation::scheme_names();
  plan.schemes = options.schemes.empty() ? validation::default_scheme_names() : options.schemes;
  for (const std::string& name : plan.schemes) {
    if (std::find(schemes.begin(), schemes.end(), name) == schemes.end()) {
      std::cerr << "tide: validate: unknown scheme '" << name << "'; the schemes are: " << joined(schemes) << '\n';
      return std::nullopt;
    }
  }
  if (options.kernels.empty()) plan.kernels.assign(default_kernels.begin(), default_kernels.end());
  for (const std::string& name : options.kernels) {
    const std::optional<KernelType> kernel = kernel_from_name(name);
    if (!kernel) {
      std::cerr << "tide: validate: unknown kernel '" << name << "'; the kernels are: " << joined(all_kernel_names())
                << '\n';
      return std::nullopt;
    }
    plan.kernels.push_back(*kernel);
  }
  return plan;
}

// Runs one case at one resolution; an exception (an instability, a bad set-up) becomes a failed run.
StudyRun run_one(const Case& study_case, int resolution, const validation::Variant& variant) {
  try {
    return {study_case.run(resolution, variant), ""};
  } catch (const std::exception& error) {
    StudyRun failed;
    failed.record.case_name = study_case.name;
    failed.record.scheme = variant.scheme;
    failed.record.kernel = std::string(kernel_name(variant.kernel));
    failed.record.resolution = resolution;
    failed.failure = error.what();
    return failed;
  }
}

void print_outcome(const StudyRun& run) {
  if (!run.ok()) {
    std::printf("%s\n", run.status().c_str());
    return;
  }
  const validation::RunRecord& record = run.record;
  std::printf("%zu particles, %llu steps, %.2f s", record.particles, static_cast<unsigned long long>(record.steps),
              record.wall_seconds);
  if (!record.metrics.empty()) std::printf(", %s %.3g", record.metrics[0].name.c_str(), record.metrics[0].value);
  std::printf("\n");
}

// The run of `reused` (successful or failed) with the same case, scheme, kernel and resolution, if any.
const StudyRun* find_reused(std::span<const StudyRun> reused, const std::string& case_name, const std::string& scheme,
                            KernelType kernel, int resolution) {
  const auto same = [&](const StudyRun& run) {
    const validation::RunRecord& r = run.record;
    return r.case_name == case_name && r.scheme == scheme && r.kernel == kernel_name(kernel) &&
           r.resolution == resolution;
  };
  const auto found = std::find_if(reused.begin(), reused.end(), same);
  return found == reused.end() ? nullptr : &*found;
}

// Runs the plan, taking from `reused` the runs it already has; `reused_runs` counts those.
std::vector<StudyRun> run_study(const Plan& plan, const std::vector<int>& resolutions, std::span<const StudyRun> reused,
                                std::size_t& reused_runs) {
  std::size_t total = 0;
  for (const Case& study_case : plan.cases) {
    const auto schemes = std::count_if(plan.schemes.begin(), plan.schemes.end(),
                                       [&](const std::string& scheme) { return study_case.runs_scheme(scheme); });
    const auto kernels = std::count_if(plan.kernels.begin(), plan.kernels.end(),
                                       [&](KernelType kernel) { return study_case.runs_kernel(kernel); });
    total += (resolutions.empty() ? study_case.resolutions.size() : resolutions.size()) *
             static_cast<std::size_t>(schemes) * static_cast<std::size_t>(kernels);
  }
  std::vector<StudyRun> runs;
  for (const Case& study_case : plan.cases) {
    for (const std::string& scheme : plan.schemes) {
      if (!study_case.runs_scheme(scheme)) continue;
      for (const KernelType kernel : plan.kernels) {
        if (!study_case.runs_kernel(kernel)) continue;
        for (const int resolution : resolutions.empty() ? study_case.resolutions : resolutions) {
          std::printf("[%zu/%zu] %s %s/%s resolution %d: ", runs.size() + 1, total, study_case.name.c_str(),
                      scheme.c_str(), std::string(kernel_name(kernel)).c_str(), resolution);
          std::fflush(stdout);
          if (const StudyRun* earlier = find_reused(reused, study_case.name, scheme, kernel, resolution)) {
            runs.push_back(*earlier);
            ++reused_runs;
            std::printf("reused, ");
            print_outcome(runs.back());
            continue;
          }
          runs.push_back(run_one(study_case, resolution, {scheme, kernel}));
          print_outcome(runs.back());
          std::fflush(stdout);
        }
      }
    }
  }
  return runs;
}

// Copies through a temporary file so the page never links a half-copied image.
void copy_image(const fs::path& from, const fs::path& directory) {
  fs::create_directories(directory);
  const fs::path to = directory / from.filename();
  fs::path partial = to;
  partial += ".tmp";
  fs::copy_file(from, partial, fs::copy_options::overwrite_existing);
  fs::rename(partial, to);
}

void write_report(const ValidateOptions& options, const Plan& plan, const std::vector<StudyRun>& runs,
                  std::size_t reused_runs) {
  const fs::path& out = options.output_directory;
  validation::write_csv(out / "results.csv", runs);
  validation::write_orders_csv(out / "orders.csv", validation::convergence_orders(runs));
  const fs::path images = options.docs_page.parent_path() / options.docs_page.stem();
  for (const Case& study_case : plan.cases) {
    for (const fs::path& image : validation::write_plots(out, study_case, runs)) {
      if (!options.docs_page.empty()) copy_image(image, images);
    }
  }
  std::cout << "tide: validate: wrote " << (out / "results.csv").string() << ", orders.csv and the plots in "
            << out.string() << '\n';
  if (options.docs_page.empty()) return;
  validation::StudyContext context = validation::current_context(options.command_line);
  context.build = std::string(TIDE_BUILD_TYPE) + ", " + TIDE_CXX_COMPILER;
  if (reused_runs > 0) {
    std::vector<std::string> files;
    for (const fs::path& file : options.reuse) files.push_back(file.string());
    context.reused = std::to_string(reused_runs) + " of the " + std::to_string(runs.size()) + " runs taken from " +
                     joined(files) + " (earlier runs of the study: their wall times were measured then)";
  }
  validation::write_markdown(options.docs_page, context, plan.cases, runs, options.docs_page.stem().string());
  std::cout << "tide: validate: wrote " << options.docs_page.string() << " and its plots in " << images.string()
            << '\n';
}

// A word a POSIX shell reads back as itself.
std::string shell_word(std::string_view word) {
  if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                              "-_./,=:+@") == std::string_view::npos) {
    return std::string(word);
  }
  std::string quoted = "'";
  for (const char c : word) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  quoted += '\'';
  return quoted;
}

}  // namespace

std::string quoted_command_line(int argc, char** argv) {
  std::string text = "tide";
  for (int k = 1; k < argc; ++k) {
    text += ' ';
    text += shell_word(argv[k]);
  }
  return text;
}

int list_cases() {
  for (const Case& study_case : validation::cases()) {
    std::vector<std::string> resolutions;
    for (const int resolution : study_case.resolutions) resolutions.push_back(std::to_string(resolution));
    std::printf("%-20s %s\n%-20s resolutions %s (%s)\n", study_case.name.c_str(), study_case.title.c_str(), "",
                joined(resolutions).c_str(), study_case.resolution_meaning.c_str());
  }
  std::printf("schemes: %s (default: %s)\nkernels: %s (default: %s)\n", joined(validation::scheme_names()).c_str(),
              joined(validation::default_scheme_names()).c_str(), joined(all_kernel_names()).c_str(),
              joined(default_kernel_names()).c_str());
  return exit_ok;
}

int validate(const ValidateOptions& options) {
  if (options.list) return list_cases();
  const std::optional<Plan> plan = make_plan(options);
  if (!plan) return exit_bad_input;
  if (!validation::gnuplot_available()) {
    std::cerr << "tide: validate: gnuplot is not on the PATH and draws the study's plots; install it (Debian: "
                 "apt-get install gnuplot-nox)\n";
    return exit_failure;
  }
  std::vector<StudyRun> reused;
  for (const fs::path& file : options.reuse) {
    try {
      const std::vector<StudyRun> earlier = validation::read_csv(file);
      reused.insert(reused.end(), earlier.begin(), earlier.end());
    } catch (const std::exception& error) {
      std::cerr << "tide: validate: --reuse: " << error.what() << '\n';
      return exit_bad_input;
    }
  }
  std::size_t reused_runs = 0;
  const std::vector<StudyRun> runs = run_study(*plan, options.resolutions, reused, reused_runs);
  write_report(options, *plan, runs, reused_runs);
  const auto failed = std::count_if(runs.begin(), runs.end(), [](const StudyRun& run) { return !run.ok(); });
  if (failed == 0) return exit_ok;
  std::cerr << "tide: validate: " << failed << " of " << runs.size() << " runs failed (status column of results.csv)\n";
  return exit_unstable;
}

}  // namespace tide::app
