// The validation study's report on hand-made runs: CSV layout and quoting, convergence orders
// of synthetic errors with a known order, the markdown page's tables, and gnuplot's figures.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tide/validation/report.hpp"

namespace tide::validation {
namespace {

namespace fs = std::filesystem;

StudyRun make_run(const std::string& case_name, const std::string& scheme, int resolution,
                  std::vector<Metric> metrics) {
  StudyRun run;
  run.record.case_name = case_name;
  run.record.scheme = scheme;
  run.record.kernel = "wendland_c2";
  run.record.resolution = resolution;
  run.record.particles = static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution);
  run.record.steps = 10 * static_cast<std::uint64_t>(resolution);
  run.record.wall_seconds = 1e-4 * resolution * resolution;
  run.record.metrics = std::move(metrics);
  return run;
}

// Errors C r^-p at a ladder of resolutions: a scheme of known order p.
std::vector<StudyRun> ladder(const std::string& scheme, double order) {
  std::vector<StudyRun> runs;
  for (const int resolution : {10, 20, 40, 80}) {
    runs.push_back(make_run("poiseuille", scheme, resolution,
                            {{"velocity_l2_error", 3.0 * std::pow(resolution, -order)},
                             {"wall_shear_error", 0.5 * std::pow(resolution, -1.0)}}));
  }
  return runs;
}

Case synthetic_case() {
  Case study_case;
  study_case.name = "poiseuille";
  study_case.title = "Poiseuille flow start-up";
  study_case.reference = "series solution (Morris et al. 1997)";
  study_case.resolution_meaning = "particles across the channel";
  study_case.metric_notes = {"velocity_l2_error: L2 norm of u - u_exact over max |u_exact|",
                             "wall_shear_error: relative error of the wall shear stress"};
  study_case.resolutions = {10, 20, 40, 80};
  return study_case;
}

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class ValidationReport : public testing::Test {
 protected:
  void SetUp() override {
    directory_ =
        fs::temp_directory_path() /
        ("validation_report_test_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  fs::path directory_;
};

TEST_F(ValidationReport, CsvHasTheUnionOfMetricColumnsInFirstSeenOrder) {
  const std::vector<StudyRun> runs{make_run("a", "wcsph", 20, {{"first", 0.5}, {"second", 0.25}}),
                                   make_run("b", "wcsph", 20, {{"third", 2}, {"first", 0.125}})};
  write_csv(directory_ / "results.csv", runs);
  const std::vector<std::string> lines = read_lines(directory_ / "results.csv");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "case,scheme,kernel,resolution,particles,steps,wall_seconds,particle_steps_per_second,status,first,"
            "second,third");
  EXPECT_EQ(lines[1], "a,wcsph,wendland_c2,20,400,200,0.04,2e+06,ok,0.5,0.25,");
  EXPECT_EQ(lines[2], "b,wcsph,wendland_c2,20,400,200,0.04,2e+06,ok,0.125,,2");
  EXPECT_FALSE(fs::exists(directory_ / "results.csv.tmp"));
}

TEST_F(ValidationReport, CsvQuotesFieldsAndRecordsFailedRuns) {
  StudyRun failed = make_run("dam, break", "wcsph", 40, {});
  failed.failure = "density \"out of band\", step 12";
  const std::vector<StudyRun> runs{make_run("dam, break", "wcsph", 20, {{"front_error", 0.1}}), failed};
  write_csv(directory_ / "results.csv", runs);
  const std::vector<std::string> lines = read_lines(directory_ / "results.csv");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1], "\"dam, break\",wcsph,wendland_c2,20,400,200,0.04,2e+06,ok,0.1");
  EXPECT_EQ(lines[2], "\"dam, break\",wcsph,wendland_c2,40,,,,,\"failed: density \"\"out of band\"\", step 12\",");
}

