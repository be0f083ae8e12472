#include "run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "progress.hpp"
#include "run_frames.hpp"
#include "run_outputs.hpp"
#include "tide/io/checkpoint_file.hpp"
#include "tide/io/crowd_writer.hpp"
#include "tide/io/frame_writer.hpp"
#include "tide/io/probe_writer.hpp"
#include "tide/io/recovery_writer.hpp"
#include "tide/io/scene_reader.hpp"
#include "tide/io/series_writer.hpp"
#include "tide/solvers/capabilities.hpp"
#include "tide/solvers/instability.hpp"
#include "tide/solvers/probes.hpp"
#include "tide/solvers/recovery.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/solvers/stage_shares.hpp"

namespace tide::app {
namespace {

std::string limit_counts(const TimeStepTally& tally) {
  std::ostringstream text;
  for (std::size_t k = 0; k < time_step_limit_count; ++k) {
    text << (k > 0 ? ", " : "") << time_step_limit_name(static_cast<TimeStepLimit>(k)) << ' ' << tally.counts[k];
  }
  return text.str();
}

void add_solve_attributes(const std::string& name, const SolveTally& tally,
                          std::map<std::string, std::string>& attributes) {
  if (tally.solves == 0) return;
  attributes[name + "_solve_mean_iterations"] = std::to_string(tally.mean_iterations());
  attributes[name + "_solve_max_iterations"] = std::to_string(tally.max_iterations);
  attributes[name + "_solve_max_error"] = std::to_string(tally.max_error);
}

void print_solve_summary(const char* name, const SolveTally& tally) {
  if (tally.solves == 0) return;
  std::printf(
      "  %-11s %.3g iterations per step (max %d), final mean density error %.3g%% of rho0 (max %.3g%%), %zu of %zu "
      "missed the threshold\n",
      name, tally.mean_iterations(), tally.max_iterations, 100 * tally.mean_error(), 100 * tally.max_error,
      tally.missed, tally.solves);
}

std::map<std::string, std::string> frame_attributes(const TimeStepTally& since_last_frame,
                                                    const SolveTallies& solves_since_last_frame) {
  std::map<std::string, std::string> attributes;
  if (since_last_frame.total() == 0) return attributes;
  add_solve_attributes("density", solves_since_last_frame.density, attributes);
  add_solve_attributes("divergence", solves_since_last_frame.divergence, attributes);
  attributes["time_step_limit"] = std::string(time_step_limit_name(since_last_frame.most_frequent()));
  for (std::size_t k = 0; k < time_step_limit_count; ++k) {
    attributes[std::string(time_step_limit_name(static_cast<TimeStepLimit>(k))) + "_limited_steps"] =
        std::to_string(since_last_frame.counts[k]);
  }
  return attributes;
}

/// Each rigid body's state into <out>/bodies.csv, columns "<key path>.<quantity>": the centre of
/// mass, the orientation (2D: the angle about z; 3D: the unit quaternion w, x, y, z from the
/// start), the velocity of the centre, the angular velocity, and the fluid's force on the body
/// and its torque about the reference point (the centre, or the pivot), without gravity.
template <int D>
SeriesRecorder<D> body_recorder(const scene::Scene& scene, const RigidBodies<D>& bodies,
                                const std::filesystem::path& output_directory) {
  const std::vector<std::string> axes =
      D == 2 ? std::vector<std::string>{"x", "y"} : std::vector<std::string>{"x", "y", "z"};
  std::vector<std::string> columns;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const std::string body = bodies.contact(k).name() + ".";
    for (const std::string& a : axes) columns.push_back(body + a);
    if (D == 2) {
      columns.push_back(body + "angle");
    } else {
      for (const char* q : {"qw", "qx", "qy", "qz"}) columns.push_back(body + q);
    }
    for (const std::string& a : axes) columns.push_back(body + "v" + a);
    if (D == 2) {
      columns.push_back(body + "omega");
    } else {
      for (const std::string& a : axes) columns.push_back(body + "omega_" + a);
    }
    for (const char* load : {"", "contact_"}) {
      for (const std::string& a : axes) columns.push_back(body + load + "f" + a);
      if (D == 2) {
        columns.push_back(body + load + "torque");
      } else {
        for (const std::string& a : axes) columns.push_back(body + load + "torque_" + a);
      }
    }
  }
  const std::vector<std::string> comments{
      "TideSPH rigid bodies of " + scene.source,
      "SI units; orientation from the start (2D: angle about z in rad; 3D: unit quaternion); force and torque "
      "are the fluid's, contact_ force and torque those of the bodies and walls it touches, without gravity, the "
      "torques about the centre of mass or the pivot"};
  return SeriesRecorder<D>(scene,
                           std::make_unique<io::SeriesWriter>(output_directory / "bodies.csv", comments, columns),
                           [](const Simulation<D>& s) {
                             const RigidBodies<D>& bodies = *s.bodies();
                             std::vector<double> row;
                             for (std::size_t k = 0; k < bodies.size(); ++k) {
                               const RigidBody& body = bodies.body(k);
                               const Eigen::Vector3d centre = body.centre(), omega = body.angular_velocity();
                               const Eigen::Vector3d velocity = body.point(body.mass_properties().centre).velocity;
                               const Eigen::Quaterniond q = body.orientation();
                               for (int d = 0; d < D; ++d) row.push_back(centre[d]);
                               if (D == 2) {
                                 row.push_back(2 * std::atan2(q.z(), q.w()));
                               } else {
                                 row.insert(row.end(), {q.w(), q.x(), q.y(), q.z()});
                               }
                               for (int d = 0; d < D; ++d) row.push_back(velocity[d]);
                               if (D == 2) {
                                 row.push_back(omega.z());
                               } else {
                                 for (int d = 0; d < 3; ++d) row.push_back(omega[d]);
                               }
                               const auto add_load = [&](const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
                                 for (int d = 0; d < D; ++d) row.push_back(force[d]);
                                 if (D == 2) {
                                   row.push_back(torque.z());
                                 } else {
                                   for (int d = 0; d < 3; ++d) row.push_back(torque[d]);
                                 }
                               };
                               add_load(bodies.fluid_force(k), bodies.fluid_torque(k));
                               add_load(bodies.contact_force(k), bodies.contact_torque(k));
                             }
                             return row;
                           });
}

/// The scene's probes into <out>/probes.csv, output.recovery into <out>/recovery.csv (its
/// initial mass measured now: std::invalid_argument when its region holds none).
template <int D>
std::vector<SeriesRecorder<D>> series_recorders(const scene::Scene& scene, const Simulation<D>& simulation,
                                                const std::filesystem::path& output_directory) {
  std::vector<SeriesRecorder<D>> recorders;
  if (!scene.probes.empty()) {
    recorders.emplace_back(scene, std::make_unique<io::ProbeWriter>(output_directory / "probes.csv", scene),
                           [&scene](const Simulation<D>& s) { return read_probes<D>(s, scene.probes); });
  }
  if (scene.output.recovery) {
    auto meter = std::make_shared<const RecoveryMeter<D>>(simulation, *scene.output.recovery);
    recorders.emplace_back(
        scene, std::make_unique<io::RecoveryWriter>(output_directory / "recovery.csv", scene, meter->initial_mass()),
        [meter](const Simulation<D>& s) {
          const double mass = meter->mass(s);
          return std::vector<double>{mass, meter->recovery(mass)};
        });
  }
  if (const RigidBodies<D>* bodies = simulation.bodies(); bodies && !bodies->empty())
    recorders.push_back(body_recorder<D>(scene, *bodies, output_directory));
  if (scene.crowd) {
    recorders.emplace_back(
        scene, std::make_unique<io::CrowdWriter>(output_directory / "crowd.csv", scene), [](const Simulation<D>& s) {
          const CrowdStatus status = *s.crowd_status();
          std::vector<double> row{static_cast<double>(status.inside)};
          for (const std::size_t out : status.out) row.push_back(static_cast<double>(out));
          row.push_back(status.mean_density);
          row.push_back(status.mean_speed);
          row.insert(row.end(),
                     {status.peak.density, status.peak.position[0], status.peak.position[1], status.peak.time});
          return row;
        });
  }
  return recorders;
}

/// The frames of the moving walls (obstacles with a motion), one run of frames per contact, named
/// after its key path: walls.obstacles[2] writes walls_obstacles_2_NNNNNN.h5 and
/// walls_obstacles_2.xdmf beside the fluid's frames.
template <int D>
class MovingWallFrames {
 public:
  MovingWallFrames(const Simulation<D>& simulation, const std::filesystem::path& directory, io::VtkFiles vtk) {
    const Interactions<D>& interactions = simulation.interactions();
    for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
      if (!interactions.contact(k).moves()) continue;
      contacts_.push_back(k);
      writers_.emplace_back(directory, std::vector<std::string>{"position", "surface_velocity", "pressure"},
                            wall_series_name(interactions.contact(k).name()), vtk);
    }
  }

