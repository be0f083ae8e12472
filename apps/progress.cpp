#include "progress.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace tide::app {
namespace {

std::string format_seconds(double seconds) {
  char text[32];
  if (seconds < 60) {
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  } else {
    std::snprintf(text, sizeof text, "%d min %02d s", static_cast<int>(seconds) / 60, static_cast<int>(seconds) % 60);
  }
  return text;
}

}  // namespace

Progress::Progress(std::ostream& out, bool terminal, bool quiet, double start_time, double end_time,
                   std::size_t particles, double from_time, std::uint64_t from_step)
    : out_(out),
      terminal_(terminal),
      quiet_(quiet),
      start_time_(start_time),
      end_time_(end_time),
      particles_(particles),
      from_time_(from_time),
      from_step_(from_step),
      wall_start_(std::chrono::steady_clock::now()),
      last_draw_(wall_start_) {}

double Progress::wall_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
}

void Progress::update(double time, std::uint64_t steps, bool force) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  // A terminal is redrawn ten times a second; a log gets a line every ten seconds.
  const auto interval = terminal_ ? std::chrono::milliseconds(100) : std::chrono::milliseconds(10000);
  if (!force && now - last_draw_ < interval) return;
  last_draw_ = now;

  const double fraction = std::clamp((time - start_time_) / (end_time_ - start_time_), 0.0, 1.0);
  const double wall = wall_seconds();
  const double done = time - from_time_;  // by this process
  const double eta = done > 0 ? wall * std::max(end_time_ - time, 0.0) / done : 0;
  const double rate = wall > 0 ? static_cast<double>(particles_) * static_cast<double>(steps - from_step_) / wall : 0;
  char line[256];
  std::snprintf(line, sizeof line, "t = %.4g / %.4g s  step %llu  wall %s  ETA %s  %.3g M particle-steps/s", time,
                end_time_, static_cast<unsigned long long>(steps), format_seconds(wall).c_str(),
                format_seconds(eta).c_str(), rate / 1e6);
  if (terminal_) {
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width);
    out_ << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] "
         << static_cast<int>(fraction * 100) << "%  " << line << "\033[K" << std::flush;
  } else {
    out_ << "progress " << static_cast<int>(fraction * 100) << "%: " << line << '\n' << std::flush;
  }
}

void Progress::finish(double time, std::uint64_t steps) {
  update(time, steps, true);
  if (terminal_ && !quiet_) out_ << '\n';
}

}  // namespace tide::app