TEST_F(ValidationReport, CsvReadsBackWhatWasWritten) {
  StudyRun failed = make_run("dam, break", "dfsph", 40, {});
  failed.failure = "density \"out of band\",\nstep 12";
  const std::vector<StudyRun> runs{make_run("dam, break", "wcsph", 20, {{"front_error", 0.1}, {"offset", 1.0 / 3}}),
                                   failed, make_run("poiseuille", "iisph", 10, {{"velocity_l2_error", 2.5e-7}})};
  write_csv(directory_ / "results.csv", runs);
  const std::vector<StudyRun> read = read_csv(directory_ / "results.csv");
  ASSERT_EQ(read.size(), runs.size());
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const RunRecord& expected = runs[k].record;
    const RunRecord& got = read[k].record;
    EXPECT_EQ(got.case_name, expected.case_name);
    EXPECT_EQ(got.scheme, expected.scheme);
    EXPECT_EQ(got.kernel, expected.kernel);
    EXPECT_EQ(got.resolution, expected.resolution);
    EXPECT_EQ(read[k].failure, runs[k].failure);
    if (!runs[k].ok()) continue;
    EXPECT_EQ(got.particles, expected.particles);
    EXPECT_EQ(got.steps, expected.steps);
    EXPECT_EQ(got.wall_seconds, expected.wall_seconds);  // format_shortest reads back exactly
    ASSERT_EQ(got.metrics.size(), expected.metrics.size());
    for (std::size_t m = 0; m < expected.metrics.size(); ++m) {
      EXPECT_EQ(got.metrics[m].name, expected.metrics[m].name);
      EXPECT_EQ(got.metrics[m].value, expected.metrics[m].value);
    }
  }
}

