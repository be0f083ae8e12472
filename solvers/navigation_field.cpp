#include "tide/solvers/navigation_field.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

namespace tide {

NavigationField::NavigationField(const Grid& grid, std::vector<bool> blocked, const std::vector<bool>& goal)
    : grid_(grid), blocked_(std::move(blocked)) {
  march(goal);
  set_directions();
}

bool NavigationField::neighbor(std::size_t cx, std::size_t cy, int dx, int dy, std::size_t& index) const {
  std::array<long long, 2> c{static_cast<long long>(cx) + dx, static_cast<long long>(cy) + dy};
  for (int d = 0; d < 2; ++d) {
    const auto n = static_cast<long long>(grid_.cells[d]);
    if (grid_.periodic[d]) c[d] = ((c[d] % n) + n) % n;
    if (c[d] < 0 || c[d] >= n) return false;
  }
  index = static_cast<std::size_t>(c[1]) * grid_.cells[0] + static_cast<std::size_t>(c[0]);
  return true;
}

void NavigationField::march(const std::vector<bool>& goal) {
  const std::size_t nx = grid_.cells[0];
  const std::size_t count = nx * grid_.cells[1];
  distance_.assign(count, unreachable);
  std::vector<bool> known(count, false);
  using Entry = std::pair<double, std::size_t>;  // (distance, cell): a total order, so ties resolve the same way
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> trial;
  for (std::size_t k = 0; k < count; ++k) {
    if (goal[k] && !blocked_[k]) {
      distance_[k] = 0;
      trial.push({0, k});
    }
  }
  const double h = grid_.cell;
  // The smallest known distance of the two neighbours of cell (cx, cy) along one axis.
  const auto upwind = [&](std::size_t cx, std::size_t cy, int axis) {
    double least = unreachable;
    for (const int step : {-1, 1}) {
      std::size_t n = 0;
      if (neighbor(cx, cy, axis == 0 ? step : 0, axis == 1 ? step : 0, n) && known[n])
        least = std::min(least, distance_[n]);
    }
    return least;
  };
  while (!trial.empty()) {
    const auto [t, k] = trial.top();
    trial.pop();
    if (known[k]) continue;
    known[k] = true;
    const std::size_t cx = k % nx, cy = k / nx;
    for (const auto& [dx, dy] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}}) {
      std::size_t n = 0;
      if (!neighbor(cx, cy, dx, dy, n) || known[n] || blocked_[n]) continue;
      const std::size_t nx_ = n % nx, ny_ = n / nx;
      const double a = upwind(nx_, ny_, 0), b = upwind(nx_, ny_, 1);
      // The first-order upwind update of the eikonal equation (Sethian 1996, eq. 3): one-sided
      // where only one axis has a known neighbour or the two differ by a cell or more.
      const double candidate =
          std::abs(a - b) >= h ? std::min(a, b) + h : (a + b + std::sqrt(2 * h * h - (a - b) * (a - b))) / 2;
      if (candidate < distance_[n]) {
        distance_[n] = candidate;
        trial.push({candidate, n});
      }
    }
  }
}

void NavigationField::set_directions() {
  const std::size_t nx = grid_.cells[0];
  direction_.assign(distance_.size(), {0, 0});
  for (std::size_t k = 0; k < distance_.size(); ++k) {
    if (!std::isfinite(distance_[k])) continue;
    const std::size_t cx = k % nx, cy = k / nx;
    std::array<double, 2> gradient{};
    for (int axis = 0; axis < 2; ++axis) {
      // Central where both neighbours are reachable, one-sided where one is, as −∇T must not
      // point into a wall.
      std::size_t low = 0, high = 0;
      const bool has_low =
          neighbor(cx, cy, axis == 0 ? -1 : 0, axis == 1 ? -1 : 0, low) && std::isfinite(distance_[low]);
      const bool has_high =
          neighbor(cx, cy, axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, high) && std::isfinite(distance_[high]);
      if (has_low && has_high) {
        gradient[axis] = (distance_[high] - distance_[low]) / (2 * grid_.cell);
      } else if (has_high) {
        gradient[axis] = (distance_[high] - distance_[k]) / grid_.cell;
      } else if (has_low) {
        gradient[axis] = (distance_[k] - distance_[low]) / grid_.cell;
      }
    }
    const double norm = std::hypot(gradient[0], gradient[1]);
    if (norm > 0) direction_[k] = {-gradient[0] / norm, -gradient[1] / norm};
  }
}

bool NavigationField::cell_of(const Vector<2>& x, std::array<std::size_t, 2>& cell) const {
  for (int d = 0; d < 2; ++d) {
    double c = std::floor((static_cast<double>(x[d]) - grid_.lower[d]) / grid_.cell);
    const auto n = static_cast<double>(grid_.cells[d]);
    if (grid_.periodic[d]) c -= n * std::floor(c / n);
    if (!(c >= 0 && c < n)) return false;
    cell[d] = static_cast<std::size_t>(c);
  }
  return true;
}

double NavigationField::distance(const Vector<2>& x) const {
  std::array<std::size_t, 2> cell{};
  if (!cell_of(x, cell)) return unreachable;
  return distance_[cell[1] * grid_.cells[0] + cell[0]];
}

bool NavigationField::blocked(const Vector<2>& x) const {
  std::array<std::size_t, 2> cell{};
  return !cell_of(x, cell) || blocked_[cell[1] * grid_.cells[0] + cell[0]];
}

Vector<2> NavigationField::direction(const Vector<2>& x) const {
  // The cell whose centre is the lower-left of the four around x, and x's place between them.
  std::array<double, 2> s{};
  std::array<long long, 2> base{};
  for (int d = 0; d < 2; ++d) {
    const double u = (static_cast<double>(x[d]) - grid_.lower[d]) / grid_.cell - 0.5;
    base[d] = static_cast<long long>(std::floor(u));
    s[d] = u - std::floor(u);
  }
  std::array<double, 2> sum{};
  for (const auto& [dx, dy] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
    std::size_t k = 0;
    const long long cx = base[0] + dx, cy = base[1] + dy;
    if (cx < -1 || cy < -1) continue;
    // neighbor() wraps periodic axes and refuses cells outside the grid.
    if (!neighbor(static_cast<std::size_t>(cx + 1), static_cast<std::size_t>(cy + 1), -1, -1, k)) continue;
    if (blocked_[k]) continue;
    const double weight = (dx == 1 ? s[0] : 1 - s[0]) * (dy == 1 ? s[1] : 1 - s[1]);
    sum[0] += weight * direction_[k][0];
    sum[1] += weight * direction_[k][1];
  }
  const double norm = std::hypot(sum[0], sum[1]);
  if (!(norm > 0)) return Vector<2>::Zero();
  return Vector<2>(static_cast<Real>(sum[0] / norm), static_cast<Real>(sum[1] / norm));
}

}  // namespace tide