  void write(const Simulation<D>& simulation) {
    for (std::size_t w = 0; w < writers_.size(); ++w) {
      writers_[w].write(simulation.interactions().contact(contacts_[w]).particles(), simulation.time(),
                        simulation.step_count());
    }
  }

  void save(StateArchive& archive) const {
    for (std::size_t w = 0; w < writers_.size(); ++w)
      save_grids(archive, "run/wall_frames/" + std::to_string(w), writers_[w].xdmf_grids());
  }
  void restore(const StateArchive& archive) {
    for (std::size_t w = 0; w < writers_.size(); ++w)
      writers_[w].continue_after(restore_grids(archive, "run/wall_frames/" + std::to_string(w)));
  }

 private:
  std::vector<std::size_t> contacts_;
  std::vector<io::FrameWriter<D>> writers_;
};

/// The walls that do not move, written once as frame 0 of one run of frames per contact
/// (walls_000000.h5, free_slip_walls_000000.h5, ...) so that tide render can draw them.
template <int D>
void write_fixed_walls(const Simulation<D>& simulation, const std::filesystem::path& directory, io::VtkFiles vtk) {
  const Interactions<D>& interactions = simulation.interactions();
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    if (contact.moves() || contact.particles().empty()) continue;
    io::FrameWriter<D>(directory, {"position"}, wall_series_name(contact.name()), vtk)
        .write(contact.particles(), simulation.time(), simulation.step_count());
  }
}

