#pragma once

#include <filesystem>
#include <optional>

namespace tide::app {

struct OilStudyOptions {
  std::filesystem::path scenes_directory;  // where the oil_*.json scenes are
  std::filesystem::path output_directory = "oil-study";
  std::optional<double> until;  // overrides each scene's end time
  bool reuse = false;           // take a scene's recovery.csv from an earlier study that reached its end time
};

/// `tide oil-study`: runs every oil_*.json scene (the cavity–fracture structures after Zhou et al.
/// 2010, docs/multiphase.md), each into <out>/<scene name>/, then writes oil_study.csv and
/// oil_study.md (the recovery of each scene at its end) and plots the recovery curves with
/// gnuplot: middle_fractured.png, upper_fractured.png and upper_fractured_width.png.
/// Exit code 2 when there are no scenes, 3 if a run failed.
int oil_study(const OilStudyOptions& options);

}  // namespace tide::app
