#pragma once

// What `tide run` writes as it goes and keeps in its checkpoints (docs/output.md, "Checkpoints"):
// the schedule of a periodic output, the CSV series, and the tallies behind the frames'
// attributes and the run summary.

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tide/core/scene.hpp"
#include "tide/core/state_archive.hpp"
#include "tide/io/series_writer.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/solvers/step_report.hpp"
#include "tide/solvers/time_step.hpp"

namespace tide::app {

/// The times of a periodic output: one is due once the time passes the next output time (within
/// round-off of the sum of intervals).
class OutputSchedule {
 public:
  OutputSchedule(double first, double interval) : next_(first), interval_(interval) {}
  bool due(double time) const { return time >= next_ - 1e-9 * interval_; }
  void advance_past(double time) {
    while (next_ <= time + 1e-9 * interval_) next_ += interval_;
  }
  void save(StateArchive& archive, const std::string& path) const { archive.put_double(path, next_); }
  void restore(const StateArchive& archive, const std::string& path) { next_ = archive.double_value(path); }

 private:
  double next_;
  double interval_;
};

/// When `tide run` writes its checkpoint: every `every` simulated seconds after the start, when
/// `wall_seconds` of wall-clock time have passed since the last one, and after the last step;
/// with neither interval, never.
class CheckpointSchedule {
 public:
  CheckpointSchedule(std::optional<double> every, std::optional<double> wall_seconds, double start_time, double now)
      : every_(every.has_value()),
        simulated_(start_time + every.value_or(1), every.value_or(1)),
        wall_seconds_(wall_seconds.value_or(0)),
        last_(std::chrono::steady_clock::now()) {
    simulated_.advance_past(now);
  }
  bool active() const { return every_ || wall_seconds_ > 0; }
  bool due(double time) const {
    const std::chrono::duration<double> since = std::chrono::steady_clock::now() - last_;
    return (every_ && simulated_.due(time)) || (wall_seconds_ > 0 && since.count() >= wall_seconds_);
  }
  void written(double time) {
    simulated_.advance_past(time);
    last_ = std::chrono::steady_clock::now();
  }

 private:
  bool every_;
  OutputSchedule simulated_;  // read only with every_
  double wall_seconds_;       // 0: none
  std::chrono::steady_clock::time_point last_;
};

/// A time series read every output.probe_interval into a CSV file; does nothing without a writer.
template <int D>
class SeriesRecorder {
 public:
  using Reading = std::function<std::vector<double>(const Simulation<D>&)>;

  SeriesRecorder(const scene::Scene& scene, std::unique_ptr<io::SeriesWriter> writer, Reading read)
      : writer_(std::move(writer)), read_(std::move(read)), schedule_(scene.time.start, scene.output.probe_interval) {}

  bool active() const { return writer_ != nullptr; }
  const io::SeriesWriter& writer() const { return *writer_; }

  /// Adds a row if one is due at the simulation's time.
  void record(const Simulation<D>& simulation) {
    if (!active() || !schedule_.due(simulation.time())) return;
    writer_->add(simulation.time(), read_(simulation));
    schedule_.advance_past(simulation.time());
  }

  void write() const {
    if (active()) writer_->write();
  }

  /// The rows so far and the next reading's time, under `path`.
  void save(StateArchive& archive, const std::string& path) const {
    if (!active()) return;
    schedule_.save(archive, path + "/next");
    archive.put_text(path + "/rows", writer_->rows_text());
    archive.put_count(path + "/row_count", writer_->rows());
  }
  void restore(const StateArchive& archive, const std::string& path) {
    if (!active()) return;
    schedule_.restore(archive, path + "/next");
    writer_->continue_after(archive.text(path + "/rows"), archive.count_value(path + "/row_count"));
  }

 private:
  std::unique_ptr<io::SeriesWriter> writer_;
  Reading read_;
  OutputSchedule schedule_;
};

/// The pressure solves of one kind over a run, for its summary and its frames.
struct SolveTallies {
  SolveTally density;
  SolveTally divergence;

  void add(const StepReport& report) {
    if (report.density_solve) density.add(*report.density_solve);
    if (report.divergence_solve) divergence.add(*report.divergence_solve);
  }
};

/// The steps' binding limits and solves, over the run (for its summary) and since the last frame
/// (for the next frame's attributes).
struct RunTallies {
  TimeStepTally run, frame;
  SolveTallies run_solves, frame_solves;

  void add(const StepReport& report) {
    run.add(report.time_step.limit);
    frame.add(report.time_step.limit);
    run_solves.add(report);
    frame_solves.add(report);
  }
  void start_frame() {
    frame = {};
    frame_solves = {};
  }
  void save(StateArchive& archive, const std::string& path) const;
  void restore(const StateArchive& archive, const std::string& path);
};

/// The XDMF grids of a frame writer (io::FrameWriter::xdmf_grids), under `path`, and back.
void save_grids(StateArchive& archive, const std::string& path, const std::vector<std::string>& grids);
std::vector<std::string> restore_grids(const StateArchive& archive, const std::string& path);

}  // namespace tide::app