/// Everything `tide run` keeps between two steps, into a checkpoint and back: the simulation's
/// state and the run's outputs so far (frames named in the XDMF files, series rows, schedules,
/// tallies).
template <int D>
struct RunState {
  Simulation<D>& simulation;
  std::vector<SeriesRecorder<D>>& series;
  io::FrameWriter<D>& frames;
  MovingWallFrames<D>& wall_frames;
  OutputSchedule& frame_schedule;
  RunTallies& tallies;

  StateArchive save() const {
    StateArchive archive;
    simulation.save(archive);
    for (std::size_t k = 0; k < series.size(); ++k) series[k].save(archive, "run/series/" + std::to_string(k));
    save_grids(archive, "run/frames", frames.xdmf_grids());
    wall_frames.save(archive);
    frame_schedule.save(archive, "run/frames/next");
    tallies.save(archive, "run/tallies");
    return archive;
  }

  void restore(const StateArchive& archive) {
    simulation.restore(archive);
    for (std::size_t k = 0; k < series.size(); ++k) series[k].restore(archive, "run/series/" + std::to_string(k));
    frames.continue_after(restore_grids(archive, "run/frames"));
    wall_frames.restore(archive);
    frame_schedule.restore(archive, "run/frames/next");
    tallies.restore(archive, "run/tallies");
  }
};

