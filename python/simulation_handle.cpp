#include "simulation_handle.hpp"

#include "tide/io/checkpoint_file.hpp"

namespace tide::python {
namespace {

AnySimulation make_any_simulation(const scene::Scene& scene) {
  if (scene.dimension == 3) return std::shared_ptr<Simulation<3>>(make_simulation<3>(scene));
  return std::shared_ptr<Simulation<2>>(make_simulation<2>(scene));
}

}  // namespace

SimulationHandle::SimulationHandle(SceneSource source)
    : source_(std::move(source)), simulation_(make_any_simulation(source_.scene)) {}

StepReport SimulationHandle::step() {
  return std::visit(
      [&](auto& simulation) {
        const auto start = std::chrono::steady_clock::now();
        const StepReport report = simulation->step();
        const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
        statistics_.add(report, simulation->fluid().size(), seconds.count());
        return report;
      },
      simulation_);
}

bool SimulationHandle::run_for(double until, std::chrono::duration<double> wall_budget) {
  const auto start = std::chrono::steady_clock::now();
  const auto time = [&] { return std::visit([](const auto& simulation) { return simulation->time(); }, simulation_); };
  while (time() < until) {
    if (std::chrono::steady_clock::now() - start >= wall_budget) return false;
    step();
  }
  return true;
}

void SimulationHandle::write_checkpoint(const std::filesystem::path& file) const {
  std::visit(
      [&](const auto& simulation) {
        StateArchive archive;
        simulation->save(archive);
        io::write_checkpoint(file, source_.identity, simulation->step_count(), simulation->time(), archive);
      },
      simulation_);
}

void SimulationHandle::restore_checkpoint(const std::filesystem::path& file) {
  const StateArchive archive = io::read_checkpoint(file, source_.identity);
  AnySimulation restored = make_any_simulation(source_.scene);
  std::visit([&](auto& simulation) { simulation->restore(archive); }, restored);
  simulation_ = std::move(restored);
  statistics_ = {};
}

}  // namespace tide::python