TEST_F(ValidationReport, CsvReaderNamesTheLineAndWhatItExpected) {
  const auto error_of = [&](const std::string& text) {
    std::ofstream(directory_ / "bad.csv") << text;
    try {
      read_csv(directory_ / "bad.csv");
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  const std::string header =
      "case,scheme,kernel,resolution,particles,steps,wall_seconds,particle_steps_per_second,status,e\n";
  EXPECT_NE(error_of("a,b\n").find("bad.csv:1: expected the header"), std::string::npos);
  EXPECT_NE(error_of(header + "c,wcsph,wendland_c2,20,400,200,0.04,2e+06,ok\n").find("bad.csv:2: expected 10 fields"),
            std::string::npos);
  EXPECT_NE(error_of(header + "c,wcsph,wendland_c2,twenty,400,200,0.04,2e+06,ok,1\n")
                .find("bad.csv:2, column resolution: expected a number, found \"twenty\""),
            std::string::npos);
  EXPECT_NE(error_of(header + "c,wcsph,wendland_c2,20,400,200,0.04,2e+06,done,1\n").find("column status"),
            std::string::npos);
  EXPECT_NE(error_of(header + "\"c,wcsph\n").find("line 2: a quoted field is not closed"), std::string::npos);
  EXPECT_NE(error_of("").find("expected the header"), std::string::npos);
  EXPECT_THROW(read_csv(directory_ / "missing.csv"), std::runtime_error);
}

TEST(ConvergenceOrders, PowerLawErrorsGiveTheirExponent) {
  std::vector<StudyRun> runs = ladder("wcsph", 2.0);
  const std::vector<StudyRun> delta = ladder("wcsph_delta", 1.5);
  runs.insert(runs.end(), delta.begin(), delta.end());
  // A failed run and a run without the metric are left out, not counted as zero error.
  runs.push_back(make_run("poiseuille", "wcsph", 160, {}));
  runs.back().failure = "unstable";

  const std::vector<ConvergenceOrder> orders = convergence_orders(runs);
  ASSERT_EQ(orders.size(), 16u);  // 2 schemes x 2 metrics x (3 consecutive + 1 fit)
  for (const ConvergenceOrder& order : orders) {
    const double expected = order.metric == "wall_shear_error" ? 1.0 : order.scheme == "wcsph" ? 2.0 : 1.5;
    EXPECT_NEAR(order.order, expected, 1e-12) << order.scheme << ' ' << order.metric << ' ' << order.from;
    EXPECT_EQ(order.to, order.least_squares ? 80 : 2 * order.from);
  }
  EXPECT_EQ(orders[0].scheme, "wcsph");
  EXPECT_EQ(orders[0].metric, "velocity_l2_error");
  EXPECT_EQ(orders[0].from, 10);
  EXPECT_TRUE(orders[3].least_squares);
  EXPECT_EQ(orders[3].from, 10);
}

TEST(ConvergenceOrders, LeastSquaresFitsANoisyLadder) {
  // ln e = ln 2 - 2 ln r + (+d, -d, +d): the consecutive orders scatter, the fit stays near 2.
  const double d = 0.05;
  std::vector<StudyRun> runs;
  const std::vector<int> resolutions{40, 10, 20};  // out of order on purpose
  const std::vector<double> noise{d, d, -d};
  for (std::size_t k = 0; k < resolutions.size(); ++k) {
    runs.push_back(
        make_run("c", "wcsph", resolutions[k], {{"e", 2.0 * std::pow(resolutions[k], -2.0) * std::exp(noise[k])}}));
  }
  const std::vector<ConvergenceOrder> orders = convergence_orders(runs);
  ASSERT_EQ(orders.size(), 3u);
  EXPECT_NEAR(orders[0].order, 2.0 + 2 * d / std::log(2.0), 1e-12);
  EXPECT_NEAR(orders[1].order, 2.0 - 2 * d / std::log(2.0), 1e-12);
  // Slope of the noise (d, -d, d) against ln r (0, 1, 2) ln 2 is zero: the fit is exact.
  EXPECT_TRUE(orders[2].least_squares);
  EXPECT_NEAR(orders[2].order, 2.0, 1e-12);
}

TEST_F(ValidationReport, OrdersCsvHasOneRowPerOrder) {
  const std::vector<StudyRun> runs = ladder("wcsph", 2.0);
  const std::vector<ConvergenceOrder> orders = convergence_orders(runs);
  write_orders_csv(directory_ / "orders.csv", orders);
  const std::vector<std::string> lines = read_lines(directory_ / "orders.csv");
  ASSERT_EQ(lines.size(), orders.size() + 1);
  EXPECT_EQ(lines[0], "case,scheme,kernel,metric,from,to,order,fit");
  EXPECT_EQ(lines[4].substr(0, lines[4].find(",2")), "poiseuille,wcsph,wendland_c2,velocity_l2_error,10,80");
  EXPECT_TRUE(lines[4].ends_with(",least_squares"));
}

TEST_F(ValidationReport, MarkdownHasARowPerRunAndTheCaseInformation) {
  std::vector<StudyRun> runs = ladder("wcsph", 2.0);
  runs.push_back(make_run("poiseuille", "wcsph_delta", 10, {}));
  runs.back().failure = "velocity | beyond the sound speed";
  StudyContext context;
  context.command = "tide validate poiseuille --docs docs/validation.md";
  context.machine = "test CPU (2 logical cores)";
  context.threads = 2;
  context.precision = "double";
  context.date = "2025-01-01";
  const std::vector<Case> cases{synthetic_case()};
  write_markdown(directory_ / "validation.md", context, cases, runs, "validation");
  const std::string page = read_text(directory_ / "validation.md");

  EXPECT_NE(page.find(context.command), std::string::npos);
  EXPECT_NE(page.find("## Poiseuille flow start-up"), std::string::npos);
  EXPECT_NE(page.find("series solution (Morris et al. 1997)"), std::string::npos);
  EXPECT_NE(page.find("particles across the channel"), std::string::npos);
  EXPECT_NE(page.find("- wall_shear_error: relative error"), std::string::npos);
  EXPECT_NE(page.find("| scheme | kernel | resolution | particles | steps | wall s | particle-steps/s | "
                      "velocity_l2_error | wall_shear_error |"),
            std::string::npos);
  EXPECT_NE(page.find("| wcsph | wendland_c2 | 10 | 100 | 100 | 0.01 | 1e+06 | 0.03 | 0.05 |"), std::string::npos);
  EXPECT_NE(page.find("| wcsph | wendland_c2 | 80 | 6400 | 800 | 0.64 | 8e+06 | 0.000469 | 0.00625 |"),
            std::string::npos);
  EXPECT_NE(page.find("| wcsph_delta | wendland_c2 | 10 | failed: velocity \\| beyond the sound speed |"),
            std::string::npos);
  EXPECT_NE(page.find("10→20: 2.00, 20→40: 2.00, 40→80: 2.00 | 2.00 (10→80) |"), std::string::npos);
  EXPECT_NE(page.find("](validation/poiseuille.png)"), std::string::npos);
}

// Hand-written notes in <page>-notes/<case>.md end the case's section, so that a regenerated page
// keeps them; a case without a notes file gets none.
TEST_F(ValidationReport, MarkdownEndsACaseWithItsHandWrittenNotes) {
  EXPECT_EQ(notes_directory(directory_ / "validation.md"), directory_ / "validation-notes");
  fs::create_directories(directory_ / "validation-notes");
  const std::string note = "### Measured by hand\n\nA table kept across regenerations.\n";
  std::ofstream(directory_ / "validation-notes" / "poiseuille.md") << note;
  const std::vector<StudyRun> runs = ladder("wcsph", 2.0);
  Case other = synthetic_case();
  other.name = "couette";
  other.title = "Couette flow start-up";
  const std::vector<Case> cases{synthetic_case(), other};
  write_markdown(directory_ / "validation.md", StudyContext{}, cases, runs, "validation");
  const std::string page = read_text(directory_ / "validation.md");

  const std::size_t at = page.find(note);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(page.find(note, at + 1), std::string::npos) << "once";
  EXPECT_LT(page.find("](validation/poiseuille_resolution.png)\n\n" + note), at + 1) << "after the figures";
  EXPECT_EQ(page.compare(at + note.size(), 25, "\n## Couette flow start-up"), 0) << "before the next case";
}

TEST_F(ValidationReport, GnuplotDrawsNonEmptyPngs) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  std::vector<StudyRun> runs = ladder("wcsph", 2.0);
  const std::vector<StudyRun> delta = ladder("wcsph_delta", 1.5);
  runs.insert(runs.end(), delta.begin(), delta.end());
  runs.push_back(make_run("other case", "wcsph", 20, {{"e", 1}}));
  const std::vector<fs::path> images = write_plots(directory_, synthetic_case(), runs);
  ASSERT_EQ(images.size(), 2u);
  EXPECT_EQ(images[0], directory_ / "poiseuille.png");
  EXPECT_EQ(images[1], directory_ / "poiseuille_resolution.png");
  for (const fs::path& image : images) {
    ASSERT_TRUE(fs::exists(image)) << image;
    std::ifstream in(image, std::ios::binary);
    char signature[8] = {};
    in.read(signature, sizeof signature);
    EXPECT_EQ(std::string(signature + 1, 3), "PNG") << image;
    EXPECT_GT(fs::file_size(image), 1000u) << image;
  }
  // Only the images remain: no script, log or partial file.
  EXPECT_EQ(std::distance(fs::directory_iterator(directory_), fs::directory_iterator()), 2);
}

TEST_F(ValidationReport, NoPlotWithoutAPositiveError) {
  std::vector<StudyRun> runs{make_run("poiseuille", "wcsph", 20, {{"e", 0}})};
  runs.push_back(make_run("poiseuille", "wcsph", 40, {}));
  runs.back().failure = "unstable";
  EXPECT_TRUE(write_plots(directory_, synthetic_case(), runs).empty());
}

}  // namespace
}  // namespace tide::validation