/// The checkpoints a run wrote: how many, and the size and write time of the last.
struct CheckpointTally {
  std::size_t written = 0;
  std::uintmax_t bytes = 0;
  double seconds = 0;
};

template <int D>
int run(const scene::Scene& scene, const RunOptions& options, const std::filesystem::path& output_directory) {
  const std::filesystem::path checkpoint_file = checkpoint_path(output_directory);
  const bool checkpoints_asked = options.checkpoint_every || options.checkpoint_wall;
  io::CheckpointIdentity identity;
  std::optional<StateArchive> resumed;
  try {
    // A run that neither resumes nor writes checkpoints does not read its scene file again.
    if (checkpoints_asked || !options.resume.empty()) identity = io::checkpoint_identity(options.scene_file, D);
    if (!options.resume.empty()) resumed = io::read_checkpoint(checkpoint_file, identity);
  } catch (const std::runtime_error& error) {
    std::cerr << "tide: cannot resume: " << error.what() << '\n';
    return exit_bad_input;
  }
  std::unique_ptr<Simulation<D>> simulation;
  std::vector<SeriesRecorder<D>> series;
  try {
    simulation = make_simulation<D>(scene);
    // Before a restore: the recovery's initial mass is that of the start, as in the run resumed.
    series = series_recorders<D>(scene, *simulation, output_directory);
  } catch (const InstabilityError& error) {
    std::cerr << "tide: " << scene.source << ": the initial state is already out of bounds: " << error.what() << '\n';
    return exit_unstable;
  } catch (const std::invalid_argument& error) {
    std::cerr << "tide: " << error.what() << '\n';
    return exit_bad_input;
  }
  const io::VtkFiles vtk = scene.output.vtk ? io::VtkFiles::on : io::VtkFiles::off;
  io::FrameWriter<D> writer(output_directory, scene.output.fields, "frames", vtk);
  MovingWallFrames<D> wall_frames(*simulation, output_directory, vtk);
  const double end_time = scene.time.end;
  const double interval = scene.time.output_interval;
  OutputSchedule frames(scene.time.start + interval, interval);
  RunTallies tallies;
  RunState<D> state{*simulation, series, writer, wall_frames, frames, tallies};
  if (resumed) {
    try {
      state.restore(*resumed);
    } catch (const std::exception& error) {  // an entry missing or of another length: a damaged checkpoint
      std::cerr << "tide: cannot resume from " << checkpoint_file.string() << ": " << error.what() << '\n';
      return exit_bad_input;
    }
    resumed.reset();
  }
  const std::size_t particles = simulation->fluid().size();
  if (!options.quiet) {
    std::cout << "tide: " << (options.resume.empty() ? "running " : "resuming ") << scene.source << " ("
              << scheme_name(scene.solver.scheme) << ", " << D << "D, " << particles << " fluid and "
              << simulation->interactions().contact_particle_count() << " wall particles) "
              << (options.resume.empty() ? "" : "at t = " + std::to_string(simulation->time()) + " s ")
              << "until t = " << end_time << " s; frames every " << interval << " s into " << output_directory.string()
              << '\n';
  }
  const bool terminal = isatty(fileno(stdout)) != 0;
  const std::uint64_t first_step = simulation->step_count();  // a resumed run's steps before this process
  Progress progress(std::cout, terminal, options.quiet, scene.time.start, end_time, particles, simulation->time(),
                    first_step);

  const auto record_series = [&] {
    for (auto& recorder : series) recorder.record(*simulation);
  };
  const auto write_series = [&] {
    for (const auto& recorder : series) recorder.write();
  };
  if (options.resume.empty()) {
    writer.write(simulation->fluid(), simulation->time(), 0);
    write_fixed_walls(*simulation, output_directory, vtk);
    wall_frames.write(*simulation);
    record_series();
  }
  // On resume, the series files go back to the checkpoint's rows: those the run wrote after it
  // come again from the steps that follow.
  write_series();
  CheckpointSchedule checkpoints(options.checkpoint_every, options.checkpoint_wall, scene.time.start,
                                 simulation->time());
  CheckpointTally checkpoint_tally;
  const auto write_checkpoint = [&] {
    const auto started = std::chrono::steady_clock::now();
    io::write_checkpoint(checkpoint_file, identity, simulation->step_count(), simulation->time(), state.save());
    checkpoint_tally.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    checkpoint_tally.bytes = std::filesystem::file_size(checkpoint_file);
    ++checkpoint_tally.written;
    checkpoints.written(simulation->time());
  };
  std::filesystem::path last_frame = output_directory;
  try {
    while (simulation->time() < end_time) {
      const StepReport report = simulation->step();
      tallies.add(report);
      const double time = simulation->time();
      record_series();
      if (frames.due(time) || time >= end_time) {
        last_frame = writer.write(simulation->fluid(), time, simulation->step_count(),
                                  frame_attributes(tallies.frame, tallies.frame_solves));
        wall_frames.write(*simulation);
        write_series();
        tallies.start_frame();
        frames.advance_past(time);
      }
      if (checkpoints.active() && (checkpoints.due(time) || time >= end_time)) write_checkpoint();
      progress.update(time, simulation->step_count());
    }
  } catch (const InstabilityError& error) {
    progress.finish(simulation->time(), simulation->step_count());
    write_series();
    std::cerr << "tide: " << error.what() << "\ntide: the last good frame is " << last_frame.string() << '\n';
    return exit_unstable;
  } catch (const std::runtime_error& error) {  // a checkpoint that could not be written
    std::cerr << "tide: " << error.what() << '\n';
    return exit_failure;
  }
  progress.finish(simulation->time(), simulation->step_count());
  write_series();

  const double wall = progress.wall_seconds();
  const std::uint64_t steps_here = simulation->step_count() - first_step;
  const double rate = static_cast<double>(particles) * static_cast<double>(steps_here) / wall;
  std::printf("run summary: %s\n", scene.source.c_str());
  // A crowd's agents leave through its exits, counted in crowd.csv; a fluid's particles are lost.
  const bool crowd = scene.crowd.has_value();
  std::size_t gone = simulation->removed_total();
  if (crowd) {
    const std::vector<std::size_t> out = simulation->crowd_status()->out;
    gone = std::accumulate(out.begin(), out.end(), std::size_t{0});
  }
  std::printf("  particles   %zu %s, %zu wall, %zu %s\n", particles, crowd ? "agents at the start" : "fluid",
              simulation->interactions().contact_particle_count(), gone,
              crowd ? "out through the exits" : "removed (left the domain)");
  std::printf("  steps       %llu, simulated %.4g s", static_cast<unsigned long long>(simulation->step_count()),
              simulation->time() - scene.time.start);
  if (first_step > 0) std::printf(" (%llu steps since the resume)", static_cast<unsigned long long>(steps_here));
  std::printf("\n");
  std::printf("  wall time   %.2f s, %.3g M %s-steps/s (%s x steps / wall time)\n", wall, rate / 1e6,
              crowd ? "agent" : "particle", crowd ? "agents at the start" : "fluid particles");
  std::printf("  time step   binding limit per step: %s\n", limit_counts(tallies.run).c_str());
  print_solve_summary("density", tallies.run_solves.density);
  print_solve_summary("divergence", tallies.run_solves.divergence);
  std::printf("  stages      %s\n", format_stage_shares(simulation->pipeline().times()).c_str());
  std::printf("  output      %zu frames, %s\n", writer.frames_written(), writer.xdmf_path().string().c_str());
  for (const auto& recorder : series) {
    std::printf("  series      %zu rows, %s\n", recorder.writer().rows(), recorder.writer().path().string().c_str());
  }
  if (checkpoint_tally.written > 0) {
    std::printf("  checkpoints %zu, %s: %.3g MB, written in %.3g s\n", checkpoint_tally.written,
                checkpoint_file.string().c_str(), static_cast<double>(checkpoint_tally.bytes) / 1e6,
                checkpoint_tally.seconds);
  }
  return exit_ok;
}

