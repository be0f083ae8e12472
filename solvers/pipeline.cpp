#include "tide/solvers/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

namespace tide {

Pipeline::Pipeline(std::vector<Stage> stages) : stages_(std::move(stages)), seconds_(stages_.size(), 0) {
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    for (std::size_t before = 0; before < k; ++before) {
      if (stages_[before].name == stages_[k].name)
        throw std::invalid_argument("pipeline: two stages named " + stages_[k].name);
    }
  }
}

void Pipeline::run(StepContext& context) {
  auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    stages_[k].run(context);
    const auto end = std::chrono::steady_clock::now();
    seconds_[k] += std::chrono::duration<double>(end - start).count();
    start = end;
  }
}

std::vector<std::string_view> Pipeline::names() const {
  std::vector<std::string_view> names;
  names.reserve(stages_.size());
  for (const Stage& stage : stages_) names.emplace_back(stage.name);
  return names;
}

bool Pipeline::contains(std::string_view name) const {
  return std::any_of(stages_.begin(), stages_.end(), [&](const Stage& stage) { return stage.name == name; });
}

double Pipeline::seconds(std::string_view name) const {
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    if (stages_[k].name == name) return seconds_[k];
  }
  return 0;
}

std::vector<StageTime> Pipeline::times() const {
  std::vector<StageTime> times;
  times.reserve(stages_.size());
  for (std::size_t k = 0; k < stages_.size(); ++k) times.push_back({stages_[k].name, seconds_[k]});
  return times;
}

}  // namespace tide