// A scene the reader accepts but that is likely to go unstable: said before any work, without
// stopping it (stress-testing a limit is a reason to run such a scene).
void warn_about(const scene::Scene& scene) {
  if (scene.solver.cfl > max_stable_cfl) {
    std::cerr << "tide: warning: " << scene.source << ": /solver/cfl = " << scene.solver.cfl << " is above "
              << max_stable_cfl << ", beyond which explicit WCSPH steps are not known to be stable "
              << "(docs/stability.md, time step)\n";
  }
}

}  // namespace

std::optional<scene::Scene> load_scene(const std::filesystem::path& file) {
  try {
    scene::Scene scene = io::read_scene_file(file);
    check_capabilities(scene);
    warn_about(scene);
    return scene;
  } catch (const scene::SceneError& error) {
    std::cerr << "tide: " << error.what() << '\n';
    return std::nullopt;
  }
}

std::filesystem::path checkpoint_path(const std::filesystem::path& run_directory) {
  return run_directory / "checkpoint.h5";
}

std::filesystem::path run_output_directory(const RunOptions& options) {
  if (!options.resume.empty()) return options.resume;
  return options.output_directory.empty() ? std::filesystem::path("runs") / options.scene_file.stem()
                                          : options.output_directory;
}

int run_scene(const RunOptions& given) {
  RunOptions options = given;
  if (!options.resume.empty()) {
    if (!options.output_directory.empty() && options.output_directory != options.resume) {
      std::cerr << "tide: --resume " << options.resume.string() << " continues the run in that directory; --out "
                << options.output_directory.string() << " names another\n";
      return exit_bad_input;
    }
    if (options.scene_file.empty()) {
      try {
        options.scene_file = io::checkpoint_scene_file(checkpoint_path(options.resume));
      } catch (const std::runtime_error& error) {
        std::cerr << "tide: cannot resume: " << error.what() << '\n';
        return exit_bad_input;
      }
    }
  }
  std::optional<scene::Scene> scene = load_scene(options.scene_file);
  if (!scene) return exit_bad_input;
  if (options.until) {
    if (!(*options.until > scene->time.start)) {
      std::cerr << "tide: --until: expected a time after the scene's start time " << scene->time.start << " s, got "
                << *options.until << '\n';
      return exit_bad_input;
    }
    scene->time.end = *options.until;
  }
  if (options.vtk) scene->output.vtk = true;
  const std::filesystem::path output_directory = run_output_directory(options);
  return scene->dimension == 2 ? run<2>(*scene, options, output_directory) : run<3>(*scene, options, output_directory);
}

int check_scene(const std::filesystem::path& scene_file) {
  const std::optional<scene::Scene> scene = load_scene(scene_file);
  if (!scene) return exit_bad_input;
  try {
    auto report = [&](const auto& simulation) {
      std::cout << scene_file.string() << ": ok: " << scheme_name(scene->solver.scheme) << ", " << scene->dimension
                << "D, " << simulation.fluid().size() << " fluid and "
                << simulation.interactions().contact_particle_count()
                << " wall particles, h = " << simulation.smoothing_length() << " m, t = " << scene->time.start << " to "
                << scene->time.end << " s\n";
    };
    if (scene->dimension == 2) {
      report(*make_simulation<2>(*scene));
    } else {
      report(*make_simulation<3>(*scene));
    }
  } catch (const InstabilityError& error) {
    std::cerr << "tide: " << scene_file.string() << ": the initial state is out of bounds: " << error.what() << '\n';
    return exit_bad_input;
  } catch (const std::invalid_argument& error) {
    std::cerr << "tide: " << error.what() << '\n';
    return exit_bad_input;
  }
  return exit_ok;
}

}  // namespace tide::app
